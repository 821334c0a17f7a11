using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// update_object's slicing (acclient.c:323080) and the world gate (CPhysics::UseTime, acclient.c:311334) at the edge values of
/// dt: 0, 1e-9, exactly EPSILON, exactly each quantum, exact multiples of MaxQuantum, 2.0 and the next double, negative, NaN and
/// infinity; and the same run at clock origins 0, 1e6 s and 1e9 s.
/// </summary>
public class TimeSlicingAtEdgeValuesTests
{
    private static (PhysicsWorld World, PhysicsObj Obj, StepRecorder Steps) Setup(double start)
    {
        PhysicsWorld world = TickTestContext.World(start);
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 50f));
        obj.SetVelocity(new Vector3(1f, 2f, 0f));
        var steps = new StepRecorder();
        world.StepObserver = steps;
        return (world, obj, steps);
    }

    /// <summary>Hash of everything but the clock fields (which the edge cases below assert separately).</summary>
    private static ulong Motion(PhysicsObj o)
    {
        var h = new StateHasher();
        h.Add(o.Position);
        h.Add(o.Velocity);
        h.Add(o.Acceleration);
        h.Add(o.Omega);
        h.Add((uint)o.TransientState);
        h.Add(o.CachedVelocity);
        return h.Value;
    }

    [Theory]
    [InlineData(0.0, 0.0)]
    [InlineData(0.0, 1e-9)]
    [InlineData(100.0, 0.0)]
    [InlineData(100.0, 1e-9)]
    [InlineData(1e9, 0.0)]
    public void DtZeroOrOneNanosecond_ConsumesTheTime_WithoutAStep(double start, double dt)
    {
        // dt <= EPSILON (0.0002): retail sets update_time = now and simulates nothing.
        var (world, obj, steps) = Setup(start);
        ulong before = Motion(obj);
        world.SetCurrentTime(start + dt);
        obj.UpdateObject();
        Assert.Equal(0, steps.Count);
        Assert.Equal(start + dt, obj.UpdateTime);
        Assert.Equal(before, Motion(obj));
    }

    [Fact]
    public void DtExactlyEpsilon_IsNotSimulated_TheNextDoubleIs()
    {
        // The test is dt > EPSILON with EPSILON widened to double (0.0002f = 2.0000000949949026e-4). With a clock origin of 0
        // the dt is the clock value itself, so both cases are exact.
        double eps = PhysicsGlobals.Epsilon;
        var (world, obj, steps) = Setup(0.0);
        world.SetCurrentTime(eps);
        obj.UpdateObject();
        Assert.Equal(0, steps.Count);
        Assert.Equal(eps, obj.UpdateTime);

        (world, obj, steps) = Setup(0.0);
        double above = Math.BitIncrement(eps);
        world.SetCurrentTime(above);
        obj.UpdateObject();
        Assert.Equal(1, steps.Count);
        Assert.Equal((float)above, steps.Quantum(0));
        Assert.Equal(above, obj.UpdateTime);
    }

    [Theory]
    [InlineData(1.0 / 30.0)]   // exactly MinQuantum: one whole step (no MinQuantum test on the single-step path)
    [InlineData(0.2)]          // exactly MaxQuantum: dt > MaxQuantum is false, so ONE step, not a slice plus remainder
    public void DtExactlyAQuantum_IsOneWholeStep(double dt)
    {
        var (world, obj, steps) = Setup(0.0);
        world.SetCurrentTime(dt);
        obj.UpdateObject();
        Assert.Equal(1, steps.Count);
        Assert.Equal((float)dt, steps.Quantum(0));
        Assert.Equal(dt, obj.UpdateTime);
    }

    [Fact]
    public void WorldGate_RunsAtExactlyMinQuantum_NotOneDoubleBelow()
    {
        // CPhysics::UseTime: quantum >= MinQuantum. Origin 0 makes the quantum the clock value itself.
        var (world, obj, steps) = Setup(0.0);
        Assert.False(world.Tick(Math.BitDecrement(PhysicsGlobals.MinQuantum)));
        Assert.Equal(0, steps.Count);
        Assert.True(world.Tick(PhysicsGlobals.MinQuantum));
        Assert.Equal(1, steps.Count);
        Assert.Equal((float)PhysicsGlobals.MinQuantum, steps.Quantum(0));
        Assert.Equal(PhysicsGlobals.MinQuantum, obj.UpdateTime);
    }

    [Theory]
    [InlineData(0.0, 1)]
    [InlineData(0.0, 2)]
    [InlineData(0.0, 3)]
    [InlineData(0.0, 5)]
    [InlineData(0.0, 7)]
    [InlineData(0.0, 10)]
    [InlineData(1e6, 3)]
    [InlineData(1e6, 10)]
    [InlineData(1e9, 7)]
    public void DtExactMultipleOfMaxQuantum_GivesExactlyThatManyWholeSteps(double start, int k)
    {
        // now = start + k * 0.2. The slicing loop subtracts 0.2 while dt > 0.2. k * 0.2 and the repeated subtraction differ by
        // at most k ulps of 2.0 (k * 4.4e-16), and the clock's rounding at the origin adds at most one spacing (1.2e-7 s at
        // 1e9). So the last slice is either a whole slice followed by a remainder below 1.3e-7 s (far below MinQuantum: not
        // simulated, carried) or a remainder within 1.3e-7 s of 0.2 (> MinQuantum: simulated, and its float rounding is 0.2f
        // only when within half a float spacing, 7.5e-9 — so at 1e9 compare with 2.5e-7 instead). Either way: k steps.
        var (world, obj, steps) = Setup(start);
        double now = start + k * PhysicsGlobals.MaxQuantum;
        world.SetCurrentTime(now);
        obj.UpdateObject();
        Assert.Equal(k, steps.Count);
        for (int i = 0; i < k; i++)
        {
            Assert.Equal(0.2, steps.Quantum(i), start >= 1e9 ? 2.5e-7 : 1e-8);
        }

        // The physics clock (update_time) is the origin plus the k slices, each addition rounding by at most half the clock
        // spacing u at the origin (u/2 = 6e-8 s at 1e9, 5.8e-11 s at 1e6, 1.1e-16 s near 1), and now itself rounds by u/2:
        // |now - update_time| <= (k + 1) * u / 2 plus the carried remainder (< 1e-15 s, see above). At 1e9 the consumed clock
        // may run AHEAD of now by a few spacings — retail's double clock does the same; the next dt is shorter by as much.
        double u = Math.BitIncrement(now) - now;
        Assert.True(Math.Abs(now - obj.UpdateTime) <= (k + 1) * u / 2 + 1e-15, $"now - update_time = {now - obj.UpdateTime}");
        // The next 0.05 s tick is exactly one step (no extra or missing step from the carried difference).
        steps.Clear();
        world.SetCurrentTime(now + 0.05);
        obj.UpdateObject();
        Assert.Equal(1, steps.Count);
    }

    [Fact]
    public void TenThousandTicks_ByAccumulatedMaxQuantum_AreOneWholeStepEach()
    {
        // t += 0.2 ten thousand times (t reaches 2000 s, double spacing 2.3e-13): the accumulated clock and the object's
        // consumed time drift apart by at most 10,000 spacings = 2.3e-9 s, far below MinQuantum and below half a float spacing
        // at 0.2 (7.5e-9): every tick is one step of exactly 0.2f (a slice whose tiny remainder is carried, or one whole step).
        var (world, obj, steps) = Setup(0.0);
        double t = 0.0;
        for (int i = 0; i < 10_000; i++)
        {
            t += PhysicsGlobals.MaxQuantum;
            world.SetCurrentTime(t);
            obj.UpdateObject();
            Assert.Equal(1, steps.Count);
            Assert.Equal(0.2f, steps.Quantum(0));
            steps.Clear();
        }

        Assert.InRange(t - obj.UpdateTime, 0.0, 2.3e-9);
    }

    [Fact]
    public void DtTwoSeconds_IsTenSlices_TheNextDoubleIsNotSimulated()
    {
        // HugeQuantum: dt <= 2.0 is simulated (10 slices of 0.2: 2.0 - 0.2*9 = 0.2000000000000002 > 0.2 would be an 11th
        // slice only if the remainder after the 10th slice exceeded MinQuantum; it is ~1e-16). Above 2.0: update_time = now.
        var (world, obj, steps) = Setup(0.0);
        world.SetCurrentTime(2.0);
        obj.UpdateObject();
        Assert.Equal(10, steps.Count);

        (world, obj, steps) = Setup(0.0);
        ulong before = Motion(obj);
        double above = Math.BitIncrement(2.0);
        world.SetCurrentTime(above);
        obj.UpdateObject();
        Assert.Equal(0, steps.Count);
        Assert.Equal(above, obj.UpdateTime);
        Assert.Equal(before, Motion(obj));
    }

    [Fact]
    public void NegativeDt_AtTheWorld_ResyncsWithoutTouchingAnyObject()
    {
        // CPhysics::UseTime: a clock that went back sets last_update = now and updates nothing (retail's recovery).
        var (world, obj, steps) = Setup(50.0);
        Assert.True(world.Tick(50.1));
        steps.Clear();
        ulong before = SceneTestContext.Hash(obj);
        Assert.False(world.Tick(49.0));
        Assert.Equal(0, steps.Count);
        Assert.Equal(49.0, world.LastUpdate);
        Assert.Equal(before, SceneTestContext.Hash(obj));
    }

    [Theory]
    [InlineData(double.NaN)]
    [InlineData(double.PositiveInfinity)]
    [InlineData(double.NegativeInfinity)]
    public void NonFiniteClock_IsRefused_AndNothingChanges(double bad)
    {
        var (world, obj, steps) = Setup(50.0);
        Assert.True(world.Tick(50.1));
        steps.Clear();
        ulong before = SceneTestContext.Hash(obj);
        double current = world.CurrentTime, last = world.LastUpdate, physics = world.PhysicsTime;
        Assert.Throws<ArgumentException>(() => world.Tick(bad));
        Assert.Throws<ArgumentException>(() => world.SetCurrentTime(bad));
        Assert.Throws<ArgumentException>(() => new PhysicsWorld(bad));
        Assert.Equal(current, world.CurrentTime);
        Assert.Equal(last, world.LastUpdate);
        Assert.Equal(physics, world.PhysicsTime);
        Assert.Equal(0, steps.Count);
        Assert.Equal(before, SceneTestContext.Hash(obj));
    }

    /// <summary>
    /// A walker on a slope with root motion and turning, a jumper and a fade, ticked by <paramref name="dts"/> from a clock
    /// starting at <paramref name="origin"/>. Returns a hash of every step's quantum and of the state after every tick, with
    /// the clock fields taken relative to the origin.
    /// </summary>
    private static (ulong Hash, int Steps, Vector3 Final) RunFromOrigin(double origin, Func<int, double> dts, int ticks)
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (vx, vy) => 20 + 2 * vx + vy);
        var world = new PhysicsWorld(origin);
        world.Sweep = new RetailSweep(terrain);
        var steps = new StepRecorder();
        world.StepObserver = steps;
        var p = new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 2, 2), Frame.FromHeading(new Vector3(60f, 60f, 0f), 30f));
        p.Frame.Origin = new Vector3(60f, 60f, SweepScene.Ground(terrain, p));
        PhysicsObj walker = SweepScene.Walker(world, p, id: 1);
        SweepScene.SetWalk(walker, new Vector3(0f, 2.5f, 0f));
        ((SimplePartArray)walker.PartArray!).SequenceOmega = new Vector3(0f, 0f, 0.3f);
        p.Frame.Origin = new Vector3(100f, 40f, 0f);
        p.Frame.Origin = new Vector3(100f, 40f, SweepScene.Ground(terrain, p));
        PhysicsObj jumper = SweepScene.Walker(world, p, id: 2);
        walker.SetTranslucency(0.7f, 1.5);
        var h = new StateHasher();
        double t = origin;
        int total = 0;
        for (int i = 0; i < ticks; i++)
        {
            if (i % 40 == 0 && (jumper.TransientState & TransientState.Contact) != 0)
            {
                jumper.SetVelocity(new Vector3(0.5f, 0f, 4f));
            }

            t += dts(i);
            world.Tick(t);
            for (int s = 0; s < steps.Count; s++)
            {
                h.Add(steps.Quantum(s));
                h.Add(steps.Time(s) - origin);
            }

            total += steps.Count;
            steps.Clear();
            foreach (PhysicsObj o in new[] { walker, jumper })
            {
                h.Add(o.Position);
                h.Add(o.Velocity);
                h.Add((uint)o.TransientState);
                h.Add(o.UpdateTime - origin);
                h.Add(o.Translucency);
            }
        }

        return (h.Value, total, walker.Position.Frame.Origin);
    }

    // Tick lengths that are multiples of 2^-23 s (the double spacing at 1e9 s): 3/64 s (21 Hz), with stalls of 3/16 s (one
    // whole step, below MaxQuantum) and 2.5 s (above HugeQuantum: consumed, not simulated). Every clock value at every origin
    // is then exact, so every dt is the same double and the runs must agree bit for bit. (A stall above MaxQuantum is sliced:
    // the physics clock then advances by 0.2 s, which is not a multiple of the spacing at 1e9 and rounds there — retail's
    // double clock; the 20 Hz test below covers it with a bound.)
    private static double ExactDt(int i) => i % 97 == 50 ? 2.5 : i % 31 == 7 ? 0.1875 : 3.0 / 64.0;

    [Fact]
    public void SameRun_AtClockOrigins0_1e6_1e9_WithExactTickLengths_IsBitIdentical()
    {
        var r0 = RunFromOrigin(0.0, ExactDt, 400);
        var r6 = RunFromOrigin(1e6, ExactDt, 400);
        var r9 = RunFromOrigin(1e9, ExactDt, 400);
        Assert.Equal(r0.Steps, r6.Steps);
        Assert.Equal(r0.Steps, r9.Steps);
        Assert.Equal(r0.Hash, r6.Hash);
        Assert.Equal(r0.Hash, r9.Hash);
    }

    [Fact]
    public void SameRun_AtClockOrigins0_1e6_1e9_At20Hz_SameStepsAndPositionsWithinTheClockRounding()
    {
        // 0.05 s is not a multiple of the clock spacing at large origins (1.16e-10 s at 1e6, 1.19e-7 s at 1e9), so each tick's
        // dt differs from the origin-0 run by at most one spacing (the object's consumed time equals the previous clock value
        // exactly, so only the new clock value rounds): every step still passes the gate and the slicing identically (0.05 is
        // far from 1/30, 0.2 and EPSILON), so the step counts are equal. Positions: the walker moves 2.5 m/s of root motion;
        // each step's displacement differs by at most 2.5 * 1.2e-7 = 3e-7 m from the dt and by one float spacing of the origin
        // (at most 1.5e-5 m below 256 m) from a different rounding once any bit differed, so after N = 400 steps the
        // difference is at most 400 * (3e-7 + 1.5e-5) = 6.1e-3 m. Bound 6.2e-3 m. (A tick rate exactly at the 1/30 s gate
        // would not keep its step count at 1e9: the gate compares the rounded clock difference with 1/30.)
        // Stalls of 0.45 s (two 0.2 s slices and a 0.05 s remainder) every 61 ticks: each slice adds at most one more clock
        // rounding (u/2) to the remainder's dt, so per stall at most 3 * 1.2e-7 s more: 7 stalls * 2.5 m/s * 3.6e-7 s = 6.3e-6
        // m, inside the bound's slack.
        static double Dt(int i) => i % 61 == 30 ? 0.45 : 0.05;
        var r0 = RunFromOrigin(0.0, Dt, 400);
        foreach (double origin in new[] { 1e6, 1e9 })
        {
            var r = RunFromOrigin(origin, Dt, 400);
            Assert.Equal(r0.Steps, r.Steps);
            Assert.True(Vector3.Distance(r0.Final, r.Final) < 6.2e-3f, $"origin {origin}: {r.Final} vs {r0.Final}");
        }
    }
}
