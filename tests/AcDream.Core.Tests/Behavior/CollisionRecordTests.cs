using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class CollisionRecordTests
{
    [Fact]
    public void CollisionRecords_ListWhatWasHit_ReportEachContactOnce_AndEndAfterOneSecond()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        var listener = new RecordingListener();
        sweep.ObjectCollisionListener = listener;
        PhysicsObj a = ObjectScene.Creature(world, 2, ObjectScene.At(103f, 100f));
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f, heading: 90f));
        SweepScene.SetWalk(c, new Vector3(0f, 2f, 0f));

        // Into a: the step of tick 21 (to 102.1) collides and the walker stops at x = 102. From then on its sliding normal
        // (-1, 0, 0) takes the whole step away (adjust_offset): it no longer sweeps, so the record keeps the first touch.
        SweepScene.Run(world, 30);
        Assert.Equal(102f, c.Position.Frame.Origin.X, 3);
        Assert.Equal(1, c.NumCollisionRecords);
        Assert.Equal(a.Id, c.CollisionRecords[0].ObjectId);
        Assert.False(c.CollisionRecords[0].Ethereal);
        // touched_time = the physics clock of tick 21: 21 * 0.05 = 1.05 s.
        Assert.Equal(1.05, c.CollisionRecords[0].TouchedTime, 9);
        // Reported once, to both, however many ticks it kept pushing.
        Assert.Single(listener.Objects, e => e.Reporter == c.Id);
        Assert.Single(listener.Objects, e => e.Reporter == a.Id);
        var profile = listener.Objects.Find(e => e.Reporter == c.Id).Profile;
        Assert.Equal(a.Id, profile.Id);
        Assert.False(profile.Missile);
        Assert.True(profile.InContact);

        // Walk away (turn around at t = 1.5 s): each committed sweep runs report_collision_end; the record survives while
        // at most 1 s old (t = 2.0 s: 0.95 s), and is gone by t = 2.15 s (1.1 s), reported to both.
        c.SetHeading(270f);
        SweepScene.Run(world, 10);
        Assert.Equal(1, c.NumCollisionRecords);
        Assert.Empty(listener.Ends);
        SweepScene.Run(world, 3);
        Assert.Equal(0, c.NumCollisionRecords);
        Assert.Contains(listener.Ends, e => e.Reporter == c.Id && e.Other == a.Id);
        Assert.Contains(listener.Ends, e => e.Reporter == a.Id && e.Other == c.Id);
    }
}
