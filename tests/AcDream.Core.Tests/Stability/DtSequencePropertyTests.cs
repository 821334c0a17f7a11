using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using FsCheck;
using FsCheck.Fluent;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// Property-based (FsCheck) invariants over random sequences of frame times: every update_object call obeys retail's slicing
/// rules (acclient.c:323080), nothing becomes NaN, and a resting object never moves.
/// </summary>
public class DtSequencePropertyTests
{
    private static readonly double[] EdgeDts =
    [
        0.0, 1e-9, PhysicsGlobals.Epsilon, Math.BitIncrement((double)PhysicsGlobals.Epsilon), PhysicsGlobals.MinQuantum,
        PhysicsGlobals.MaxQuantum, 2 * PhysicsGlobals.MaxQuantum, 3 * PhysicsGlobals.MaxQuantum, 2.0, Math.BitIncrement(2.0), 5.0,
    ];

    /// <summary>Frame times: mostly ordinary (0.1 µs .. 0.2 s), some long (up to 2.2 s), some edge values, some negative.</summary>
    private static readonly Gen<double> Dts = Gen.Frequency(
        (6, Gen.Choose(1, 2_000_000).Select(i => i * 1e-7)),
        (2, Gen.Choose(0, 2_200_000).Select(i => i * 1e-6)),
        (2, Gen.Elements(EdgeDts)),
        (1, Gen.Choose(-1000, -1).Select(i => i * 1e-3)));

    private static readonly Gen<(double Origin, double[] Dts)> Sequences =
        from origin in Gen.Elements(0.0, 100.0, 1e6, 1e9)
        from dts in Gen.ArrayOf(Dts, 40)
        select (origin, dts);

    private static Config Cfg => PropertyAssert.Replayable(200, 20261122UL, 0x9E3779B97F4A7C15UL);

