using System;
using System.Numerics;
using AcDream.Core.Benchmarks.Report;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Report;

/// <summary>The accuracy report's closed forms and error measures (benchmarks/.../Report/ClosedForms.cs, compiled in here),
/// checked against hand-computed values, including a full error computation on a hand-derived case.</summary>
public class ReportClosedFormsTests
{
    [Fact]
    public void FreeFallZ_BeforeAndAfterTheClamp()
    {
        // t = 2: 100 + 0.5 * -9.8 * 4 = 80.4.
        Assert.Equal(80.4, ClosedForms.FreeFallZ(100.0, -9.8, 2.0), 12);
        // t = 10: clamp at t_c = 50 / 9.8 = 5.10204 s after 0.5 * 9.8 * t_c² = 127.551 m, then 50 * 4.89796 = 244.898 m:
        // 1000 - 127.551 - 244.898 = 627.551.
        Assert.Equal(627.551, ClosedForms.FreeFallZ(1000.0, -9.8, 10.0), 3);
    }

    [Fact]
    public void FrictionDistance_OneSecond()
    {
        // f = 0.95: λ = ln 20 = 2.995732; 10 * (1 - 0.05) / 2.995732 = 3.171178 m; speed 10 * 0.05 = 0.5 m/s.
        Assert.Equal(3.171178, ClosedForms.FrictionDistance(10.0, 0.95, 1.0), 5);
        Assert.Equal(0.5, ClosedForms.FrictionSpeed(10.0, 0.95, 1.0), 12);
    }

    [Fact]
    public void Projectile_AndSpin_AndAngle()
    {
        var p = ClosedForms.Projectile(new Vector3(1f, 2f, 3f), new Vector3(4f, 0f, 10f), -10.0, 2.0);
        Assert.Equal((9.0, 2.0, 3.0), p); // x 1 + 8, z 3 + 20 - 20
        var q = ClosedForms.SpinAboutZ(Math.PI / 2, 1.0); // 90 degrees: (cos 45°, 0, 0, sin 45°)
        Assert.Equal(Math.Sqrt(0.5), q.W, 12);
        Assert.Equal(Math.Sqrt(0.5), q.Z, 12);
        Assert.Equal(90.0, ClosedForms.AngleDegrees((1, 0, 0, 0), q), 9);
        // A scaled quaternion is the same rotation: 0 degrees (both are normalised first); q and -q too.
        Assert.Equal(0.0, ClosedForms.AngleDegrees((2 * q.W, 0, 0, 2 * q.Z), (-q.W, 0, 0, -q.Z)), 6);
        Assert.Equal(5.0, ClosedForms.Distance(new Vector3(3f, 4f, 0f), (0, 0, 0)), 12);
    }

    [Fact]
    public void FreeFallError_OfRetailAtOneSixteenth_IsHalfGQSquared()
    {
        // Retail from rest: the first step does not move the origin (|v|² = 0), then z_N = z0 + g q² (N² - 1) / 2
        // (FreeFallTests). The closed form at t = N q is z0 + g q² N² / 2, so the error is |g| q² / 2 at every N:
        // 9.8000002 / 512 = 0.019140625 m. z stays within [98, 100]: float rounding adds at most 16 * 3.8e-6 m.
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 100f));
        for (int n = 1; n <= 16; n++)
        {
            world.Tick(n / 16.0);
        }

        double err = Math.Abs(obj.Position.Frame.Origin.Z - ClosedForms.FreeFallZ(100.0, PhysicsGlobals.Gravity, obj.UpdateTime));
        Assert.Equal(0.019140625, err, 4);
    }

    [Fact]
    public void FrictionError_OfRetailAtOneSixteenth_MatchesTheHandSum()
    {
        // Sliding from 10 m/s on level walkable ground, q = 1/16, 16 steps: each step scales v by k = (1 - f)^q and then
        // moves v q (no acceleration), so x = 10 q Σ_{n=1..16} k^n = 10 q k (1 - k^16) / (1 - k). With f = 0.95f
        // (0.949999988): λ = -ln(0.050000012) = 2.995732, k = e^(-λ/16) = 0.8292503, k^16 = 0.0500000:
        // x = 10 * 0.0625 * 0.8292503 * 0.95 / 0.1707497 = 2.883562; closed form 10 * 0.95 / 2.995732 = 3.171178;
        // error 0.287616 m (the discrete sum lags: each step moves at the end-of-step speed).
        var world = new PhysicsWorld(0.0) { Sweep = new FlatGroundSweep() };
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(2f, 10f, 0f));
        obj.SetVelocity(new Vector3(10f, 0f, 0f));
        for (int n = 1; n <= 16; n++)
        {
            world.Tick(n / 16.0);
        }

        double x = obj.Position.Frame.Origin.X - 2.0;
        double err = Math.Abs(x - ClosedForms.FrictionDistance(10.0, obj.Friction, obj.UpdateTime));
        Assert.Equal(0.287616, err, 4);
    }
}
