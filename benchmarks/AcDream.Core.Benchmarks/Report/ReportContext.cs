using System;
using System.Collections.Generic;
using System.Diagnostics;

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
            Console.WriteLine(TableRow(scene, (isRetail ? "* " : "") + choice, error, unit, ns, bytes, note));
        }

        return row;
    }

    /// <summary>Header of the console table (the columns of <see cref="TableRow"/>).</summary>
    public static string TableHeader { get; } = string.Create(System.Globalization.CultureInfo.InvariantCulture,
        $"      {"scene",-30} {"choice (* = retail)",-42} {"error",11} {"unit",-4} {"ns/frame",10} {"B/frame",8}  note");

    /// <summary>One console row: fixed-width columns (long text is cut with "~" so the columns never drift).</summary>
    public static string TableRow(string scene, string choice, double error, string unit, double ns, double bytes, string note) =>
        string.Create(System.Globalization.CultureInfo.InvariantCulture,
            $"      {Fit(scene, 30),-30} {Fit(choice, 42),-42} {error,11:G4} {Fit(unit, 4),-4} {ns,10:F1} {bytes,8:F1}  {note}");

    private static string Fit(string s, int width) => s.Length <= width ? s : string.Concat(s.AsSpan(0, width - 1), "~");

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

    /// <summary>The real terrain folder, found as the tests find it (<see cref="Tests.Support.Shared.TerrainDataDir"/>:
    /// ACDREAM_TERRAIN_DIR, a relative value resolved against the repository root, else ../shared/data/ac-terrain beside the
    /// repository), or null with <paramref name="reason"/>.</summary>
    public static string? FindTerrainDir(out string reason) => Tests.Support.Shared.TerrainDataDir.Find(out reason);
}
