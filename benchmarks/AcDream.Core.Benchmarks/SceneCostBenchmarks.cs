using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Scene;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Replay.Harness;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// A scene pays only for what moves: one world tick with 100 creatures (one of them the player; the other 99 walking 2 m squares)
/// among 0, 10,000 or 100,000 resting or static objects (half resting items, half static scenery, on a 1.44 m grid over a
/// 576 x 360 m area around the player). The player walks a 2 m square with the others, walks a 51 m line back and forth, or stands
/// still. The resting objects are dormant and never visited; the only per-tick cost they add is the exact 96 m gate: dormant
/// objects within 2 m of the moving player's 96 m circle are tested from the gate ring each tick it moves (the ring is rebuilt
/// every 2 m of travel), and those it passes over change side without a visit. Mean per world tick.
/// </summary>
[MemoryDiagnoser]
public class SceneRestingObjectsBenchmarks
{
    private const int Ticks = 10;
    private PhysicsWorld _world = null!;
    private double _now;
    private int _tick;
    private PhysicsObj[] _movers = null!;

    /// <summary>The scene's world (for the in-process comparison, <c>scene-ab</c>).</summary>
    internal PhysicsWorld World => _world;

    /// <summary>The walking player's speed, m/s (2 as the other movers; <c>scene-ab --speed</c> sets a runner's). A line leg
    /// stays 51 m long whatever the speed.</summary>
    internal float PlayerSpeed { get; set; } = 2f;

    private int LineLegTicks => Math.Max(1, (int)Math.Round(51.0 / (PlayerSpeed * 0.034)));

    /// <summary>Number of resting or static objects besides the 100 movers.</summary>
    [Params(0, 10_000, 100_000)]
    public int Resting { get; set; }

    /// <summary>How dormant objects follow the player's 96 m gate.</summary>
    [Params(GateTracking.Exact, GateTracking.MovingObjectsOnly)]
    public GateTracking Gate { get; set; }

    /// <summary>How the player moves.</summary>
    [Params(PlayerPath.Square, PlayerPath.Line, PlayerPath.Still)]
    public PlayerPath Player { get; set; } = PlayerPath.Square;

    /// <summary>Builds the scene and ticks it until the resting objects are dormant.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _world = new PhysicsWorld(0.0) { Sweep = new ReplayGroundSweep(), GateTracking = Gate };
        _movers = new PhysicsObj[100];
        for (int i = 0; i < _movers.Length; i++)
        {
            _movers[i] = SceneBench.Mover(_world, (uint)(1 + i), SceneBench.At(40f + (i % 10) * 10f, 40f + (i / 10) * 10f));
        }

        _world.Player = _movers[0];
        if (Player == PlayerPath.Still)
        {
            ((SimplePartArray)_movers[0].PartArray!).SequenceVelocity = System.Numerics.Vector3.Zero;
        }
        else
        {
            ((SimplePartArray)_movers[0].PartArray!).SequenceVelocity = new System.Numerics.Vector3(0f, PlayerSpeed, 0f);
        }

        for (int i = 0; i < Resting; i++)
        {
            // A 3 x 3 block area (576 m square) centred on block 0xA9B4; ids after the movers.
            float x = -192f + (i % 400) * 1.44f;
            float y = -192f + (i / 400 % 400) * 1.44f;
            PhysicsObj o = SceneBench.Item(_world, (uint)(1000 + i), SceneBench.At(x, y));
            if ((i & 1) == 1)
            {
                o.SetState(o.State | PhysicsState.Static);
            }
        }

        _now = 0.0;
        for (int i = 0; i < 20; i++)
        {
            Step();
        }
    }

    /// <summary>One world tick.</summary>
    [Benchmark(OperationsPerInvoke = Ticks)]
    public int Tick()
    {
        for (int i = 0; i < Ticks; i++)
        {
            Step();
        }

        return _world.LastTickVisitCount;
    }

    private void Step()
    {
        // Movers walk (root motion, 2 m/s) in a square: every 30 ticks they turn 90 degrees, so they stay in the area forever.
        if (_tick % 30 == 0)
        {
            float heading = _tick / 30 % 4 * 90f;
            for (int m = Player == PlayerPath.Line ? 1 : 0; m < _movers.Length; m++)
            {
                _movers[m].SetHeading(heading);
            }
        }

        if (Player == PlayerPath.Line && _tick % LineLegTicks == 0)
        {
            _movers[0].SetHeading(_tick / LineLegTicks % 2 == 0 ? 90f : 270f); // 51 m east, then back west
        }

        _tick++;
        _now += 0.034;
        _world.Tick(_now);
    }
}

