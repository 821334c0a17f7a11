using System.Numerics;
using AcDream.Core.Physics.World;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// The whole world tick (<c>CPhysics::UseTime</c>) with N moving objects, each updated once per tick (one step): one
/// sphere, 1 m/s and 0.5 rad/s, no gravity, so none is ever at rest (docs/performance.md called these rows "resting
/// objects" until #38; <see cref="RestingWorldTickBenchmarks"/> is the world of objects really at rest).
/// Each invoke runs <see cref="Ticks"/> ticks; the mean is per world tick.
/// </summary>
[MemoryDiagnoser]
public class WorldTickBenchmarks
{
    private const int Ticks = 10;

    // 0.034 s >= 1/30: every tick passes the outer gate and every object takes one step (1/30 itself could fall an ulp short).
    private const double Dt = 0.034;

    private PhysicsWorld _world = null!;
    private double _now;

    /// <summary>Number of moving objects in the world.</summary>
    [Params(100, 1000, 10000)]
    public int N { get; set; }

    /// <summary>Builds the world; the player is the first object and every object is within 96 m of it.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _world = new PhysicsWorld(0.0);
        for (int i = 0; i < N; i++)
        {
            BenchScene.CreateMover(_world, new Vector3(10f + (i % 100) * 0.5f, 10f + (i / 100) * 0.1f, 50f));
        }

        _world.Player = _world.GetObject(0);
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

    // One world tick of the row (InstructionCounts).
    internal bool TickOnce()
    {
        _now += Dt;
        return _world.Tick(_now);
    }
}
