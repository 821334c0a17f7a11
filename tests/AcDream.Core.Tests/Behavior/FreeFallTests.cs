using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>Scenes of motion under gravity, friction and spin, against closed forms.</summary>
public class FreeFallTests
{
    private const double Q = 0.0625; // the world ticks every 1/16 s (>= 1/30, exact in binary)

    [Fact]
    public void FreeFallFromRest_1000Ticks_MatchesDiscreteClosedFormWithTheVelocityClamp()
    {
        var world = new PhysicsWorld(0.0);
        const float z0 = 5000f;
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, z0));
        double g = PhysicsGlobals.Gravity; // -9.8000002
        double q = Q;

        // Discrete closed form of retail's integration (hand-derived):
        //   step 1 from rest: |v|^2 = 0 skips the origin update; v = g q.
        //   step n >= 2: z += v_{n-1} q + g q^2 / 2, v_n = n g q.  Sum over n = 2..N:
        //   z_N = z0 + g q^2 * sum_{k=1}^{N-1} (k + 1/2) = z0 + g q^2 (N^2 - 1) / 2.
        //   The clamp: at the start of step n, |v| = (n-1) |g| q; (n-1) * 0.6125 > 50 first for n = 83 (82 * 0.6125 = 50.2).
        //   From then on every step starts at |v| = 50: z += -50 q + g q^2 / 2.
        for (int n = 1; n <= 1000; n++)
        {
            Assert.True(world.Tick(n * Q));
            double expected = n <= 82
                ? z0 + g * q * q * ((double)n * n - 1.0) / 2.0
                : z0 + g * q * q * (82.0 * 82.0 - 1.0) / 2.0 + (n - 82) * (-50.0 * q + g * q * q / 2.0);
            if (n == 1 || n == 50 || n == 82 || n == 83 || n == 500 || n == 1000)
            {
                // z is a float in [1984, 5000]: each step's store rounds by at most half an ulp (2.44e-4 m for 4096..8192), and
                // a constant increment rounds the same way every step, so the bound is n * 2.44e-4 (0.244 m at n = 1000).
                Assert.True(Math.Abs(obj.Position.Frame.Origin.Z - expected) <= n * 2.44e-4 + 1e-3,
                    $"tick {n}: z = {obj.Position.Frame.Origin.Z}, closed form {expected}");
            }

            if (n == 50)
            {
                Assert.Equal(50 * g * q, obj.Velocity.Z, 3); // v_n = n g q before the clamp
            }
        }

        // After the clamp the velocity ends each step at -50 + g q.
        Assert.Equal(-50.0 + g * q, obj.Velocity.Z, 4);
        Assert.Equal(10f, obj.Position.Frame.Origin.X);
        Assert.Equal(10f, obj.Position.Frame.Origin.Y);
        // cached velocity = displacement / quantum of the last swept step = -50 + g q / 2
        Assert.Equal(-50.0 + g * q / 2.0, obj.CachedVelocity.Z, 2);
    }

    [Fact]
    public void SlidingOnFlatGround_DecaysAsOneMinusFToTheT_ThenStops_ThenSleeps()
    {
        var world = new PhysicsWorld(0.0) { Sweep = new FlatGroundSweep() };
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f));
        Assert.Equal(Vector3.Zero, obj.Acceleration); // on walkable ground
        obj.SetVelocity(new Vector3(10f, 0f, 0f));
        double k = Math.Pow(1.0 - 0.949999988079071, Q); // (1 - 0.95f)^(1/16) = 0.82925 per step

        // v_n = 10 k^n while |v|^2 at the start of a step is >= 0.0627: 10 k^20 = 10 * 0.05^1.25 = 0.2364 is the last one.
        for (int n = 1; n <= 20; n++)
        {
            Assert.True(world.Tick(n * Q));
            Assert.Equal(10.0 * Math.Pow(k, n), obj.Velocity.X, 4);
            Assert.True(obj.IsActive);
        }

        Assert.True(world.Tick(21 * Q)); // step 21 starts at |v|^2 = 0.0559 < 0.0625 + EPSILON: velocity zeroed
        Assert.Equal(Vector3.Zero, obj.Velocity);
        Assert.True(obj.IsActive);
        float xAtStop = obj.Position.Frame.Origin.X;

        Assert.True(world.Tick(22 * Q)); // |v|^2 = 0 on walkable ground, no movement manager: the object deactivates
        Assert.False(obj.IsActive);
        Assert.Equal(xAtStop, obj.Position.Frame.Origin.X);

        // Distance travelled: sum_{n=1}^{20} v_n q with v_n = 10 k^n (the origin moves with the post-friction velocity).
        double travelled = 0;
        for (int n = 1; n <= 20; n++)
        {
            travelled += 10.0 * Math.Pow(k, n) * Q;
        }

        Assert.Equal(10.0 + travelled, xAtStop, 3);
    }

    [Fact]
    public void SpinByOmega_WithoutSpheres_RotatesByTheClosedFormAngle_AndKeepsItsOrigin()
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 50f), spheres: 0);
        obj.SetOmega(new Vector3(0f, 0f, 0.5f));
        for (int n = 1; n <= 100; n++)
        {
            Assert.True(world.Tick(n * Q));
        }

        // theta = omega * N * q = 0.5 * 100 / 16 = 3.125 rad about +Z: q = (cos 1.5625, 0, 0, sin 1.5625).
        double half = 0.5 * 100 * Q / 2.0;
        Assert.Equal(Math.Cos(half), obj.Position.Frame.Qw, 4);
        Assert.Equal(Math.Sin(half), obj.Position.Frame.Qz, 4);
        // No collision spheres: retail keeps the origin (rotation only), although gravity has built up a velocity.
        Assert.Equal(new Vector3(10f, 10f, 50f), obj.Position.Frame.Origin);
        Assert.True(obj.Velocity.Z < -49f);
        Assert.Equal(Vector3.Zero, obj.CachedVelocity);
    }

    [Fact]
    public void BlockedSweep_KeepsOriginButTakesNewOrientation()
    {
        var world = new PhysicsWorld(0.0) { Sweep = new BlockedTransition() };
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 50f));
        obj.SetVelocity(new Vector3(5f, 0f, 0f));
        obj.SetOmega(new Vector3(0f, 0f, 1f));
        Assert.True(world.Tick(Q));
        Assert.Equal(new Vector3(10f, 10f, 50f), obj.Position.Frame.Origin);
        Assert.Equal(Math.Sin(Q / 2.0), obj.Position.Frame.Qz, 5);
        Assert.Equal(Vector3.Zero, obj.CachedVelocity);
    }

    [Fact]
    public void AlignPath_TurnsToFaceTheDirectionOfTravel()
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 50f));
        obj.SetState(obj.State | PhysicsState.AlignPath);
        obj.SetVelocity(new Vector3(5f, 0f, 0f)); // east
        Assert.True(world.Tick(Q));
        Assert.True(world.Tick(2 * Q)); // second step: moving east and falling
        Vector3 facing = obj.Position.Frame.GetVectorHeading();
        Assert.True(facing.X > 0.9f, $"facing {facing}");
    }

    [Fact]
    public void RootMotion_IsAppliedOnlyOnWalkableGround_ScaledByScale()
    {
        var world = new PhysicsWorld(0.0) { Sweep = new FlatGroundSweep() };
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f));
        obj.Movement = new BasicMovementManager(); // stays awake at rest
        var parts = (SimplePartArray)obj.PartArray!;
        parts.SequenceVelocity = new Vector3(0f, 4f, 0f); // 4 m/s forward (+Y) in local axes
        obj.SetScaleStatic(2f);
        Assert.True(world.Tick(Q));
        // local offset = 4 * 1/16 = 0.25 m, times scale 2 on walkable ground = 0.5 m north
        Assert.Equal(10.5f, obj.Position.Frame.Origin.Y);
        Assert.Equal(1, parts.HandleMovementCount);
        Assert.Equal(1, ((BasicMovementManager)obj.Movement).UseTimeCount);
    }
}
