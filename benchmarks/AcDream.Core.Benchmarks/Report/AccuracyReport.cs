using System;
using System.Collections.Generic;
using System.IO;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Data;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// The accuracy-versus-cost report: runs each scene under each fidelity choice, measures its error against a stated reference
/// and its time per frame in the same process, and writes <c>accuracy-vs-cost.md</c> with SVG charts (ScottPlot) beside it,
/// into <c>artifacts/report/</c> (git-ignored) by default. <c>--update-docs</c> writes into <c>docs/</c> instead (refreshing
/// the committed copy); <c>--out DIR</c> chooses any folder. <c>--quick</c> runs a short piece of every scene once and writes
/// nothing (CI keeps the report from rotting). The console shows one progress line per scene group and an aligned table of
/// the rows.
/// </summary>
internal static class AccuracyReport
{
    private static readonly PhysicsProfile Retail = PhysicsProfile.Retail;
    private static readonly PhysicsProfile Ace = PhysicsProfile.AceCompatible;

    private static readonly (string Name, Action<ReportContext> Run)[] Groups =
    [
        ("substep profile", Substeps),
        ("arithmetic", Arithmetic),
        ("renormalisation", Renormalisation),
        ("sweep resolution", Sweep),
        ("remote smoothing", Smoothing),
    ];

    public static int Run(ReadOnlySpan<string> args)
    {
        bool quick = false;
        string root = FindRepoRoot();
        string outDir = Path.Combine(root, "artifacts", "report");
        for (int i = 0; i < args.Length; i++)
        {
            if (args[i] == "--quick")
            {
                quick = true;
            }
            else if (args[i] == "--update-docs")
            {
                outDir = Path.Combine(root, "docs");
            }
            else if (args[i] == "--out" && i + 1 < args.Length)
            {
                outDir = Path.GetFullPath(args[++i]);
            }
            else
            {
                Console.Error.WriteLine($"report: unknown argument '{args[i]}' (use --quick, --update-docs or --out DIR)");
                return 2;
            }
        }

        string? terrainDir = ReportContext.FindTerrainDir(out string terrainReason);
        Console.WriteLine(terrainDir is null
            ? $"real terrain: not found ({terrainReason}); the Holtburg scene is skipped"
            : $"real terrain: {terrainDir}");
        if (!quick)
        {
            // Warm-up: every scene's code once (quick), then a pause so the tiered JIT installs optimised code before timing.
            Console.WriteLine("warm-up: every scene once, untimed");
            var warm = new ReportContext(true, terrainDir) { Silent = true };
            foreach (var g in Groups)
            {
                g.Run(warm);
            }

            System.Threading.Thread.Sleep(500);
            FineCache.Clear();
        }

        var ctx = new ReportContext(quick, terrainDir);
        var clock = System.Diagnostics.Stopwatch.StartNew();
        for (int k = 0; k < Groups.Length; k++)
        {
            var g = Groups[k];
            int before = ctx.Rows.Count;
            var groupClock = System.Diagnostics.Stopwatch.StartNew();
            Console.WriteLine();
            Console.WriteLine($"[{k + 1}/{Groups.Length}] {g.Name}");
            Console.WriteLine(ReportContext.TableHeader);
            g.Run(ctx);
            Console.WriteLine($"      {ctx.Rows.Count - before} rows in {groupClock.Elapsed.TotalSeconds:F1} s");
        }

        if (ctx.TerrainDir is null)
        {
            ctx.Notes.Add($"The Holtburg walker scene was skipped: real terrain not found ({terrainReason}).");
        }

        Console.WriteLine();
        Console.WriteLine($"report scenes ran in {clock.Elapsed.TotalSeconds:F1} s");
        string md = ReportWriter.Markdown(ctx);
        if (quick)
        {
            Console.WriteLine($"--quick: {ctx.Rows.Count} rows measured, nothing written");
            return 0;
        }

        Directory.CreateDirectory(outDir);
        ReportWriter.Charts(ctx, outDir);
        File.WriteAllText(Path.Combine(outDir, "accuracy-vs-cost.md"), md);
        Console.WriteLine($"wrote {Path.Combine(outDir, "accuracy-vs-cost.md")} and its charts beside it");
        return 0;
    }

