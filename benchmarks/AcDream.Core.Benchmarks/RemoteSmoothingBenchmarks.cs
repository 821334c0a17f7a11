using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Replay.Harness;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// The position managers at work: N remote creatures on level ground (<c>FlatFloorSeam</c>) around the player, each
/// receiving a server position 1 m ahead every 8th world tick, under each <see cref="RemoteSmoothing"/> (retail: the
/// InterpolationManager's adjust_offset / UseTime every step, the ConstraintManager re-armed on every report).
/// Each invoke runs <see cref="Ticks"/> world ticks at 0.034 s; the mean is per world tick, reports included.
/// </summary>
[MemoryDiagnoser]
public class RemoteSmoothingBenchmarks
{
    private const int Ticks = 16;
    private const double Dt = 0.034;
    private PhysicsWorld _world = null!;
    private PhysicsObj[] _creatures = [];
    private double _now;
    private int _tick;
    private ushort _stamp;

    /// <summary>Number of remote creatures.</summary>
    [Params(10, 100, 1000)]
    public int N { get; set; }

    /// <summary>How the creatures follow their reports.</summary>
    [Params(RemoteSmoothing.Retail, RemoteSmoothing.Snap, RemoteSmoothing.LinearExtrapolation)]
    public RemoteSmoothing Smoothing { get; set; }

    /// <summary>Builds the world: the player at (96, 96), creatures on a grid within 40 m of it, walking north 2 m/s.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _world = new PhysicsWorld(0.0, PhysicsProfile.Retail.With(remoteSmoothing: Smoothing)) { Sweep = new ReplayGroundSweep() };
        PhysicsObj player = _world.CreateObject(1);
        player.PartArray = new SimplePartArray(1, 1) { Radius = 0.5f };
        player.EnterWorld(new Position(0x80800001u, new Vector3(96f, 96f, 0f)));
        _world.Player = player;
        _creatures = new PhysicsObj[N];
        for (int i = 0; i < N; i++)
        {
            PhysicsObj c = _world.CreateObject((uint)(i + 2));
            c.PartArray = new SimplePartArray(1, 1) { Radius = 0.5f, Height = 1.8f, SequenceVelocity = new Vector3(0f, 2f, 0f) };
            c.Movement = new BasicMovementManager();
            var p = new Position(0x80800001u, new Vector3(66f + (i % 32) * 2f, 66f + (i / 32) * 2f, 0f));
            p.TryAdjustToOutside();
            c.EnterWorld(p);
            _creatures[i] = c;
        }

        _now = 0.0;
        _tick = 0;
        _world.Tick(_now += Dt);
    }

    /// <summary>One world tick, with the reports due in it.</summary>
    [Benchmark(OperationsPerInvoke = Ticks)]
    public bool Tick()
    {
        bool ticked = false;
        for (int i = 0; i < Ticks; i++)
        {
            _now += Dt;
            if ((++_tick & 7) == 0)
            {
                _stamp++;
                _world.SetCurrentTime(_now);
                foreach (PhysicsObj c in _creatures)
                {
                    Position p = c.Position;
                    p.Frame.Origin += new Vector3(0f, 1f, 0f);
                    p.TryAdjustToOutside();
                    c.HandleReceivedPosition(p, _stamp, 0, true);
                }
            }

            ticked = _world.Tick(_now);
        }

        return ticked;
    }
}
