using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Replay.Harness;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>Each non-retail fidelity switch changes the tick, in the direction reasoned out in each test.</summary>
public class FidelitySwitchTests
{
    // A float's quaternion component after set_rotate is the double-normalised value rounded once: each |error| <= 2^-25
    // (half an ulp below 1), so |q|² - 1 = 2 Σ q_i e_i + O(e²) with Σ|q_i| <= 2 gives |q|² - 1 <= 4 * 2^-25 = 1.19e-7.
    private const double NormalisedBound = 1.2e-7;

    [Fact]
    public void RenormaliseNever_LetsTheNormDrift_WhileRetailStaysNormalised()
    {
        // A body spinning at 2 rad/s about +Z, ticked at 1/30 s for 120 s: 3600 steps of one combine and one grotate.
        // Retail renormalises on both, so after every step |q|² - 1 is within the rounding bound above. Without it, each
        // product adds a rounding of the same size and nothing pulls the norm back: after 7200 unnormalised products the
        // drift is far outside the bound (a random walk of ~sqrt(7200) * 6e-8 = 5e-6, and the report measured 2.4e-4 in 10 min).
        PhysicsObj retail = Spinner(PhysicsProfile.Retail);
        PhysicsObj never = Spinner(PhysicsProfile.Retail.With(renormaliseEvery: 0));
        double worstRetail = 0;
        for (int n = 1; n <= 3600; n++)
        {
            retail.World.Tick(n / 30.0);
            never.World.Tick(n / 30.0);
            worstRetail = Math.Max(worstRetail, Math.Abs(retail.Position.Frame.QuaternionNorm2 - 1.0));
        }

        Assert.True(worstRetail <= NormalisedBound, $"retail drift {worstRetail}");
        double drift = Math.Abs(never.Position.Frame.QuaternionNorm2 - 1.0);
        Assert.True(drift > 10 * NormalisedBound, $"never-renormalised drift {drift}");
        // Both still turn the same way: 120 s * 2 rad/s = 240 rad = 13751 deg = 38 turns + 71.0 deg counter-clockwise,
        // i.e. heading 360 - 71.0 = 289.0 (clockwise from north). Drift only scales the quaternion.
        Assert.Equal(retail.Position.Frame.Heading, never.Position.Frame.Heading, 1);
    }

    [Fact]
    public void RenormaliseEverySecondChange_NormalisesAtEveryGRotate()
    {
        // Each step makes two rotation changes (combine, then grotate); with N = 2 the second one, grotate, renormalises, so
        // at the end of every step the norm is within the retail bound even though combine did not normalise.
        PhysicsObj obj = Spinner(PhysicsProfile.Retail.With(renormaliseEvery: 2));
        for (int n = 1; n <= 1000; n++)
        {
            obj.World.Tick(n / 30.0);
            Assert.True(Math.Abs(obj.Position.Frame.QuaternionNorm2 - 1.0) <= NormalisedBound, $"step {n}");
        }
    }

    [Fact]
    public void GRotateNoRenormalise_QuarterTurn_FacesWest()
    {
        // +90 degrees about +Z (counter-clockwise seen from above) turns north-facing identity to face west: heading 270.
        Frame f = Frame.Identity;
        f.GRotateNoRenormalise(new Vector3(0f, 0f, (float)(Math.PI / 2)));
        Assert.Equal(270.0, f.Heading, 4);
        Assert.True(Math.Abs(f.QuaternionNorm2 - 1.0) < 1e-6);
        // Below EPSILON (|w|² < EPSILON²) nothing changes, as in grotate.
        Frame g = Frame.Identity;
        g.GRotateNoRenormalise(new Vector3(0f, 0f, 1e-4f));
        Assert.True(g.Equals(Frame.Identity));
    }

    [Fact]
    public void CombineNoRenormalise_WithIdentity_IsTheOtherFrame()
    {
        // identity ∘ f: origin = f.origin (matrix is I), q = 1 * f.q, exactly (products by 1 and 0 are exact).
        Frame f = Frame.FromHeading(new Vector3(1f, 2f, 3f), 30f);
        Frame r = Frame.Identity;
        r.CombineNoRenormalise(Frame.Identity, f);
        Assert.Equal(f.Origin, r.Origin);
        Assert.Equal(f.Qw, r.Qw);
        Assert.Equal(f.Qz, r.Qz);
    }

