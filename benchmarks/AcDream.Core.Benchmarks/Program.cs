using System;
using BenchmarkDotNet.Running;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Entry point. <c>report</c> runs the accuracy-versus-cost report into artifacts/report/ (<c>--update-docs</c>: into docs/;
/// <c>--quick</c>: a short CI run that writes nothing); <c>replay</c> writes the interpolation replay figures into
/// artifacts/replay/ (<c>--update-docs</c>: docs/interpolation-replay.md and .svg); <c>scene-ab</c> compares a
/// world tick with and without 100,000 resting objects in one process (see <see cref="Report.SceneAbReport"/>);
/// <c>crowd-ab</c> the crowd density ratio (1,000 walkers ÷ 100) in one process (see <see cref="Report.CrowdAbReport"/>);
/// <c>world-map</c> draws the top-down picture of what collides around Holtburg (see <see cref="Report.HoltburgMap"/>);
/// <c>landscape-memory</c> prints the memory a streamed 3 × 3 holds (see <see cref="LandscapeMemory"/>);
/// <c>count ROW N</c> runs one row N times for instruction counts (see <see cref="InstructionCounts"/>);
/// anything else goes to BenchmarkDotNet's switcher (e.g. <c>--filter '*'</c>, <c>--job Dry</c>).
/// </summary>
public static class Program
{
    /// <summary>Runs the report or the BenchmarkDotNet switcher.</summary>
    public static int Main(string[] args)
    {
        if (args.Length > 0 && string.Equals(args[0], "report", StringComparison.OrdinalIgnoreCase))
        {
            return Report.AccuracyReport.Run(args.AsSpan(1));
        }

        if (args.Length > 0 && string.Equals(args[0], "replay", StringComparison.OrdinalIgnoreCase))
        {
            return Report.ReplayReport.Run(args.AsSpan(1));
        }

        if (args.Length > 0 && string.Equals(args[0], "motion-replay", StringComparison.OrdinalIgnoreCase))
        {
            return Report.MotionReplayReport.Run(args.AsSpan(1));
        }

        if (args.Length > 0 && string.Equals(args[0], "scene-ab", StringComparison.OrdinalIgnoreCase))
        {
            return Report.SceneAbReport.Run(args.AsSpan(1));
        }

        if (args.Length > 0 && string.Equals(args[0], "crowd-ab", StringComparison.OrdinalIgnoreCase))
        {
            return Report.CrowdAbReport.Run(args.AsSpan(1));
        }

        if (args.Length > 0 && string.Equals(args[0], "world-map", StringComparison.OrdinalIgnoreCase))
        {
            return Report.HoltburgMap.Run(args.AsSpan(1));
        }

        if (args.Length > 0 && string.Equals(args[0], "landscape-memory", StringComparison.OrdinalIgnoreCase))
        {
            return LandscapeMemory.Run();
        }

        if (args.Length > 0 && string.Equals(args[0], "count", StringComparison.OrdinalIgnoreCase))
        {
            return InstructionCounts.Run(args.AsSpan(1));
        }

        BenchmarkSwitcher.FromAssembly(typeof(Program).Assembly).Run(args);
        return 0;
    }
}