    [Fact]
    public void EveryCall_ObeysTheSlicingRules_AndNothingBecomesNaN()
    {
        PropertyAssert.Holds(Cfg, Prop.ForAll(Sequences.ToArbitrary(), seq =>
        {
            PhysicsWorld world = TickTestContext.World(seq.Origin);
            PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(12f, 12f, 100f));
            obj.SetVelocity(new Vector3(1f, -2f, 3f));
            obj.SetOmega(new Vector3(0f, 0f, 0.5f));
            var steps = new StepRecorder();
            world.StepObserver = steps;
            double now = seq.Origin;
            foreach (double d in seq.Dts)
            {
                now += d;
                double u = obj.UpdateTime;
                double dt = now - u;
                steps.Clear();
                world.SetCurrentTime(now);
                obj.UpdateObject();
                if (!CallObeysRules(obj, steps, u, now, dt))
                {
                    string q = steps.Count > 0 ? steps.Quantum(steps.Count - 1).ToString("R", System.Globalization.CultureInfo.InvariantCulture) : "-";
                    throw new InvalidOperationException(FormattableString.Invariant(
                        $"u {u:R} now {now:R} dt {dt:R}: {steps.Count} steps (last {q}), update_time {obj.UpdateTime:R}"));
                }

                if (!VectorMath.IsFinite(obj.Position.Frame.Origin) || !VectorMath.IsFinite(obj.Velocity) || !obj.Position.Frame.IsValid())
                {
                    return false;
                }
            }

            return true;
        }));
    }

    /// <summary>
    /// Retail's rules for one call with dt = now - update_time: dt &lt;= EPSILON or dt &gt; 2.0 → no step, update_time = now;
    /// dt &lt;= 0.2 → one step of (float)dt, update_time = u + dt; otherwise slices of 0.2 (each 0.2f) while more than 0.2 is left,
    /// then one remainder step only when the rest exceeds 1/30, and update_time = the consumed clock (the rest is carried).
    /// </summary>
    private static bool CallObeysRules(PhysicsObj obj, StepRecorder steps, double u, double now, double dt)
    {
        if (!(dt > PhysicsGlobals.Epsilon) || dt > PhysicsGlobals.HugeQuantum)
        {
            return steps.Count == 0 && obj.UpdateTime == now;
        }

        if (dt <= PhysicsGlobals.MaxQuantum)
        {
            return steps.Count == 1 && steps.Quantum(0) == (float)dt && obj.UpdateTime == u + dt;
        }

        // Sliced. Slices are whole 0.2f steps; at most one remainder, above 1/30 (as a float: (float)(1/30 + tiny) >= 1/30f).
        int slices = 0;
        while (slices < steps.Count && steps.Quantum(slices) == 0.2f)
        {
            slices++;
        }

        int rest = steps.Count - slices;
        if (slices < 1 || rest > 1 || (rest == 1 && !(steps.Quantum(slices) >= (float)PhysicsGlobals.MinQuantum)))
        {
            return false;
        }

        // The count: slices * 0.2 covers dt to within one slice. Each slice's subtraction rounds by at most one ulp of 2.0
        // (4.4e-16 s); allow 1e-12 s. With a remainder step, dt - slices*0.2 lies in (1/30, 0.2]; without, in [0, 1/30]. A
        // remainder within half a float spacing of 0.2 (7.5e-9 s) has the quantum 0.2f and is counted above as a slice, so
        // "left" may then be as low as -7.5e-9 s: allow -1e-8.
        double left = dt - slices * PhysicsGlobals.MaxQuantum;
        bool countOk = rest == 1
            ? left > PhysicsGlobals.MinQuantum - 1e-12 && left <= PhysicsGlobals.MaxQuantum + 1e-12
            : left >= -1e-8 && left <= PhysicsGlobals.MinQuantum + 1e-12;

        // The consumed clock: u + the slices (+ the remainder). Each addition to the clock rounds by half a spacing at the
        // clock's magnitude (u up to 1e9 + 90 s: spacing 1.2e-7 s), at most 11 additions: 11 * 6e-8 = 6.6e-7 s; the remainder's
        // float rounding does not enter (the clock adds the double remainder). Bound 1e-6 s. What is not consumed is carried:
        // now - update_time is the unsimulated rest, at most 1/30 s (plus the same rounding).
        double consumed = slices * PhysicsGlobals.MaxQuantum + (rest == 1 ? left : 0.0);
        bool clockOk = Math.Abs(obj.UpdateTime - (u + consumed)) <= 1e-6
                       && now - obj.UpdateTime >= -1e-6 && now - obj.UpdateTime <= PhysicsGlobals.MinQuantum + 1e-6;
        return countOk && clockOk;
    }

    [Fact]
    public void AWalkerRestingOnAWalkableSlope_UnderTheRetailSweep_NeverMoves_WhateverTheFrameTimes()
    {
        // The same on real terrain through the retail sweep: a slope rising 20 m per 24 m (N.z = 0.768 >= floor_z) and a
        // walker (movement manager: never deactivates) standing on it. In contact on walkable ground gravity is zeroed, so
        // no step of any length moves it.
        PropertyAssert.Holds(Cfg, Prop.ForAll(Sequences.ToArbitrary(), seq =>
        {
            TerrainWorld terrain = SweepScene.Terrain();
            SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (vx, _) => 10 + 20 * vx);
            var world = new PhysicsWorld(seq.Origin) { Sweep = new RetailSweep(terrain) };
            var p = new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 3, 4), new Vector3(84f, 108f, 0f));
            p.Frame.Origin = new Vector3(84f, 108f, SweepScene.Ground(terrain, p));
            PhysicsObj obj = SweepScene.Walker(world, p);
            Position start = obj.Position;
            double now = seq.Origin;
            foreach (double d in seq.Dts)
            {
                now += d;
                world.Tick(now);
                if (obj.Position != start || obj.Velocity != Vector3.Zero)
                {
                    return false;
                }
            }

            return true;
        }));
    }

    [Fact]
    public void ARestingObject_NeverMoves_WhateverTheFrameTimes()
    {
        // On walkable ground with zero velocity calc_acceleration zeroes gravity, friction has nothing to act on, the frame
        // is combined with the identity offset and the unchanged origin skips the sweep: every bit of the position stays.
        // Through the world gate (CPhysics::UseTime) and directly through update_object, with an object that stays awake
        // (movement manager) and one that self-deactivates (none).
        PropertyAssert.Holds(Cfg, Prop.ForAll(Sequences.ToArbitrary(), seq =>
        {
            foreach (bool awake in new[] { true, false })
            {
                PhysicsWorld world = TickTestContext.World(seq.Origin);
                world.Sweep = new FlatGroundSweep();
                PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(12f, 12f, 0f));
                if (awake)
                {
                    obj.Movement = new BasicMovementManager();
                }

                Position start = obj.Position;
                double now = seq.Origin;
                for (int i = 0; i < seq.Dts.Length; i++)
                {
                    now += seq.Dts[i];
                    if ((i & 1) == 0)
                    {
                        world.Tick(now);
                    }
                    else
                    {
                        world.SetCurrentTime(now);
                        obj.UpdateObject();
                    }

                    if (obj.Position != start || obj.Velocity != Vector3.Zero)
                    {
                        return false;
                    }
                }
            }

            return true;
        }));
    }
}
