using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Objects streamed in and out: <see cref="Add"/> creates 100,000 moving objects (the mover of <see cref="BenchScene"/>, spread
/// over a landblock) in the given id order into an empty world and ticks once (the tick merges them into the visiting list);
/// <see cref="Remove"/> removes the 100,000 objects of a ticked world (created in ascending id order, so ascending removal is
/// oldest first) in the given id order. The mean is per object.
/// </summary>
[MemoryDiagnoser]
public class ObjectChurnBenchmarks
{
    private const int N = 100_000;
    private uint[] _ids = null!;
    private PhysicsWorld _world = null!;
    private PhysicsObj?[] _byId = null!;

    /// <summary>The id order of the creations or removals.</summary>
    [Params(IdOrder.Ascending, IdOrder.Descending, IdOrder.Random)]
    public IdOrder Order { get; set; }

    /// <summary>The ids in <see cref="Order"/>.</summary>
    [GlobalSetup]
    public void Setup() => _ids = IdOrders.Ids(N, Order);

    /// <summary>An empty world.</summary>
    [IterationSetup(Target = nameof(Add))]
    public void SetupAdd() => _world = new PhysicsWorld(0.0);

    /// <summary>A world with the N objects, created in ascending id order and ticked once.</summary>
    [IterationSetup(Target = nameof(Remove))]
    public void SetupRemove()
    {
        _world = new PhysicsWorld(0.0);
        _byId = new PhysicsObj?[N + 1];
        for (uint id = 1; id <= N; id++)
        {
            _byId[id] = Create(_world, id);
        }

        _world.Tick(0.034);
    }

    /// <summary>Creates the N objects in <see cref="Order"/>, then one world tick.</summary>
    [Benchmark(OperationsPerInvoke = N)]
    public int Add()
    {
        foreach (uint id in _ids)
        {
            Create(_world, id);
        }

        _world.Tick(0.034);
        return _world.ObjectCount;
    }

    /// <summary>Removes the N objects in <see cref="Order"/>.</summary>
    [Benchmark(OperationsPerInvoke = N)]
    public int Remove()
    {
        foreach (uint id in _ids)
        {
            _world.RemoveObject(_byId[id]!);
        }

        return _world.ObjectCount;
    }

    // Objects 0.2 m apart on a 400 x 250 grid (80 x 50 m) inside landblock 0xA9B4.
    private static PhysicsObj Create(PhysicsWorld world, uint id)
    {
        int i = (int)id - 1;
        return BenchScene.CreateMover(world, new Vector3(10f + (i % 400) * 0.2f, 10f + (i / 400) * 0.2f, 50f), id);
    }
}
