using System;
using System.Diagnostics;
using AcDream.Core.Physics.Scene;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// <c>scene-ab</c>: what 100,000 resting objects add to a world tick, measured in one process. The scene of
/// <see cref="SceneRestingObjectsBenchmarks"/> is built twice, with 0 and with 100,000 resting objects; the two worlds then tick
/// alternately, 1,000 world ticks each at a time, so that both see the same machine (on a machine whose speed drifts, rows that
/// BenchmarkDotNet runs one after another can differ by 20 % with identical work). Prints the median and quartiles of the
/// per-round ratios, both medians, the gate statistics per tick and the bytes allocated per tick.
/// </summary>
/// <remarks>Options: <c>--path square|line|still</c> (default square), <c>--gate exact|moving</c> (default exact),
/// <c>--speed M</c> (the player's speed in m/s, default 2: a runner is about 12), <c>--rounds N</c> (default 41),
/// <c>--warm N</c> (world ticks before measuring, default 3,000).</remarks>
public static class SceneAbReport
{
    /// <summary>Runs the comparison and prints the figures; returns 0, or 2 on a bad option.</summary>
    public static int Run(ReadOnlySpan<string> args)
    {
        var path = PlayerPath.Square;
        var gate = GateTracking.Exact;
        int rounds = 41, warm = 3000;
        float speed = 2f;
        for (int i = 0; i < args.Length; i++)
        {
            string value = i + 1 < args.Length ? args[i + 1] : "";
            switch (args[i])
            {
                case "--path" when Enum.TryParse(value, ignoreCase: true, out PlayerPath p):
                    path = p;
                    i++;
                    break;
                case "--gate" when value is "exact" or "moving":
                    gate = value == "exact" ? GateTracking.Exact : GateTracking.MovingObjectsOnly;
                    i++;
                    break;
                case "--speed" when float.TryParse(value, System.Globalization.CultureInfo.InvariantCulture, out float v) && v > 0f && v <= 50f:
                    speed = v;
                    i++;
                    break;
                case "--rounds" when int.TryParse(value, out int r) && r > 0:
                    rounds = r;
                    i++;
                    break;
                case "--warm" when int.TryParse(value, out int w) && w >= 0:
                    warm = w;
                    i++;
                    break;
                default:
                    Console.Error.WriteLine($"scene-ab: unknown option or value '{args[i]} {value}'");
                    return 2;
            }
        }

        var none = new SceneRestingObjectsBenchmarks { Resting = 0, Gate = gate, Player = path, PlayerSpeed = speed };
        var many = new SceneRestingObjectsBenchmarks { Resting = 100_000, Gate = gate, Player = path, PlayerSpeed = speed };
        none.Setup();
        many.Setup();
        for (int i = 0; i < warm / 10; i++)
        {
            none.Tick();
            many.Tick();
        }

        GateStatistics before = many.World.GateStatistics;
        long allocated = GC.GetAllocatedBytesForCurrentThread();
        var a = new double[rounds];
        var b = new double[rounds];
        var ratio = new double[rounds];
        for (int r = 0; r < rounds; r++)
        {
            a[r] = Time(none);
            b[r] = Time(many);
            ratio[r] = b[r] / a[r];
        }

        allocated = GC.GetAllocatedBytesForCurrentThread() - allocated;
        GateStatistics after = many.World.GateStatistics;
        double ticks = rounds * 1000.0;
        Array.Sort(a);
        Array.Sort(b);
        Array.Sort(ratio);
        Console.WriteLine($"scene-ab: player {path} at {speed:0.#} m/s, gate {gate}, {rounds} rounds of 1,000 world ticks each");
        Console.WriteLine($"  median per tick: 0 resting {a[rounds / 2]:F2} us, 100,000 resting {b[rounds / 2]:F2} us");
        Console.WriteLine($"  ratio: median {ratio[rounds / 2]:F3}, quartiles {ratio[rounds / 4]:F3} .. {ratio[rounds * 3 / 4]:F3}");
        Console.WriteLine($"  gate per tick: {(after.Remeasures - before.Remeasures) / ticks:F1} re-measured, "
            + $"{(after.Crossings - before.Crossings) / ticks:F2} crossings, {(after.Wakes - before.Wakes) / ticks:F3} wakes");
        Console.WriteLine($"  allocated: {allocated / (2.0 * ticks):F2} B per tick");
        return 0;
    }

    // Microseconds per world tick over 1,000 world ticks (100 benchmark invocations of 10).
    private static double Time(SceneRestingObjectsBenchmarks bench)
    {
        long t0 = Stopwatch.GetTimestamp();
        for (int i = 0; i < 100; i++)
        {
            bench.Tick();
        }

        return Stopwatch.GetElapsedTime(t0).TotalMicroseconds / 1000.0;
    }
}
