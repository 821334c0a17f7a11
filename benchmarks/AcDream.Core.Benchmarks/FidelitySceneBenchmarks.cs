using System;
using System.Numerics;
using AcDream.Core.Benchmarks.Report;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Scene ticks under each fidelity choice: N walkers (one 0.5 m sphere, 3 m/s, turning 0.5 rad/s) on a hand-made hilly
/// landblock through the retail sweep, the world ticked at 0.034 s. The choices are those of the accuracy report
/// (docs/accuracy-vs-cost.md). Each invoke runs <see cref="Ticks"/> world ticks; the mean is per world tick.
/// </summary>
[MemoryDiagnoser]
public class FidelitySceneBenchmarks
{
    private const int Ticks = 10;
    private const double Dt = 0.034;
    private PhysicsWorld _world = null!;
    private double _now;

    /// <summary>Number of walkers.</summary>
    [Params(10, 100)]
    public int N { get; set; }

    /// <summary>Fidelity choice: Retail, AceCompatible, Float32, RenormaliseNever, SweepCoarse4 (step = 4 × radius).</summary>
    [Params("Retail", "AceCompatible", "Float32", "RenormaliseNever", "SweepCoarse4")]
    public string Fidelity { get; set; } = "Retail";

    /// <summary>Builds the terrain (heights rising 2 m per vertex eastward and northward, a gentle hill) and the walkers.</summary>
    [GlobalSetup]
    public void Setup()
    {
        PhysicsProfile profile = Fidelity switch
        {
            "Retail" => PhysicsProfile.Retail,
            "AceCompatible" => PhysicsProfile.AceCompatible,
            "Float32" => PhysicsProfile.Retail.With(arithmetic: ArithmeticMode.Float32),
            "RenormaliseNever" => PhysicsProfile.Retail.With(renormaliseEvery: 0),
            "SweepCoarse4" => PhysicsProfile.Retail.With(sweepStepScale: 4f),
            _ => throw new ArgumentException("unknown fidelity choice", nameof(Fidelity)),
        };
        TerrainWorld terrain = TerrainKit.Metres();
        TerrainKit.AddBlock(terrain, (vx, vy) => 10 + 2 * vx + vy + (vx * vy % 3));
        _world = TerrainKit.World(terrain, profile);
        for (int i = 0; i < N; i++)
        {
            float x = 20f + (i % 10) * 15f, y = 20f + (i / 10) * 15f % 150f;
            Position p = SyntheticTerrain.OnGround(terrain, TerrainKit.CellId((int)(x / 24f), (int)(y / 24f)), x, y, 36f * i);
            PhysicsObj w = TerrainKit.Walker(_world, p, (uint)(i + 1));
            TerrainKit.Walk(w, new Vector3(0f, 3f, 0f), 0.5f);
        }

        _now = 0.0;
    }

    /// <summary>One world tick.</summary>
    [Benchmark(OperationsPerInvoke = Ticks)]
    public bool Tick()
    {
        bool ticked = false;
        for (int i = 0; i < Ticks; i++)
        {
            _now += Dt;
            ticked = _world.Tick(_now);
        }

        return ticked;
    }
}
