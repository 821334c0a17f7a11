using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Retail's detection manager: one pass over eight detection cylinders (<c>DetectionManager::CheckDetection</c> for each:
/// the object lookup, the distance, the enter / leave decision), and one 30 Hz world tick of a detector watching eight objects
/// that walk in and out (a check every second, with its reports). Every row must allocate 0 B.
/// </summary>
[MemoryDiagnoser]
public class DetectionBenchmarks
{
    private const int Watched = 8;
    private PhysicsWorld _world = null!;
    private PhysicsObj _detector = null!;
    private DetectionManager _manager = null!;
    private readonly PhysicsObj[] _objects = new PhysicsObj[Watched];
    private readonly DetectionCylsphere[] _cylinders = new DetectionCylsphere[Watched];
    private int _ticks;

    /// <summary>Free space; the detector at the block centre, eight objects 2 .. 9 m north of it, cylinders of radius 5 m.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _world = new PhysicsWorld(0.0);
        _detector = _world.CreateObject(1);
        _detector.PartArray = new SimplePartArray(1, 1) { Radius = 0.5f };
        Enter(_detector, 0f);
        _world.Player = _detector;
        _manager = new DetectionManager(_detector, new NullListener());
        _detector.DetectionManager = _manager;
        for (int i = 0; i < Watched; i++)
        {
            PhysicsObj o = _world.CreateObject((uint)(10 + i));
            o.PartArray = new SimplePartArray(1, 1) { Radius = 0.5f };
            Enter(o, 2f + i);
            _objects[i] = o;
            _manager.CreateDetectionCylsphere((uint)(100 + i), o.Id, 5f);
            _cylinders[i] = _manager.Find((uint)(100 + i))!;
        }

        for (int i = 0; i < 120; i++)
        {
            Tick();
        }
    }

    private static void Enter(PhysicsObj o, float north)
    {
        if (!o.EnterWorld(At(north)))
        {
            throw new System.InvalidOperationException("The benchmark's object did not enter the world.");
        }
    }

    private static Position At(float north) =>
        new(0xA9B40001u, Frame.FromHeading(new Vector3(96f, 96f + north, 0f), 0f));

    /// <summary>One check of each of the eight cylinders against its object.</summary>
    [Benchmark]
    public int CheckEightCylinders()
    {
        int changes = 0;
        for (int i = 0; i < Watched; i++)
        {
            _cylinders[i].ObjectDetected = (i & 1) == 0;
            changes += (int)_manager.CheckDetection(_cylinders[i], _objects[i]);
        }

        return changes;
    }

    /// <summary>One world tick (1/30 s); every second the objects swap between 2 .. 9 m and 9 .. 16 m (reports each check).</summary>
    [Benchmark]
    public void TickWithDetection() => Tick();

    private void Tick()
    {
        if (++_ticks % 30 == 0)
        {
            float shift = (_ticks / 30) % 2 == 0 ? 0f : 7f;
            for (int i = 0; i < Watched; i++)
            {
                _objects[i].SetPosition(At(2f + i + shift), SetPositionFlags.Placement);
            }
        }

        _world.Tick(_world.CurrentTime + (1.0 / 30.0));
    }

    private sealed class NullListener : IDetectionListener
    {
        public void OnDetection(PhysicsObj detector, uint contextId, DetectionInfo info)
        {
        }
    }
}
