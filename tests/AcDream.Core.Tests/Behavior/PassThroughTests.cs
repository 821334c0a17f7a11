using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class PassThroughTests
{
    [Fact]
    public void EtherealWalker_PassesThroughACreature_AndRecordsTheTouch()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        var listener = new RecordingListener();
        sweep.ObjectCollisionListener = listener;
        PhysicsObj creature = ObjectScene.Creature(world, 2, ObjectScene.At(102f, 100f));
        var state = (PhysicsState)PhysicsGlobals.DefaultState | PhysicsState.Ethereal;
        PhysicsObj ghost = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f, heading: 90f), state: state);
        SweepScene.SetWalk(ghost, new Vector3(0f, 2f, 0f));

        SweepScene.Run(world, 50);

        // 50 ticks * 0.1 m: straight through to x = 105.
        Assert.Equal(105f, ghost.Position.Frame.Origin.X, 3);
        Assert.Equal(100f, ghost.Position.Frame.Origin.Y, 3);
        // The ethereal touch is still a collision: recorded once, reported to both.
        Assert.Contains(listener.Objects, e => e.Reporter == ghost.Id && e.Profile.Id == creature.Id);
        Assert.Contains(listener.Objects, e => e.Reporter == creature.Id && e.Profile.Id == ghost.Id);
    }

    [Fact]
    public void Walker_PassesThroughAnEtherealObject_WhoseRecordEndsAtOnce()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        var listener = new RecordingListener();
        sweep.ObjectCollisionListener = listener;
        PhysicsObj ghost = ObjectScene.Obstacle(world, 10, ObjectScene.At(102f, 100f), spheres: new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) },
            extra: PhysicsState.Ethereal);
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f, heading: 90f));
        SweepScene.SetWalk(c, new Vector3(0f, 2f, 0f));

        SweepScene.Run(world, 50);

        Assert.Equal(105f, c.Position.Frame.Origin.X, 3);
        // report_collision_end drops an ethereal object's record as soon as the physics clock moved on (age > 0).
        Assert.Equal(0, c.NumCollisionRecords);
        Assert.Contains(listener.Ends, e => e.Reporter == c.Id && e.Other == ghost.Id);
    }

    [Fact]
    public void IgnoreCreatures_PassesCreatures_ButNotOtherObjects()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        PhysicsObj creature = ObjectScene.Creature(world, 2, ObjectScene.At(102f, 100f));
        ObjectScene.Obstacle(world, 3, ObjectScene.At(102f, 110f), spheres: new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) });
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f, heading: 90f));

        // Through the creature: from 101.2 to 102.8 (the first step already overlaps it). With IGNORE_CREATURES the hit is
        // recorded with OK, the collision normal dropped, and the sweep reaches the end.
        Transition t = Sweep(sweep, c, 101.2f, 100f, 102.8f, ObjectInfoState.IgnoreCreatures);
        Assert.Equal(102.8f, t.SpherePath.CurrPos.Frame.Origin.X, 3);
        Assert.Equal(creature, Assert.Single(t.CollisionInfo.CollideObjects.ToArray()));
        Assert.Null(t.CollisionInfo.LastCollidedObject);
        // Without it the creature blocks: the first step collides and the walker stays at 101.2.
        t = Sweep(sweep, c, 101.2f, 100f, 102.8f, ObjectInfoState.None);
        Assert.Equal(101.2f, t.SpherePath.CurrPos.Frame.Origin.X, 3);
        Assert.Equal(creature, t.CollisionInfo.LastCollidedObject);
        // A non-creature obstacle blocks even with IGNORE_CREATURES.
        t = Sweep(sweep, c, 101.2f, 110f, 102.8f, ObjectInfoState.IgnoreCreatures);
        Assert.Equal(101.2f, t.SpherePath.CurrPos.Frame.Origin.X, 3);
    }

    [Fact]
    public void Players_PassThroughEachOther_UnlessImpenetrable()
    {
        PhysicsWorld world = ObjectScene.Flat(out _);
        PhysicsObj a = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f, heading: 90f), weenie: WeenieTraits.Player);
        PhysicsObj b = ObjectScene.Creature(world, 2, ObjectScene.At(103f, 100f), weenie: WeenieTraits.Player);
        PhysicsObj wall = ObjectScene.Creature(world, 3, ObjectScene.At(103f, 110f),
            weenie: new WeenieTraits { IsCreature = true, IsPlayer = true, IsImpenetrable = true });
        PhysicsObj c = ObjectScene.Creature(world, 4, ObjectScene.At(100f, 110f, heading: 90f), weenie: WeenieTraits.Player);
        SweepScene.SetWalk(a, new Vector3(0f, 2f, 0f));
        SweepScene.SetWalk(c, new Vector3(0f, 2f, 0f));

        SweepScene.Run(world, 60);

        // Player through player: 60 * 0.1 m = 6 m, to x = 106.
        Assert.Equal(106f, a.Position.Frame.Origin.X, 3);
        Assert.Equal(103f, b.Position.Frame.Origin.X, 3);
        // An impenetrable player blocks: stops with the gap at 1.0 (x = 102).
        Assert.Equal(102f, c.Position.Frame.Origin.X, 3);
        Assert.Equal(103f, wall.Position.Frame.Origin.X, 3);
    }

    internal static Transition Sweep(RetailSweep sweep, PhysicsObj obj, float fromX, float y, float toX, ObjectInfoState extra)
    {
        Transition t = sweep.Pool.Make()!;
        try
        {
            Position begin = ObjectScene.At(fromX, y, ObjectScene.GroundZ, 90f);
            Position end = ObjectScene.At(toX, y, ObjectScene.GroundZ, 90f);
            t.InitObject(obj, obj.GetObjectInfo(t, false) | extra);
            t.InitSphere(obj.PartArray!.Spheres, obj.Scale);
            t.InitPath(sweep.Cells.GetVisible(begin.ObjCellId), begin, end);
            Assert.True(t.FindValidPosition());
            return t;
        }
        finally
        {
            sweep.Pool.Cleanup();
        }
    }
}
