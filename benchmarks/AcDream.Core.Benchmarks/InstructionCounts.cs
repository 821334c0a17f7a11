using System;
using System.Collections.Generic;
using System.Globalization;
using AcDream.Core.Benchmarks.Floors;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// <c>count ROW N</c>: runs one benchmark row's operation N times in this process and exits, for instruction counts under
/// <c>valgrind --tool=callgrind</c>, which repeat under load where wall-clock times do not. The rows are the benchmarks'
/// own setups (and the floors beside them); the operation is run once before the N (so that the JIT, with tiering off in
/// this project, has compiled it), and a row's count per operation is (count at 2N − count at N) / N, which cancels the
/// start-up, the setup and the JIT. <c>count list</c> prints the rows. Run it with <c>DOTNET_JitEnableOptionalRelocs=0</c>:
/// without it, under valgrind, the JIT's optimised compile of any method that calls another fails on the call's optional
/// rel32 relocation and falls back to MinOpts (no inlining), so the counts would be of unoptimised code
/// (docs/performance.md, "#38: the frame path, this round").
/// </summary>
internal static class InstructionCounts
{
    // Each row: a setup that returns the operation (one call = one operation of the row's benchmark, as it counts them).
    private static readonly Dictionary<string, Func<Action>> Rows = new(StringComparer.OrdinalIgnoreCase)
    {
        ["sequence"] = () => { var b = new AnimSequenceBenchmarks(); b.Setup(); return () => b.OneTickOnce(); },
        ["combine"] = () => Frame(b => b.CombineOnce()),
        ["grotate"] = () => Frame(b => b.GRotateOnce()),
        ["rotate"] = () => Frame(b => b.RotateOnce()),
        ["roundtrip"] = () => Frame(b => b.LocalToGlobalRoundTripOnce()),
        ["setheading"] = () => Frame(b => b.SetHeadingOnce()),
        ["grotate-chain"] = () => Frame(b => b.GRotate()),
        ["floor-grotate-chain"] = () => Floor(b => b.GRotate()),
        ["floor-combine"] = () => Floor(b => b.CombineOnce()),
        ["floor-grotate"] = () => Floor(b => b.GRotateOnce()),
        ["floor-rotate"] = () => Floor(b => b.RotateOnce()),
        ["floor-roundtrip"] = () => Floor(b => b.LocalToGlobalRoundTripOnce()),
        ["floor-setheading"] = () => Floor(b => b.SetHeadingOnce()),
        ["world-1000"] = () => World(1000),
        ["world-10000"] = () => World(10000),
        ["resting-1000"] = () => Resting(1000),
        ["resting-10000"] = () => Resting(10000),
        ["crowd-100"] = () => { var c = new HoltburgCrowd(100); return () => c.TickOnce(); },
        ["crowd-1000"] = () => { var c = new HoltburgCrowd(1000); return () => c.TickOnce(); },
        ["animated-crowd"] = () => { var b = new AnimatedPartArrayBenchmarks(); b.Setup(); return b.AnimatedCrowdOf100Tick; },
    };

    /// <summary>Runs the row; 0 when it ran, 2 for an unknown row or a bad count.</summary>
    public static int Run(ReadOnlySpan<string> args)
    {
        if (args.Length == 1 && args[0] == "list")
        {
            Console.WriteLine(string.Join(' ', Rows.Keys));
            return 0;
        }

        if (args.Length != 2 || !Rows.TryGetValue(args[0], out Func<Action>? setup)
            || !int.TryParse(args[1], NumberStyles.None, CultureInfo.InvariantCulture, out int n))
        {
            Console.Error.WriteLine("usage: count ROW N (count list: the rows)");
            return 2;
        }

        Action op = setup();
        op();
        for (int i = 0; i < n; i++)
        {
            op();
        }

        return 0;
    }

    private static Action Frame(Action<FrameBenchmarks> op)
    {
        var b = new FrameBenchmarks();
        b.Setup();
        return () => op(b);
    }

    private static Action Resting(int n)
    {
        var b = new RestingWorldTickBenchmarks { N = n };
        b.Setup();
        return () => b.TickOnce();
    }

    private static Action Floor(Action<FrameFloorBenchmarks> op)
    {
        var b = new FrameFloorBenchmarks();
        b.Setup();
        return () => op(b);
    }

    private static Action World(int n)
    {
        var b = new WorldTickBenchmarks { N = n };
        b.Setup();
        return () => b.TickOnce();
    }
}
