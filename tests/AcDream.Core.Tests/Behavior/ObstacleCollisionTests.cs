using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class ObstacleCollisionTests
{
    [Fact]
    public void Creature_StepsUpOntoALowCylinderSphere_AndWalksOver()
    {
        PhysicsWorld world = ObjectScene.Flat(out _);
        // A cylinder r = 1, h = 0.4 standing at (104, 100): its top at 20.4. The walker (r = 0.5, step up 0.6) meets it
        // with its sphere bottom at the ground: the rise is r + h - disp.z = 0.5 + 0.4 - 0.5 = 0.4 <= 0.6, so it steps up.
        ObjectScene.Obstacle(world, 10, ObjectScene.At(104f, 100f), cyl: new[] { new CylSphere(Vector3.Zero, 1f, 0.4f) });
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f, heading: 90f));
        SweepScene.SetWalk(c, new Vector3(0f, 2f, 0f));

        float maxZ = 0f;
        bool onTopOverCentre = false;
        SweepScene.Run(world, 80, _ =>
        {
            Vector3 o = c.Position.Frame.Origin;
            maxZ = Math.Max(maxZ, o.Z);
            if (Math.Abs(o.X - 104f) < 0.5f)
            {
                // Over the centre the creature stands on the top disc (flat contact plane at 20.4).
                Assert.Equal(20.4f, o.Z, 3);
                Assert.True((c.TransientState & TransientState.Contact) != 0);
                onTopOverCentre = true;
            }
        });

        Assert.True(onTopOverCentre);
        Assert.Equal(20.4f, maxZ, 3);
        // 80 ticks * 0.1 m = 8 m: it walked over and down the far side, back on the ground.
        Assert.True(c.Position.Frame.Origin.X > 106f);
        Assert.Equal(ObjectScene.GroundZ, c.Position.Frame.Origin.Z, 3);
    }

    [Fact]
    public void Creature_IsBlockedByATallCylinderSphere()
    {
        PhysicsWorld world = ObjectScene.Flat(out _);
        // Height 2: the rise 0.5 + 2 - 0.5 = 2 > 0.6 step up, so the walker slides instead; head on there is nothing to
        // slide along and the step collides. It stops where the next step would come within radsum = 1 + 0.5 - EPSILON of
        // the axis: at x = 102.5 (the step to 102.6 is refused).
        ObjectScene.Obstacle(world, 10, ObjectScene.At(104f, 100f), cyl: new[] { new CylSphere(Vector3.Zero, 1f, 2f) });
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f, heading: 90f));
        SweepScene.SetWalk(c, new Vector3(0f, 2f, 0f));

        SweepScene.Run(world, 60);

        Assert.Equal(102.5f, c.Position.Frame.Origin.X, 3);
        Assert.Equal(100f, c.Position.Frame.Origin.Y, 3);
        Assert.Equal(ObjectScene.GroundZ, c.Position.Frame.Origin.Z);
    }

    [Fact]
    public void Creature_SlidingAlongAnObjectsSphere_KeepsTheTangentialPartOfItsStep()
    {
        PhysicsWorld world = ObjectScene.Flat(out _);
        // An obstacle sphere r = 0.5 on the ground at (103, 100.6): same height as the walker's sphere (centre 0.5 up).
        // The walker heads east along y = 100 at 0.1 m per tick; it first overlaps at x = 102.3 (dx = 0.7, dy = 0.6,
        // distance 0.922 < 0.9998), and from then on each step slides.
        ObjectScene.Obstacle(world, 10, ObjectScene.At(103f, 100.6f), spheres: new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) });
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f, heading: 90f));
        SweepScene.SetWalk(c, new Vector3(0f, 2f, 0f));

        var track = new System.Collections.Generic.List<Vector3> { c.Position.Frame.Origin };
        SweepScene.Run(world, 30, _ => track.Add(c.Position.Frame.Origin));

        // Ticks 1..22 walk straight (x = 102.2 after 22). Tick 23's step to 102.3 overlaps the obstacle and slides: retail keeps
        // the step's projection on the crease between the sphere and the ground, dir = n x (0, 0, 1), with n the horizontal
        // unit vector from the obstacle's centre to the walker's current centre: n = (102.2 - 103, 100 - 100.6) / 1 =
        // (-0.8, -0.6). For m = (0.1, 0, 0): m . n = -0.08, displacement = m - (m . n) n = (0.1 - 0.064, -0.048) = (0.036, -0.048).
        Vector3 d23 = track[23] - track[22];
        Assert.Equal(102.2f, track[22].X, 3);
        Assert.Equal(0.036f, d23.X, 3);
        Assert.Equal(-0.048f, d23.Y, 3);
        Assert.True((track[23] - new Vector3(103f, 100.6f, 20f)).Length() > 0.9998f);
        // Tick 24: the object starts the step with its sliding normal (-0.8, -0.6), and the sweep's adjust_offset removes the
        // step's component into it again: the walker keeps exactly the tangential velocity, |d| = 0.06 m per tick = 1.2 m/s.
        Vector3 d24 = track[24] - track[23];
        Assert.Equal(d23.X, d24.X, 4);
        Assert.Equal(d23.Y, d24.Y, 4);
        foreach (Vector3 o in track)
        {
            Assert.Equal(ObjectScene.GroundZ, o.Z);
            Assert.True((o - new Vector3(103f, 100.6f, 20f)).Length() > 0.9998f);
        }
    }

    [Fact]
    public void StaticObject_IsCollidedWith_CountsAsEnvironment_AndIsNeverMoved()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        var listener = new RecordingListener();
        sweep.ObjectCollisionListener = listener;
        PhysicsObj s = ObjectScene.Obstacle(world, 10, ObjectScene.At(104f, 100f), spheres: new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) },
            extra: PhysicsState.Static);
        Position before = s.Position;
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f, heading: 90f));
        SweepScene.SetWalk(c, new Vector3(0f, 2f, 0f));

        SweepScene.Run(world, 60);

        // Blocked like by a creature: stops at 103.0 (the step to 103.1 comes within 0.9998 of 104).
        Assert.Equal(103.0f, c.Position.Frame.Origin.X, 3);
        Assert.Equal(before, s.Position);
        Assert.False(s.IsActive);
        // Retail: a static obstacle is not recorded as an object (no collision record, no object report); the walker is in
        // contact, so the hit does not even count as an environment collision.
        Assert.Equal(0, c.NumCollisionRecords);
        Assert.Empty(listener.Objects);
    }
}
