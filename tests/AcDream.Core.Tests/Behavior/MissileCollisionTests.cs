using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class MissileCollisionTests
{
    // A missile: one sphere r = 0.1 on its origin, MISSILE | REPORT_COLLISIONS, no gravity, in the air at z = 20.5
    // (the height of a r = 0.5 creature's sphere centre).
    private static PhysicsObj Missile(PhysicsWorld world, float x, float vx)
    {
        PhysicsObj m = ObjectScene.Obstacle(world, 50, ObjectScene.At(x, 100f, 20.5f), spheres: new[] { new Sphere(Vector3.Zero, 0.1f) },
            extra: PhysicsState.Missile);
        m.SetVelocity(new Vector3(vx, 0f, 0f));
        return m;
    }

    [Fact]
    public void PathClippedMissile_StopsAtTheStepOfImpact_ReportsTheHit_AndStopsBeingAMissile()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        var listener = new RecordingListener();
        sweep.ObjectCollisionListener = listener;
        PhysicsObj creature = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f));
        PhysicsObj m = Missile(world, 95f, 10f);

        // 10 m/s: 0.5 m per tick, swept in 5 steps of one radius (0.1 m). Tick 9 goes from 99.0: the steps to 99.1 .. 99.4
        // stay outside radsum = 0.1 + 0.5 - EPSILON = 0.5998 of the creature's centre (100, 100, 20.5); the step to 99.5 hits.
        // Without PERFECT_CLIP (never set by get_object_info) collide_with_point only records the normal: the step collides,
        // the missile stays at 99.4 and the path-clipped sweep ends there.
        SweepScene.Run(world, 9);

        Assert.Equal(99.4f, m.Position.Frame.Origin.X, 3);
        Assert.Equal(20.5f, m.Position.Frame.Origin.Z, 4);
        // The collision record lists the creature; report_object_collision cleared MISSILE / ALIGNPATH / PATHCLIPPED.
        Assert.Equal(1, m.NumCollisionRecords);
        Assert.Equal(creature.Id, m.CollisionRecords[0].ObjectId);
        Assert.Equal(PhysicsState.None, m.State & (PhysicsState.Missile | PhysicsState.AlignPath | PhysicsState.PathClipped));
        // The missile reports an attack on the creature; the quadrant is the missile's origin in the creature's frame:
        // (99.4 - 100, 0, 20.5 - 20) = (-0.6, 0, 0.5): x < 0 -> 0x8, y >= 0 -> 0x20, height 1: 1/3 <= 0.5 < 2/3 -> 0x2.
        var attack = Assert.Single(listener.Attacks);
        Assert.Equal(m.Id, attack.Reporter);
        Assert.Equal(creature.Id, attack.Profile.Id);
        Assert.Equal(-1, attack.Profile.Part);
        Assert.Equal(0x8 | 0x20 | 0x2, attack.Profile.Location);
        // The creature is told an object (a missile) hit it.
        var hit = Assert.Single(listener.Objects);
        Assert.Equal(creature.Id, hit.Reporter);
        Assert.Equal(m.Id, hit.Profile.Id);
        Assert.True(hit.Profile.Missile);
        // Bounce off the normal (-1, 0, 0) with elasticity 0.05: v = 10 - 10 * 1.05 = -0.5 m/s.
        Assert.Equal(-0.5f, m.Velocity.X, 4);
    }

    [Fact]
    public void PerfectClip_MovesTheMissileToTheTimeOfImpact()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f));
        PhysicsObj m = Missile(world, 99.35f, 0f);

        // From 99.35 towards 99.85 (5 steps of 0.1). The first step (to 99.45) overlaps. Time of impact with
        // r = radsum + EPSILON = 0.6: |(-0.65, 0, 0) + t (0.1, 0, 0)| = 0.6 -> t = (0.065 - sqrt(0.065^2 - 0.0625 * 0.01)) / 0.01
        // = (0.065 - 0.06) / 0.01 = 0.5: the sphere moves back by 0.05 to 99.40, exactly touching.
        Assert.Equal(99.4f, Sweep(sweep, m, ObjectInfoState.PathClipped | ObjectInfoState.PerfectClip, 99.35f, 99.85f), 4);
        // Without PERFECT_CLIP the first step collides and the missile does not move.
        Assert.Equal(99.35f, Sweep(sweep, m, ObjectInfoState.PathClipped, 99.35f, 99.85f), 4);
    }

    internal static float Sweep(RetailSweep sweep, PhysicsObj obj, ObjectInfoState state, float fromX, float toX)
    {
        Transition t = sweep.Pool.Make()!;
        try
        {
            Position begin = obj.Position;
            begin.Frame.Origin = new Vector3(fromX, begin.Frame.Origin.Y, begin.Frame.Origin.Z);
            Position end = begin;
            end.Frame.Origin = new Vector3(toX, begin.Frame.Origin.Y, begin.Frame.Origin.Z);
            t.InitObject(obj, state);
            t.InitSphere(obj.PartArray!.Spheres, obj.Scale);
            t.InitPath(sweep.Cells.GetVisible(obj.CellId), begin, end);
            Assert.True(t.FindValidPosition());
            return t.SpherePath.CurrPos.Frame.Origin.X;
        }
        finally
        {
            sweep.Pool.Cleanup();
        }
    }
}