    [Fact]
    public void Float32_ChangesTheBits_ButStaysWithinFloatRoundingOfRetail()
    {
        // The same spinning, flying body under both arithmetic modes for 300 ticks. Float32 rounds every intermediate, so the
        // bits differ; but both round the same formulas, so they stay within a few float ulps per step of each other:
        // 300 steps * 2 roundings * ulp(512) (6.1e-5) = 0.037 m bounds the origin; the rotation, 300 * 2 * 1.2e-7 rad.
        PhysicsObj d = FidelityThrown(PhysicsProfile.Retail);
        PhysicsObj f = FidelityThrown(PhysicsProfile.Retail.With(arithmetic: ArithmeticMode.Float32));
        for (int n = 1; n <= 300; n++)
        {
            d.World.Tick(n / 30.0);
            f.World.Tick(n / 30.0);
        }

        Assert.False(d.Position.Frame.Equals(f.Position.Frame));
        Assert.True(Vector3.Distance(d.Position.Frame.Origin, f.Position.Frame.Origin) < 0.037f);
        double dq = Math.Abs(d.Position.Frame.Qw * f.Position.Frame.Qw + d.Position.Frame.Qx * f.Position.Frame.Qx
                             + d.Position.Frame.Qy * f.Position.Frame.Qy + d.Position.Frame.Qz * f.Position.Frame.Qz);
        Assert.True(2 * Math.Acos(Math.Min(1.0, dq)) < 300 * 2 * 1.2e-7 * 4, $"angle {2 * Math.Acos(Math.Min(1.0, dq))}");
    }

    [Fact]
    public void SweepStepScale_SetsTheNumberOfSweepSteps()
    {
        // A 0.5 m sphere flying east at 15 m/s without gravity over flat ground 10 m below; one 0.2 s tick moves it 3 m.
        // calc_num_steps: ceil(3 / (scale * 0.5)): retail (1) 6 steps, scale 2 -> 3 steps, scale 0.5 -> 12 steps.
        Assert.Equal(6u, StepsOfOneTick(1f));
        Assert.Equal(3u, StepsOfOneTick(2f));
        Assert.Equal(12u, StepsOfOneTick(0.5f));
    }

    [Fact]
    public void RemoteSmoothing_Snap_PlacesAtOnce_WhereRetailQueues()
    {
        // Retail queues a report 2 m away on the interpolation manager and leaves the body where it is; Snap places it there.
        Vector3 start = new(50f, 50f, 0f);
        Vector3 target = start + new Vector3(0f, 2f, 0f);
        PhysicsObj retail = Creature(PhysicsProfile.Retail, start);
        PhysicsObj snap = Creature(PhysicsProfile.Retail.With(remoteSmoothing: RemoteSmoothing.Snap), start);
        Assert.True(retail.HandleReceivedPosition(ManagerScene.At(target), 1, 0, true) >= ReceivedPositionResult.Interpolating);
        Assert.True(snap.HandleReceivedPosition(ManagerScene.At(target), 1, 0, true) >= ReceivedPositionResult.Interpolating);
        Assert.True(retail.IsInterpolating);
        Assert.Equal(start, retail.Position.Frame.Origin);
        Assert.False(snap.IsInterpolating);
        Assert.Equal(target, snap.Position.Frame.Origin);
    }

    [Fact]
    public void RemoteSmoothing_LinearExtrapolation_MovesOnAtTheReportedVelocity()
    {
        // Reports at t = 0.1 s (50, 52) and t = 0.6 s (50, 54): 2 m north in 0.5 s = 4 m/s north. The body is placed at the
        // second report and, with no root motion, then moves 4 m/s * 0.1 s = 0.4 m north in the next 0.1 s tick (-> y = 54.4).
        // Snap has no velocity and stays at 54.
        Vector3 start = new(50f, 50f, 0f);
        PhysicsObj ext = Creature(PhysicsProfile.Retail.With(remoteSmoothing: RemoteSmoothing.LinearExtrapolation), start);
        PhysicsObj snap = Creature(PhysicsProfile.Retail.With(remoteSmoothing: RemoteSmoothing.Snap), start);
        foreach (PhysicsObj c in new[] { ext, snap })
        {
            c.World.SetCurrentTime(0.1);
            Assert.True(c.HandleReceivedPosition(ManagerScene.At(new Vector3(50f, 52f, 0f)), 1, 0, true) >= ReceivedPositionResult.Interpolating);
            c.World.Tick(0.6);
            Assert.True(c.HandleReceivedPosition(ManagerScene.At(new Vector3(50f, 54f, 0f)), 2, 0, true) >= ReceivedPositionResult.Interpolating);
            c.World.Tick(0.7);
        }

        Assert.Equal(new Vector3(0f, 4f, 0f), ext.ExtrapolationVelocity);
        Assert.Equal(54.4f, ext.Position.Frame.Origin.Y, 4);
        Assert.Equal(50f, ext.Position.Frame.Origin.X, 4);
        Assert.Equal(54f, snap.Position.Frame.Origin.Y, 4);
        Assert.Equal(Vector3.Zero, snap.ExtrapolationVelocity);
    }

