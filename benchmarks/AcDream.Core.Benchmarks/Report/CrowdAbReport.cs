using System;
using System.Collections.Generic;
using System.Diagnostics;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// <c>crowd-ab</c>: the crowd density ratio of <see cref="CrowdDensityBenchmarks"/> (per walker and world tick, 1,000
/// walkers ÷ 100 on Holtburg) measured in one process. Both crowds are built, then each is ticked in batches (200 ticks of
/// the 100, 20 ticks of the 1,000: about the same time), all the batches of one crowd in a row so that each runs on its own
/// warm memory, in two phases; the fastest batch of each (and the quartiles) stand for the crowd on an undisturbed machine.
/// On a machine whose speed drifts and whose other tenants come and go, BenchmarkDotNet's short rows of the two crowds can
/// differ by 50 % between runs of identical code; the minima here repeat within a few percent.
/// </summary>
/// <remarks>Options: <c>--rounds N</c> (batches per crowd and phase, default 60). Needs ACDREAM_TERRAIN_DIR for the real
/// terrain (a synthetic 3 × 3 otherwise, as the benchmark).</remarks>
public static class CrowdAbReport
{
    /// <summary>Runs the comparison and prints the figures; returns 0, or 2 on a bad option.</summary>
    public static int Run(ReadOnlySpan<string> args)
    {
        int rounds = 60;
        for (int i = 0; i < args.Length; i++)
        {
            string value = i + 1 < args.Length ? args[i + 1] : "";
            if (args[i] == "--rounds" && int.TryParse(value, out int r) && r > 0)
            {
                rounds = r;
                i++;
            }
            else
            {
                Console.Error.WriteLine($"crowd-ab: unknown option or value '{args[i]} {value}'");
                return 2;
            }
        }

        var sparse = new HoltburgCrowd(100);
        var dense = new HoltburgCrowd(1000);
        var s = new List<double>();
        var d = new List<double>();
        for (int phase = 0; phase < 2; phase++)
        {
            Batches(sparse, 200, 100, rounds, s);
            Batches(dense, 20, 1000, rounds, d);
        }

        s.Sort();
        d.Sort();
        Console.WriteLine($"ns per walker and tick, 100 walkers: min {s[0]:F1}, quartiles {Q(s, 1):F1} / {Q(s, 2):F1} / {Q(s, 3):F1}");
        Console.WriteLine($"ns per walker and tick, 1,000 walkers: min {d[0]:F1}, quartiles {Q(d, 1):F1} / {Q(d, 2):F1} / {Q(d, 3):F1}");
        Console.WriteLine($"ratio 1,000 / 100: of the minima {d[0] / s[0]:F3}, of the medians {Q(d, 2) / Q(s, 2):F3}");
        return 0;
    }

    // One warm-up batch, then `rounds` timed batches of `ticks` world ticks; each batch's time per walker and tick.
    private static void Batches(HoltburgCrowd crowd, int ticks, int walkers, int rounds, List<double> into)
    {
        for (int i = 0; i < ticks; i++)
        {
            crowd.TickOnce();
        }

        for (int r = 0; r < rounds; r++)
        {
            long t0 = Stopwatch.GetTimestamp();
            for (int i = 0; i < ticks; i++)
            {
                crowd.TickOnce();
            }

            into.Add((Stopwatch.GetTimestamp() - t0) * 1e9 / Stopwatch.Frequency / ((double)ticks * walkers));
        }
    }

    private static double Q(List<double> sorted, int quartile) => sorted[(sorted.Count - 1) * quartile / 4];
}
