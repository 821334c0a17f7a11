using System;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// The retail motion table path's cost (<see cref="AnimatedPartArray"/>: MotionTableManager, CMotionTable and CSequence):
/// one 30 Hz world tick of a walking player whose walk cycle is a 17-part, 30-frame animation at 30 frames per second with
/// root motion frames (every tick crosses a frame: part frames, root motion, the motion data's velocity), and one tick of
/// 100 such creatures walking in circles, sharing one motion table and one animation library. Every row must allocate 0 B.
/// </summary>
[MemoryDiagnoser]
public class AnimatedPartArrayBenchmarks
{
    private const uint NonCombat = 0x8000003Du, Ready = 0x41000003u, Walk = 0x45000005u, Turn = 0x6500000Du;
    private const uint ReadyClip = 0x03000001u, WalkClip = 0x03000002u, StartClip = 0x03000003u;
    private const int Parts = 17;

    private PhysicsWorld _playerWorld = null!;
    private PhysicsWorld _crowdWorld = null!;
    private double _playerNow;
    private double _crowdNow;

    private static MotionTable Table() => MotionTable.UnPack(new MotionTableBytes { DefaultStyle = NonCombat }
        .StyleDefault(NonCombat, Ready)
        .Cycle(NonCombat, Ready, MotionDataSpec.One(ReadyClip, 0, -1, 30f))
        .Cycle(NonCombat, Walk, MotionDataSpec.One(WalkClip, 0, -1, 30f, velocity: new Vector3(0f, 3.12f, 0f)))
        .Modifier(0, Turn, new MotionDataSpec(Array.Empty<(uint, int, int, float)>(), Omega: new Vector3(0f, 0f, -1.5f)))
        .Link(NonCombat, Ready, Walk, MotionDataSpec.One(StartClip, 0, -1, 30f))
        .ToArray());

    private static AnimationLibrary Clips()
    {
        var lib = new AnimationLibrary();
        foreach ((uint id, int frames) in new[] { (ReadyClip, 30), (WalkClip, 30), (StartClip, 10) })
        {
            var b = new AnimationBytes(id, Parts);
            for (int i = 0; i < frames; i++)
            {
                b.Frame(new Vector3(0f, 0.001f, 0f), Quaternion.Identity);
            }

            lib.Add(AnimClip.UnPack(b.ToArray()));
        }

        return lib;
    }

    private static PhysicsWorld FlatWorld()
    {
        var terrain = SyntheticTerrain.Metres();
        SyntheticTerrain.AddBlock(terrain, 0x80, 0x80, (_, _) => 20);
        return new PhysicsWorld(0.0) { Sweep = new RetailSweep(terrain) };
    }

    private static PhysicsObj Walker(PhysicsWorld world, uint id, Vector3 at, MotionTable table, AnimationLibrary clips, bool turn)
    {
        PhysicsObj obj = world.CreateObject(id);
        obj.Weenie = new PlayerWeenie { RunSkill = 200 };
        var setup = new SetupPhysics(new[] { new Sphere(new Vector3(0f, 0f, 0.48f), 0.48f) }, ReadOnlySpan<CylSphere>.Empty,
            0.48f, 1.835f, 0.6f, 1.5f);
        obj.PartArray = new AnimatedPartArray(setup, Parts, table, clips);
        obj.EnterWorld(new Position(SyntheticTerrain.CellId(0x80, 0x80, (int)(at.X / 24f), (int)(at.Y / 24f)), at));
        MovementManager mm = MovementManager.Of(obj);
        mm.DoMotion(MotionCommand.WalkForward, new MovementParameters());
        if (turn)
        {
            mm.DoMotion(MotionCommand.TurnRight, new MovementParameters());
        }

        return obj;
    }

    /// <summary>Builds the walking player's world and the crowd's, and plays both past their start links.</summary>
    [GlobalSetup]
    public void Setup()
    {
        MotionTable table = Table();
        AnimationLibrary clips = Clips();
        _playerWorld = FlatWorld();
        _playerWorld.Player = Walker(_playerWorld, 1, new Vector3(96f, 20f, 20f), table, clips, turn: false);
        _crowdWorld = FlatWorld();
        for (int i = 0; i < 100; i++)
        {
            var at = new Vector3(20f + 15f * (i % 10), 20f + 15f * (i / 10), 20f);
            Walker(_crowdWorld, (uint)(i + 1), at, table, clips, turn: true);
        }

        for (int i = 0; i < 60; i++)
        {
            _playerWorld.Tick(_playerNow += 1.0 / 30.0);
            _crowdWorld.Tick(_crowdNow += 1.0 / 30.0);
        }
    }

    /// <summary>One 30 Hz tick of the walking, animated player (must be 0 B).</summary>
    [Benchmark]
    public void WalkingAnimatedPlayerTick() => _playerWorld.Tick(_playerNow += 1.0 / 30.0);

    /// <summary>One 30 Hz tick of 100 animated creatures walking in circles.</summary>
    [Benchmark]
    public void AnimatedCrowdOf100Tick() => _crowdWorld.Tick(_crowdNow += 1.0 / 30.0);
}
