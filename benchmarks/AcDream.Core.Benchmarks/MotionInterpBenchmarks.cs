using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// The motion interpreter's cost: re-interpreting the player's raw commands (the run key toggled: apply_raw_movement, three
/// adjust_motion, the motion table's cycle and modifiers, the completed-motion report), the state velocity, and one world
/// tick of a player running in a circle on flat ground through the retail sweep. Every row must allocate 0 B.
/// </summary>
[MemoryDiagnoser]
public class MotionInterpBenchmarks
{
    private PhysicsWorld _world = null!;
    private PhysicsObj _player = null!;
    private MotionInterp _mi = null!;
    private double _now;

    /// <summary>Builds a flat landblock and the player running (skill 200, 9.5 m/s) and turning (π/2 rad/s).</summary>
    [GlobalSetup]
    public void Setup()
    {
        var terrain = SyntheticTerrain.Metres();
        SyntheticTerrain.AddBlock(terrain, 0x80, 0x80, (_, _) => 20);
        _world = new PhysicsWorld(0.0) { Sweep = new RetailSweep(terrain) };
        _player = _world.CreateObject(1);
        _player.Weenie = new PlayerWeenie { RunSkill = 200, JumpSkill = 200 };
        var parts = Walkers.OneSphere();
        parts.MotionPlayer = new SpeedOnlyMotionPlayer();
        _player.PartArray = parts;
        _player.EnterWorld(new Position(SyntheticTerrain.CellId(0x80, 0x80, 4, 4), new Vector3(96f, 90f, 20f)));
        _world.Player = _player;
        MovementManager mm = MovementManager.Of(_player);
        _mi = mm.GetOrCreateMotionInterpreter();
        mm.DoMotion(MotionCommand.WalkForward, new MovementParameters { HoldKeyToApply = HoldKey.Run });
        mm.DoMotion(MotionCommand.TurnRight, new MovementParameters());
        _now = 0.0;
        for (int i = 0; i < 100; i++)
        {
            _world.Tick(_now += 1.0 / 30.0);
        }
    }

    /// <summary>The run key off and on: two apply_raw_movement passes and their completion reports.</summary>
    [Benchmark(OperationsPerInvoke = 2)]
    public void HoldRunToggle()
    {
        _mi.SetHoldRun(false, cancelMoveToOnChange: false);
        _player.CheckForCompletedMotions();
        _mi.SetHoldRun(true, cancelMoveToOnChange: false);
        _player.CheckForCompletedMotions();
    }

    /// <summary>get_state_velocity.</summary>
    [Benchmark]
    public Vector3 StateVelocity() => _mi.StateVelocity;

    /// <summary>One 30 Hz world tick of the running, turning player.</summary>
    [Benchmark]
    public void RunningPlayerTick() => _world.Tick(_now += 1.0 / 30.0);
}
