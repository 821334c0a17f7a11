using System.Numerics;
using AcDream.Core.Physics.World;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// One world tick of 100,000 moving objects (the mover of <see cref="BenchScene"/>, 0.2 m apart on a 400 x 250 grid, no
/// player, so every object stays awake) created in ascending or in random id order. The tick visits them by id either way; a
/// client receives objects in any order, and the random-order row must cost at most 1.3 times the ascending one. Each invoke
/// runs <see cref="Ticks"/> ticks; the mean is per world tick (divide by 100,000 for the cost per object).
/// </summary>
[MemoryDiagnoser]
public class CreationOrderTickBenchmarks
{
    private const int N = 100_000;
    private const int Ticks = 4;
    private PhysicsWorld _world = null!;
    private double _now;

    /// <summary>The order the objects were created in.</summary>
    [Params(IdOrder.Ascending, IdOrder.Random)]
    public IdOrder Order { get; set; }

    /// <summary>Builds the world and ticks it once (every object joins the visiting list).</summary>
    [GlobalSetup]
    public void Setup()
    {
        _world = new PhysicsWorld(0.0);
        foreach (uint id in IdOrders.Ids(N, Order))
        {
            int i = (int)id - 1;
            BenchScene.CreateMover(_world, new Vector3(10f + (i % 400) * 0.2f, 10f + (i / 400) * 0.2f, 50f), id);
        }

        _now = 0.034;
        _world.Tick(_now);
    }

    /// <summary>One world tick.</summary>
    [Benchmark(OperationsPerInvoke = Ticks)]
    public int Tick()
    {
        for (int i = 0; i < Ticks; i++)
        {
            _now += 0.034;
            _world.Tick(_now);
        }

        return _world.LastTickVisitCount;
    }
}
