using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// Friction on walkable ground (calc_friction, acclient.c:316090) and the small-velocity stop in UpdatePhysicsInternal
/// (acclient.c:317700) bring a sliding object to an exact +0 velocity in a bounded number of steps, never through subnormal
/// values (which would slow every later multiply), and a subnormal input velocity is never integrated.
/// </summary>
public class FrictionDecayReachesExactZeroTests
{
    private static PhysicsObj Slider(out PhysicsWorld world, Vector3 velocity, float friction = PhysicsGlobals.DefaultFriction)
    {
        world = TickTestContext.World(0.0);
        world.Sweep = new FlatGroundSweep();
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(12f, 12f, 0f));
        Assert.True((obj.TransientState & TransientState.OnWalkable) != 0);
        obj.Friction = friction;
        obj.SetVelocity(velocity);
        return obj;
    }

    private static bool HasSubnormal(Vector3 v) =>
        float.IsSubnormal(v.X) || float.IsSubnormal(v.Y) || float.IsSubnormal(v.Z);

    [Fact]
    public void TenMetresPerSecond_DefaultFriction_StopsExactlyAtStep26_WithoutSubnormals()
    {
        // Per 0.05 s step the speed is multiplied by (1 - 0.95)^0.05 = exp(0.05 ln 0.05) = exp(-0.1497866) = 0.860892 (the
        // velocity is horizontal, so v·N = 0 < 0.25 and nothing is removed along the normal). The stop zeroes the velocity
        // when the speed² measured BEFORE friction satisfies mag2 - 0.0625 < EPSILON, i.e. speed < sqrt(0.0627) = 0.250400.
        // Step n sees 10 * 0.860892^(n-1): below 0.2504 when n - 1 > ln(0.02504) / ln(0.860892) = -3.68729 / -0.149787 =
        // 24.62, so first at n = 26 (step 25 sees 10 * 0.860892^24 = 0.2746, above). The margins (0.2746 vs 0.2504, 0.2364
        // vs 0.2504) are far wider than float rounding over 26 multiplications (~26 * 6e-8 relative).
        PhysicsObj obj = Slider(out PhysicsWorld world, new Vector3(6f, 8f, 0f));
        for (int n = 1; n <= 25; n++)
        {
            world.Tick(n * 0.05);
            Assert.NotEqual(Vector3.Zero, obj.Velocity);
            Assert.False(HasSubnormal(obj.Velocity), $"step {n}: {obj.Velocity}");
        }

        world.Tick(26 * 0.05);
        Assert.Equal(0, BitConverter.SingleToInt32Bits(obj.Velocity.X));
        Assert.Equal(0, BitConverter.SingleToInt32Bits(obj.Velocity.Y));
        Assert.Equal(0, BitConverter.SingleToInt32Bits(obj.Velocity.Z));

        // With a zero velocity, on walkable ground and without a movement manager, the next step deactivates the object and
        // it stays put: no creep, no subnormal, for the next 1,000 ticks.
        Position rest = obj.Position;
        for (int n = 27; n < 1027; n++)
        {
            world.Tick(n * 0.05);
            Assert.Equal(rest, obj.Position);
            Assert.Equal(Vector3.Zero, obj.Velocity);
        }

        Assert.False(obj.IsActive);
    }

    [Fact]
    public void FrictionOne_StopsInOneStep_FrictionZero_KeepsTheSpeedExactly()
    {
        // f = 1: (1 - 1)^q = 0^0.05 = +0, so the velocity after one step is (+0, +0, +0) times components: exactly zero.
        PhysicsObj stop = Slider(out PhysicsWorld w1, new Vector3(3f, 0f, 0f), friction: 1f);
        w1.Tick(0.05);
        Assert.Equal(Vector3.Zero, stop.Velocity);
        Assert.False(HasSubnormal(stop.Velocity));

        // f = 0: (1 - 0)^q = 1 exactly, so the speed is unchanged bit for bit over 1,000 steps (no drift from pow).
        PhysicsObj glide = Slider(out PhysicsWorld w0, new Vector3(3f, 0f, 0f), friction: 0f);
        for (int n = 1; n <= 1000; n++)
        {
            w0.Tick(n * 0.05);
            Assert.Equal(new Vector3(3f, 0f, 0f), glide.Velocity);
        }
    }

    [Theory]
    [InlineData(1e-40f)]      // subnormal
    [InlineData(1e-30f)]      // normal, but its square underflows float
    [InlineData(float.Epsilon)]
    public void TinyOrSubnormalVelocity_IsNeverIntegrated_AndTheObjectSleeps(float speed)
    {
        // mag2 = (float)(v.x² + ...) rounds to +0 for |v| < ~1e-23, so UpdatePhysicsInternal takes the "mag2 <= 0" branch:
        // no friction, no integration, and (walkable, no movement manager) the object deactivates. The position never moves.
        PhysicsObj obj = Slider(out PhysicsWorld world, new Vector3(speed, 0f, 0f));
        Position start = obj.Position;
        for (int n = 1; n <= 100; n++)
        {
            world.Tick(n * 0.05);
            Assert.Equal(start, obj.Position);
            Assert.True(VectorMath.IsFinite(obj.Velocity));
        }

        Assert.False(obj.IsActive);
    }
}
