using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>One row of the report: a scene run under one fidelity choice, with its error and its cost from the same process.</summary>
internal sealed record ReportRow(
    string Switch,
    string Scene,
    string Choice,
    bool IsRetail,
    string Reference,
    int Frames,
    double Seconds,
    double Error,
    string Unit,
    double NsPerFrame,
    double NsPerSimSecond,
    double BytesPerFrame,
    string Note);

/// <summary>State of one report run: options, the rows, trajectories for the plot, and notes (skipped scenes).</summary>
internal sealed class ReportContext
{
    public ReportContext(bool quick, string? terrainDir)
    {
        Quick = quick;
        TerrainDir = terrainDir;
    }

    /// <summary>Short CI run: a fraction of each scene, one timing repetition, nothing written.</summary>
    public bool Quick { get; }

    /// <summary>Folder of the real Dereth terrain fixtures, or null when absent (terrain scenes are skipped).</summary>
    public string? TerrainDir { get; }

    public List<ReportRow> Rows { get; } = [];

    /// <summary>No console output (warm-up pass).</summary>
    public bool Silent { get; init; }

    public List<string> Notes { get; } = [];

    /// <summary>Trajectory plots: title -> (series name, points).</summary>
    public Dictionary<string, List<(string Name, List<(double X, double Y)> Points)>> Trajectories { get; } = [];

    /// <summary>Scales a duration for quick mode.</summary>
    public double Seconds(double full, double quick) => Quick ? quick : full;

    /// <summary>
    /// Runs <paramref name="make"/>'s sim once with sampling (error), then times fresh sims without sampling (the fastest of
    /// at least five repetitions and 0.4 s; allocation from the runtime's per-thread counter), and adds the row.
    /// </summary>
    public ReportRow Measure(string switchName, string scene, string choice, bool isRetail, string reference, string unit, Func<Sim> make)
    {
        Sim s = make();
        for (int i = 0; i < s.Frames; i++)
        {
            s.Advance(i);
            s.Sample(i);
        }

        double error = s.Error;
        string note = s.Note;
        var perFrame = new List<double>();
        double bytes = 0;
        double total = 0;
        int reps = 0;
        int minReps = Quick ? 1 : 5;
        while (reps < minReps || (!Quick && total < 0.4 && reps < 400))
        {
            Sim t = make();
            int half = t.Frames / 2;
            long t0 = Stopwatch.GetTimestamp();
            for (int i = 0; i < half; i++)
            {
                t.Advance(i);
            }

            // Allocation is counted over the second half only: a fresh world's first frames grow its buffers once.
            long a0 = GC.GetAllocatedBytesForCurrentThread();
            for (int i = half; i < t.Frames; i++)
            {
                t.Advance(i);
            }

            long a1 = GC.GetAllocatedBytesForCurrentThread();
            double sec = Stopwatch.GetElapsedTime(t0).TotalSeconds;
            total += sec;
            perFrame.Add(sec * 1e9 / t.Frames);
            bytes = (double)(a1 - a0) / Math.Max(1, t.Frames - half);
            reps++;
        }

        // The minimum over repetitions: on a shared machine interference only ever adds time.
        perFrame.Sort();
        double ns = perFrame[0];
        var row = new ReportRow(switchName, scene, choice, isRetail, reference, s.Frames, s.Seconds, error, unit, ns,
            ns * s.Frames / s.Seconds, bytes, note);
        Rows.Add(row);
        if (!Silent)
        {
            Console.WriteLine($"  {switchName,-14} {scene,-28} {choice,-34} error {error,10:G4} {unit,-4} {ns,9:F1} ns/frame {bytes,6:F1} B/frame {note}");
        }

        return row;
    }

    /// <summary>Adds a trajectory series to plot <paramref name="title"/>.</summary>
    public void AddTrajectory(string title, string name, List<(double X, double Y)> points)
    {
        if (!Trajectories.TryGetValue(title, out var list))
        {
            list = [];
            Trajectories[title] = list;
        }

        list.Add((name, points));
    }

    /// <summary>ACDREAM_TERRAIN_DIR, else ../shared/data/ac-terrain beside the repository root when present, else null.</summary>
    public static string? FindTerrainDir(string repoRoot)
    {
        string? dir = Environment.GetEnvironmentVariable("ACDREAM_TERRAIN_DIR");
        if (!string.IsNullOrEmpty(dir))
        {
            return Directory.Exists(dir) ? dir : null;
        }

        string fallback = Path.GetFullPath(Path.Combine(repoRoot, "..", "shared", "data", "ac-terrain"));
        return File.Exists(Path.Combine(fallback, "landblock_heights_sample.csv")) ? fallback : null;
    }
}
