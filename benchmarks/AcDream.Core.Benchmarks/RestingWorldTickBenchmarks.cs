using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Replay.Harness;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// The world tick (<c>CPhysics::UseTime</c>) with N objects really at rest: one sphere each, gravity on, settled on flat
/// ground (Holtburg's block 0xA9B4, on a 1.44 m grid), the player among them and standing still. The companion of
/// <see cref="WorldTickBenchmarks"/>, whose objects are not at rest (each moves at 1 m/s and turns at 0.5 rad/s every tick,
/// so retail simulates every one of them). Retail visits a resting object every tick only to find nothing to do; the
/// scene's dormancy keeps it out of the tick bit-identically (all but the player, which is always visited), so the mean per world tick should not grow with N.
/// Mean per world tick.
/// </summary>
[MemoryDiagnoser]
public class RestingWorldTickBenchmarks
{
    private const int Ticks = 10;
    private const double Dt = 0.034;
    private PhysicsWorld _world = null!;
    private double _now;

    /// <summary>Number of resting objects.</summary>
    [Params(100, 1000, 10000)]
    public int N { get; set; }

    /// <summary>Builds the world and ticks it until every object has settled and gone dormant.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _world = new PhysicsWorld(0.0) { Sweep = new ReplayGroundSweep() };
        for (int i = 0; i < N; i++)
        {
            SceneBench.Item(_world, (uint)(1 + i), SceneBench.At(-70f + (i % 100) * 1.44f, -70f + (i / 100) * 1.44f));
        }

        _world.Player = _world.GetObject(0);
        _now = 0.0;
        for (int i = 0; i < 20; i++)
        {
            TickOnce();
        }

        // The player is never dormant: it is the one object every tick visits.
        if (_world.LastTickVisitCount != 1)
        {
            throw new System.InvalidOperationException(
                $"{_world.LastTickVisitCount} of {N} objects are visited after settling (expected the player alone): the row would not measure rest.");
        }
    }

    /// <summary>One world tick.</summary>
    [Benchmark(OperationsPerInvoke = Ticks)]
    public int Tick()
    {
        for (int i = 0; i < Ticks; i++)
        {
            TickOnce();
        }

        return _world.LastTickVisitCount;
    }

    // One world tick of the row (InstructionCounts).
    internal int TickOnce()
    {
        _now += Dt;
        _world.Tick(_now);
        return _world.LastTickVisitCount;
    }
}
