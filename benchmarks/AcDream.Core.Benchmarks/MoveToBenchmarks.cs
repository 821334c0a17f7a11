using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using BenchmarkDotNet.Attributes;
using AcDream.Core.Physics.Motion.MoveTo;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// One move-to step: <c>MoveToManager::UseTime</c> running <c>HandleMoveToPosition</c> (heading check, distance between
/// cylinders, progress check, fail distance, the target's report quantum) for a player chasing a target, and one world tick
/// of that chase (both bodies walking, the target's voyeur pass every 0.5 s). Every row must allocate 0 B.
/// </summary>
[MemoryDiagnoser]
public class MoveToBenchmarks
{
    private PhysicsWorld _world = null!;
    private PhysicsObj _player = null!;
    private PhysicsObj _target = null!;
    private MoveToManager _moveTo = null!;
    private Position _playerStart;
    private Position _targetStart;
    private MovementParameters _params;
    private int _ticks;

    /// <summary>Flat ground; the player (walk only, 3.12 m/s) chases a target walking north at the same speed, 20 m ahead.</summary>
    [GlobalSetup]
    public void Setup()
    {
        var terrain = SyntheticTerrain.Metres();
        SyntheticTerrain.AddBlock(terrain, 0x80, 0x80, (_, _) => 20);
        _world = new PhysicsWorld(0.0) { Sweep = new RetailSweep(terrain) };
        uint cell = SyntheticTerrain.CellId(0x80, 0x80, 4, 4);
        _playerStart = new Position(cell, new Vector3(100f, 10f, 20f));
        _targetStart = new Position(cell, new Vector3(100f, 30f, 20f));
        _player = Creature(1, new PlayerWeenie { RunSkill = 200 }, _playerStart);
        _world.Player = _player;
        _target = Creature(2, RemoteCreatureWeenie.Creature, _targetStart);
        MovementManager.Of(_target).DoMotion(MotionCommand.WalkForward, new MovementParameters { HoldKeyToApply = HoldKey.None });
        _params = new MovementParameters();
        _params.Flags &= ~MovementParameterFlags.CanRun;
        _player.MoveToObject(2, _params);
        _moveTo = MovementManager.Of(_player).MoveToManager!;
        for (int i = 0; i < 60; i++)
        {
            Tick();
        }
    }

    private PhysicsObj Creature(uint id, IMotionWeenie weenie, in Position at)
    {
        PhysicsObj obj = _world.CreateObject(id);
        obj.Weenie = weenie;
        var parts = Walkers.OneSphere();
        parts.MotionPlayer = new SpeedOnlyMotionPlayer();
        parts.Radius = 0.5f;
        obj.PartArray = parts;
        obj.EnterWorld(at);
        return obj;
    }

    /// <summary>One <c>MoveToManager::UseTime</c> (the move step's HandleMoveToPosition), the body not moved.</summary>
    [Benchmark]
    public void MoveToUseTime() => _moveTo.UseTime();

    /// <summary>One world tick of the chase (1/30 s); every 900 ticks (before the bodies leave the landblock) both go back and
    /// the move-to restarts.</summary>
    [Benchmark]
    public void ChaseTick() => Tick();

    private void Tick()
    {
        if (++_ticks % 900 == 0)
        {
            _target.SetPositionSimple(_targetStart, true);
            _player.SetPositionSimple(_playerStart, true);
            _player.MoveToObject(2, _params);
        }

        _world.Tick(_world.CurrentTime + 1.0 / 30.0);
    }
}