/// <summary>
/// What each effect costs: 1,000 remote creatures (root motion, interpolation from server updates every 6 ticks, gravity and
/// friction on flat ground, a fade hook re-armed every 60 ticks) ticked under effect sets that add one effect at a time, from
/// "interpolation only" to "everything". Mean per world tick.
/// </summary>
[MemoryDiagnoser]
public class SceneEffectsBenchmarks
{
    private const int Ticks = 6;
    private PhysicsWorld _world = null!;
    private PhysicsObj[] _creatures = null!;
    private Position[] _targets = null!;
    private double _now;
    private int _tick;

    /// <summary>The declared effect set.</summary>
    /// <remarks>Collision is declared from the second set on: without it (and with gravity) the creatures would fall through the
    /// ground, drift past the 96 m gate and freeze, which measures something else.</remarks>
    [Params("1 Interpolation", "2 +Collision", "3 +Gravity+Friction", "4 +Hooks", "5 +RootMotion", "6 All")]
    public string EffectSet { get; set; } = "6 All";

    /// <summary>Builds 1,000 creatures and a player.</summary>
    [GlobalSetup]
    public void Setup()
    {
        const SceneEffects two = SceneEffects.Interpolation | SceneEffects.Collision;
        const SceneEffects three = two | SceneEffects.Gravity | SceneEffects.Friction;
        SceneEffects fx = EffectSet switch
        {
            "1 Interpolation" => SceneEffects.Interpolation,
            "2 +Collision" => two,
            "3 +Gravity+Friction" => three,
            "4 +Hooks" => three | SceneEffects.Hooks,
            "5 +RootMotion" => three | SceneEffects.Hooks | SceneEffects.RootMotion,
            _ => SceneEffects.All,
        };
        _world = new PhysicsWorld(0.0, hookPoolCapacity: 1100) { Effects = fx, Sweep = new ReplayGroundSweep() };
        // Every creature within 96 m of the player (a far creature keeps its fades unprocessed, as retail does).
        PhysicsObj player = SceneBench.Item(_world, 1, SceneBench.At(70f, 64f));
        _world.Player = player;
        _creatures = new PhysicsObj[1000];
        _targets = new Position[1000];
        for (int i = 0; i < _creatures.Length; i++)
        {
            Position p = SceneBench.At(40f + (i % 40) * 1.5f, 40f + (i / 40) * 2f);
            PhysicsObj c = SceneBench.Item(_world, (uint)(100 + i), p);
            ((SimplePartArray)c.PartArray!).SequenceVelocity = new Vector3(0f, 1f, 0f);
            c.GetOrCreateMotionInterpreter();
            _creatures[i] = c;
            _targets[i] = p;
        }

        for (int i = 0; i < 60; i++)
        {
            Step();
        }
    }

    /// <summary>One world tick.</summary>
    [Benchmark(OperationsPerInvoke = Ticks)]
    public int Tick()
    {
        for (int i = 0; i < Ticks; i++)
        {
            Step();
        }

        return _world.LastTickVisitCount;
    }

    private void Step()
    {
        if (_tick % 6 == 0)
        {
            float dy = (_tick / 6 % 20) * 0.3f;
            for (int i = 0; i < _creatures.Length; i++)
            {
                Position t = _targets[i];
                t.Frame.Origin += new Vector3(0f, dy, 0f);
                _creatures[i].InterpolateTo(t, keepHeading: false);
            }
        }

        if (_tick % 60 == 0)
        {
            for (int i = 0; i < _creatures.Length; i++)
            {
                _creatures[i].SetTranslucency((_tick / 60 & 1) == 0 ? 0.5f : 0f, 1.0);
            }
        }

        _tick++;
        _now += 0.034;
        _world.Tick(_now);
    }
}

/// <summary>Scene builders for the scene benchmarks.</summary>
internal static class SceneBench
{
    public static Position At(float x, float y)
    {
        var p = new Position(0xA9B40001u, new Vector3(x, y, 0f));
        p.TryAdjustToOutside();
        return p;
    }

    /// <summary>A resting item: one sphere, gravity on, placed on the flat ground.</summary>
    public static PhysicsObj Item(PhysicsWorld w, uint id, Position p)
    {
        PhysicsObj o = w.CreateObject(id);
        o.PartArray = new SimplePartArray(numParts: 1, numSpheres: 1);
        o.EnterWorld(p);
        return o;
    }

    /// <summary>A mover: a walking creature (movement manager, so it never deactivates; root motion 2 m/s forward).</summary>
    public static PhysicsObj Mover(PhysicsWorld w, uint id, Position p)
    {
        PhysicsObj o = Item(w, id, p);
        o.GetOrCreateMotionInterpreter();
        ((SimplePartArray)o.PartArray!).SequenceVelocity = new Vector3(0f, 2f, 0f);
        return o;
    }
}
