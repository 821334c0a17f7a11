using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// One object's <c>update_object</c>: a moving, spinning object with one collision sphere swept through free space.
/// <c>ThirtyHz</c> advances the clock by 1/30 s (one step); <c>Stall045</c> by 0.45 s (three steps: 0.2, 0.2, 0.05).
/// Each invoke runs <see cref="Ops"/> updates; the mean is per update_object.
/// </summary>
[MemoryDiagnoser]
public class UpdateObjectBenchmarks
{
    private const int Ops = 1000;
    private PhysicsWorld _world = null!;
    private PhysicsObj _obj = null!;
    private double _now;

    /// <summary>Builds a world with one active object (gravity off so its speed stays constant).</summary>
    [GlobalSetup]
    public void Setup()
    {
        _world = new PhysicsWorld(0.0);
        _obj = BenchScene.CreateMover(_world, new Vector3(10f, 10f, 50f));
        _now = 0.0;
    }

    /// <summary>update_object after 1/30 s: one UpdateObjectInternal step.</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public double ThirtyHz()
    {
        for (int i = 0; i < Ops; i++)
        {
            _now += 1.0 / 30.0;
            _world.SetCurrentTime(_now);
            _obj.UpdateObject();
        }

        return _obj.UpdateTime;
    }

    /// <summary>update_object after a 0.45 s stall: three steps.</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public double Stall045()
    {
        for (int i = 0; i < Ops; i++)
        {
            _now += 0.45;
            _world.SetCurrentTime(_now);
            _obj.UpdateObject();
        }

        return _obj.UpdateTime;
    }
}

/// <summary>Scene builders shared by the tick benchmarks.</summary>
internal static class BenchScene
{
    /// <summary>An object with one collision sphere, moving at 1 m/s east and spinning at 0.5 rad/s, gravity off.</summary>
    public static PhysicsObj CreateMover(PhysicsWorld world, Vector3 origin, uint id = 0)
    {
        PhysicsObj obj = world.CreateObject(id);
        obj.PartArray = new SimplePartArray(numParts: 1, numSpheres: 1);
        obj.EnterWorld(new Position(0xA9B40001u, origin));
        obj.SetState(obj.State & ~PhysicsState.Gravity);
        obj.CalcAcceleration();
        obj.SetVelocity(new Vector3(1f, 0f, 0f));
        obj.SetOmega(new Vector3(0f, 0f, 0.5f));
        return obj;
    }
}
