using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// The free step of an object without shape (a part array with no collision spheres, so no sweep): falling under gravity
/// and spinning, retail profile. <c>UpdateObjectFreeStep</c> is one object's update_object after 1/30 s (one step);
/// <c>WorldTick1000NoShape</c> one world tick of 1,000 such objects (one step each). Every 64 steps the velocity is set back
/// to 1 m/s east so the fall stays below the 50 m/s clamp. The means are per update_object and per world tick.
/// </summary>
[MemoryDiagnoser]
public class FreeStepBenchmarks
{
    private const int Ops = 1024;
    private const int Ticks = 64;
    private const int WorldObjects = 1000;
    private static readonly Vector3 Restart = new(1f, 0f, 0f);

    // 0.034 s >= 1/30: every tick passes the outer gate and every object takes one step.
    private const double Dt = 0.034;

    private PhysicsWorld _one = null!;
    private PhysicsObj _obj = null!;
    private double _oneNow;
    private PhysicsWorld _world = null!;
    private double _worldNow;

    /// <summary>A falling, spinning object without collision spheres.</summary>
    internal static PhysicsObj CreateFaller(PhysicsWorld world, Vector3 origin)
    {
        PhysicsObj obj = world.CreateObject();
        obj.PartArray = new SimplePartArray(numParts: 1, numSpheres: 0);
        obj.EnterWorld(new Position(0xA9B40001u, origin));
        obj.SetVelocity(Restart);
        obj.SetOmega(new Vector3(0f, 0f, 0.5f));
        return obj;
    }

    /// <summary>Builds the one-object world and the 1,000-object world (the player is the first object; all within 96 m).</summary>
    [GlobalSetup]
    public void Setup()
    {
        _one = new PhysicsWorld(0.0);
        _obj = CreateFaller(_one, new Vector3(10f, 10f, 50f));
        _world = new PhysicsWorld(0.0);
        for (int i = 0; i < WorldObjects; i++)
        {
            CreateFaller(_world, new Vector3(10f + (i % 100) * 0.5f, 10f + (i / 100) * 0.1f, 50f));
        }

        _world.Player = _world.GetObject(0);
    }

    /// <summary>update_object after 1/30 s: one free step.</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public double UpdateObjectFreeStep()
    {
        for (int i = 0; i < Ops; i++)
        {
            if ((i & 63) == 0)
            {
                _obj.SetVelocity(Restart);
            }

            _oneNow += 1.0 / 30.0;
            _one.SetCurrentTime(_oneNow);
            _obj.UpdateObject();
        }

        return _obj.UpdateTime;
    }

    /// <summary>One world tick of 1,000 objects without shape.</summary>
    [Benchmark(OperationsPerInvoke = Ticks)]
    public bool WorldTick1000NoShape()
    {
        bool ticked = false;
        for (int i = 0; i < Ticks; i++)
        {
            _worldNow += Dt;
            ticked = _world.Tick(_worldNow);
        }

        for (int k = 0; k < WorldObjects; k++)
        {
            _world.GetObject(k).SetVelocity(Restart);
        }

        return ticked;
    }
}