    // Substep profile: Retail (EPSILON gate, 0.2 s slices) against AceCompatible (1/30 s gate with accumulation, 0.1 s slices).
    private static void Substeps(ReportContext ctx)
    {
        const string sw = "substep profile";
        (LandHeightTable Table, List<LandBlockEntry> Blocks)? holtburg = ctx.TerrainDir is { } dir ? TerrainKit.ReadHoltburg(dir) : null;
        foreach (Pacing pacing in Pacing.All)
        {
            foreach (PhysicsProfile p in new[] { Retail, Ace })
            {
                string choice = $"{p.Name}, {pacing.Name}";
                bool retail = p == Retail;
                ctx.Measure(sw, FrictionScene.Name, choice, retail, FrictionScene.Reference, "m",
                    () => new FrictionScene(p, pacing, ctx.Seconds(1.0, 1.0)));
                ctx.Measure(sw, FreeFallScene.Name, choice, retail, FreeFallScene.Reference, "m",
                    () => new FreeFallScene(p, pacing, ctx.Seconds(5.0, 1.0)));
                MeasureAgainstFine(ctx, sw, LedgeJumpScene.Name, choice, retail, ctx.Seconds(6.0, 1.0),
                    (prof, pc, s) => new LedgeJumpScene(prof, pc, s), p, pacing, plot: pacing == Pacing.Fps30 || pacing == Pacing.Stutter60);
                MeasureAgainstFine(ctx, sw, WallSlideScene.Name, choice, retail, ctx.Seconds(8.0, 1.0),
                    (prof, pc, s) => new WallSlideScene(prof, pc, s), p, pacing);
                if (holtburg is not null)
                {
                    MeasureAgainstFine(ctx, sw, HoltburgWalkScene.Name, choice, retail, ctx.Seconds(20.0, 0.5),
                        (prof, pc, s) => new HoltburgWalkScene(holtburg.Value, prof, pc, s), p, pacing);
                }
            }
        }

        // What the fine-step references themselves cost (their error is zero by definition).
        FineCost(ctx, LedgeJumpScene.Name, ctx.Seconds(6.0, 1.0), (prof, pc, s) => new LedgeJumpScene(prof, pc, s));
        FineCost(ctx, WallSlideScene.Name, ctx.Seconds(8.0, 1.0), (prof, pc, s) => new WallSlideScene(prof, pc, s));
    }

    // Arithmetic: double intermediates (retail) against plain float32.
    private static void Arithmetic(ReportContext ctx)
    {
        const string sw = "arithmetic";
        foreach (ArithmeticMode mode in new[] { ArithmeticMode.RetailDouble, ArithmeticMode.Float32 })
        {
            PhysicsProfile p = Retail.With(arithmetic: mode);
            string choice = mode == ArithmeticMode.RetailDouble ? "double intermediates (retail)" : "float32 throughout";
            bool retail = mode == ArithmeticMode.RetailDouble;
            Pacing pc = Pacing.Fps30;
            ctx.Measure(sw, FreeFallScene.Name, choice, retail, FreeFallScene.Reference, "m", () => new FreeFallScene(p, pc, ctx.Seconds(5.0, 1.0)));
            ctx.Measure(sw, FrictionScene.Name, choice, retail, FrictionScene.Reference, "m", () => new FrictionScene(p, pc, ctx.Seconds(1.0, 1.0)));
            ctx.Measure(sw, ProjectileScene.Name, choice, retail, ProjectileScene.Reference, "m", () => new ProjectileScene(p, pc, ctx.Seconds(3.0, 1.0)));
            ctx.Measure(sw, SpinScene.Name + ", 10 min", choice, retail, SpinScene.Reference, "deg", () => new SpinScene(p, pc, ctx.Seconds(600.0, 2.0)));
            MeasureAgainstFine(ctx, sw, LedgeJumpScene.Name, choice, retail, ctx.Seconds(6.0, 1.0),
                (prof, pcc, s) => new LedgeJumpScene(prof, pcc, s), p, pc, plot: mode == ArithmeticMode.Float32);
        }
    }

    // Quaternion renormalisation: on every rotation change (retail) against every N-th and never.
    private static void Renormalisation(ReportContext ctx)
    {
        const string sw = "renormalisation";
        foreach (int every in new[] { 1, 4, 32, 0 })
        {
            PhysicsProfile p = Retail.With(renormaliseEvery: every);
            string choice = every switch { 1 => "every rotation change (retail)", 0 => "never", _ => $"every {every}th change" };
            ctx.Measure(sw, SpinScene.Name + ", 10 min", choice, every == 1, SpinScene.Reference, "deg",
                () => new SpinScene(p, Pacing.Fps30, ctx.Seconds(600.0, 2.0)));
            ctx.Measure(sw, SpinScene.Name + ", 2 h", choice, every == 1, SpinScene.Reference, "deg",
                () => new SpinScene(p, Pacing.Fps30, ctx.Seconds(7200.0, 2.0)));
        }
    }