    [Fact]
    public void NonRetailSwitches_SteadyStateTick_AllocatesNothing()
    {
        // Float32 arithmetic, no renormalisation, extrapolating remote objects: the switches' code paths must keep the tick
        // allocation-free like the retail path (reports included: they place the body and store the estimate in place).
        PhysicsProfile p = PhysicsProfile.Retail.With(ArithmeticMode.Float32, 0, 2f, RemoteSmoothing.LinearExtrapolation);
        var world = new PhysicsWorld(0.0, p) { Sweep = new FlatGroundSweep() };
        PhysicsObj player = world.CreateObject(1);
        player.PartArray = new SimplePartArray(1, 1) { Radius = 0.5f };
        Assert.True(player.EnterWorld(ManagerScene.At(new Vector3(60f, 60f, 0f))));
        world.Player = player;
        var creatures = new PhysicsObj[20];
        for (int i = 0; i < creatures.Length; i++)
        {
            PhysicsObj c = world.CreateObject((uint)(i + 2));
            c.PartArray = new SimplePartArray(1, 1) { Radius = 0.5f, SequenceOmega = new Vector3(0f, 0f, 0.5f) };
            Assert.True(c.EnterWorld(ManagerScene.At(new Vector3(40f + i, 50f, 0f))));
            creatures[i] = c;
        }

        double t = 0;
        ushort stamp = 0;
        void Run(int ticks)
        {
            for (int k = 0; k < ticks; k++)
            {
                t += 0.05;
                if (k % 4 == 0)
                {
                    stamp++;
                    world.SetCurrentTime(t);
                    foreach (PhysicsObj c in creatures)
                    {
                        Position r = c.Position;
                        r.Frame.Origin += new Vector3(0f, 0.5f, 0f);
                        c.HandleReceivedPosition(r, stamp, 0, true);
                    }
                }

                world.Tick(t);
            }
        }

        Run(20); // warm-up (JIT, position managers created on the first report)
        AllocationProbe.AssertSteadyStateAllocatesNothing(() => Run(40));
    }

    private static PhysicsObj Spinner(PhysicsProfile profile)
    {
        var world = new PhysicsWorld(0.0, profile);
        PhysicsObj obj = world.CreateObject();
        obj.PartArray = new SimplePartArray(2, 1);
        obj.SetState((PhysicsState)PhysicsGlobals.DefaultState & ~PhysicsState.Gravity);
        Assert.True(obj.EnterWorld(new Position(TickTestContext.OutdoorCell, new Vector3(10f, 10f, 50f))));
        obj.SetOmega(new Vector3(0f, 0f, 2f));
        obj.SetActive(true);
        return obj;
    }

    private static PhysicsObj FidelityThrown(PhysicsProfile profile) => Retail.FidelityDefaultsTests.Thrown(new PhysicsWorld(0.0, profile));

    private static uint StepsOfOneTick(float scale)
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 10);
        var world = new PhysicsWorld(0.0, PhysicsProfile.Retail.With(sweepStepScale: scale));
        var sweep = new RetailSweep(terrain);
        world.Sweep = sweep;
        PhysicsObj ball = world.CreateObject(1);
        var parts = new SimplePartArray(1, 0);
        parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) });
        ball.PartArray = parts;
        ball.SetState((PhysicsState)PhysicsGlobals.DefaultState & ~PhysicsState.Gravity);
        Assert.True(ball.EnterWorld(new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 2, 2), new Vector3(50f, 50f, 20f))));
        ball.SetVelocity(new Vector3(15f, 0f, 0f));
        world.Tick(0.2);
        Assert.Equal(53f, ball.Position.Frame.Origin.X, 3);
        // The tick's transition is the pool's first (nothing nested), readable until the pool's next Make.
        sweep.Pool[0].CalcNumSteps(out Vector3 offset, out _, out uint steps);
        Assert.Equal(3f, offset.X, 3);
        return steps;
    }

    private static PhysicsObj Creature(PhysicsProfile profile, Vector3 at)
    {
        var world = new PhysicsWorld(0.0, profile) { Sweep = new FlatGroundSweep() };
        PhysicsObj player = world.CreateObject(1);
        player.PartArray = new SimplePartArray(1, 1) { Radius = 0.5f };
        Assert.True(player.EnterWorld(ManagerScene.At(new Vector3(60f, 60f, 0f))));
        world.Player = player;
        PhysicsObj c = world.CreateObject(2);
        c.PartArray = new SimplePartArray(1, 1) { Radius = 0.5f, Height = 1.8f };
        Assert.True(c.EnterWorld(ManagerScene.At(at)));
        world.Tick(0.05); // measures player_distance (FLT_MAX until the first update would snap)
        return c;
    }
}