    // Sweep resolution: ceil(|offset| / radius) steps (retail) against coarser and finer steps.
    private static void Sweep(ReportContext ctx)
    {
        const string sw = "sweep resolution";
        foreach (float scale in new[] { 0.25f, 0.5f, 1f, 2f, 4f, 8f })
        {
            PhysicsProfile p = Retail.With(sweepStepScale: scale);
            string choice = scale == 1f ? "step = radius (retail)" : $"step = {scale} × radius";
            ctx.Measure(sw, SweepTunnelScene.Name, choice, scale == 1f, SweepTunnelScene.Reference, "m",
                () => new SweepTunnelScene(p, Pacing.Fps30, ctx.Seconds(3.0, 0.5)));
            ctx.Measure(sw, ThinWallScene.Name, choice, scale == 1f, ThinWallScene.Reference, "m",
                () => new ThinWallScene(p, Pacing.Fps30, ctx.Seconds(1.5, 0.5)));
            MeasureAgainstFine(ctx, sw, LedgeJumpScene.Name, choice, scale == 1f, ctx.Seconds(6.0, 1.0),
                (prof, pc, s) => new LedgeJumpScene(prof, pc, s), p, Pacing.Fps30);
        }
    }

    // Remote-object smoothing: retail interpolation against snapping and linear extrapolation.
    private static void Smoothing(ReportContext ctx)
    {
        const string sw = "remote smoothing";
        foreach (Pacing pc in new[] { Pacing.Fps60, Pacing.Stutter60 })
        {
            foreach (RemoteSmoothing mode in new[] { RemoteSmoothing.Retail, RemoteSmoothing.Snap, RemoteSmoothing.LinearExtrapolation })
            {
                PhysicsProfile p = Retail.With(remoteSmoothing: mode);
                string choice = (mode == RemoteSmoothing.Retail ? "interpolation (retail)" : mode == RemoteSmoothing.Snap ? "snap to each update" : "linear extrapolation") + ", " + pc.Name;
                ctx.Measure(sw, RemoteCreatureScene.Name, choice, mode == RemoteSmoothing.Retail, RemoteCreatureScene.Reference, "m",
                    () => new RemoteCreatureScene(p, pc, ctx.Seconds(14.0, 2.0)));
            }
        }
    }

    private static readonly Dictionary<string, Trajectory[]> FineCache = [];

    private static void MeasureAgainstFine(ReportContext ctx, string sw, string scene, string choice, bool retail, double seconds,
        Func<PhysicsProfile, Pacing?, double, StepSceneSim> make, PhysicsProfile p, Pacing pacing, bool plot = false)
    {
        string key = scene + "|" + seconds.ToString(System.Globalization.CultureInfo.InvariantCulture);
        if (!FineCache.TryGetValue(key, out Trajectory[]? reference))
        {
            StepSceneSim fine = make(Retail, null, seconds);
            for (int i = 0; i < fine.Frames; i++)
            {
                fine.Advance(i);
                fine.Sample(i);
            }

            reference = fine.Recorded;
            FineCache[key] = reference;
            if (scene == LedgeJumpScene.Name)
            {
                ctx.AddTrajectory(LedgeJumpScene.Name, "fine-step reference (1/600 s)", XZ(reference[0]));
            }
        }

        StepSceneSim? last = null;
        ctx.Measure(sw, scene, choice, retail, "fine-step reference (1/600 s, retail double)", "m", () =>
        {
            StepSceneSim s = make(p, pacing, seconds);
            s.Reference = reference;
            last ??= s;
            return s;
        });
        if (plot && last is not null)
        {
            ctx.AddTrajectory(scene, choice, XZ(last.Recorded[0]));
        }
    }

    private static void FineCost(ReportContext ctx, string scene, double seconds, Func<PhysicsProfile, Pacing?, double, StepSceneSim> make) =>
        ctx.Measure("substep profile", scene, "fine-step reference: update_object every 1/600 s", false, "(is the reference)", "m",
            () => make(Retail, null, seconds));

    private static List<(double X, double Y)> XZ(Trajectory t)
    {
        var list = new List<(double X, double Y)>(t.T.Count);
        for (int i = 0; i < t.T.Count; i++)
        {
            list.Add((t.P[i].X, t.P[i].Z));
        }

        return list;
    }

    private static string FindRepoRoot()
    {
        string? dir = AppContext.BaseDirectory;
        while (dir != null)
        {
            if (File.Exists(Path.Combine(dir, "AcDream.sln")))
            {
                return dir;
            }

            dir = Path.GetDirectoryName(dir);
        }

        return Directory.GetCurrentDirectory();
    }
}
