using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Object collisions in a crowd: 100 creatures (one sphere, r = 0.5 m) standing in a 10 × 10 grid with 2 m spacing on flat
/// ground (x, y = 90 .. 108, so the crowd spans four 24 m cells and every cell the mover touches lists up to 100 shadows),
/// and a mover of the same shape. "LaneCall" sweeps a 0.2 m move along a lane between two rows (1 m from each row: every
/// shadow tested, none hit); "LaneStep" a 10 m move along the lane (20 steps, mean per step); "BlockedCall" a 0.2 m move
/// into a creature (the step collides); "CrowdTick" one world tick in which all 100 creatures and the mover walk.
/// </summary>
[MemoryDiagnoser]
public class ObjectCollisionBenchmarks
{
    private const int LongSteps = 20;
    private const int Ticks = 10;
    private const double Dt = 0.05;
    private RetailSweep _sweep = null!;
    private PhysicsWorld _world = null!;
    private PhysicsObj _mover = null!;
    private Position _laneTo, _laneFar, _blockedFrom, _blockedTo;
    private double _now;

    /// <summary>Builds the crowd.</summary>
    [GlobalSetup]
    public void Setup()
    {
        TerrainWorld terrain = SyntheticTerrain.Metres();
        SyntheticTerrain.AddBlock(terrain, 0x40, 0x40, (_, _) => 20);
        _world = new PhysicsWorld(0.0);
        _sweep = new RetailSweep(terrain);
        _world.Sweep = _sweep;
        var rnd = new Random(11);
        for (int i = 0; i < 10; i++)
        {
            for (int j = 0; j < 10; j++)
            {
                PhysicsObj c = Creature(_world, (uint)(10 + i * 10 + j), Pos(90f + 2f * i, 90f + 2f * j, (float)(rnd.NextDouble() * 360.0)));
                ((SimplePartArray)c.PartArray!).SequenceVelocity = new Vector3(0f, 1f, 0f);
                ((SimplePartArray)c.PartArray!).SequenceOmega = new Vector3(0f, 0f, 0.5f);
            }
        }

        // The mover in the lane y = 99 between the rows y = 98 and y = 100, heading east.
        _mover = Creature(_world, 1, Pos(88f, 99f, 90f));
        ((SimplePartArray)_mover.PartArray!).SequenceVelocity = new Vector3(0f, 1f, 0f);
        _laneTo = Moved(_mover.Position, 0.2f, 0f);
        _laneFar = Moved(_mover.Position, 10f, 0f);
        // Blocked: from (95, 99.1) towards the creature at (96, 100).
        _blockedFrom = Pos(95f, 99.1f, 90f);
        _blockedTo = Moved(_blockedFrom, 0.2f, 0.2f);
        _world.ObjectMaintenanceActive = false;
        _now = 0.0;
    }

    /// <summary>A 0.2 m sweep along the lane: every shadow of the mover's cells is tested, none is hit.</summary>
    [Benchmark]
    public object? LaneCall() => _sweep.RunTransition(_mover, _mover.Position, _laneTo, false);

    /// <summary>A 10 m sweep along the lane; mean per step.</summary>
    [Benchmark(OperationsPerInvoke = LongSteps)]
    public object? LaneStep() => _sweep.RunTransition(_mover, _mover.Position, _laneFar, false);

    /// <summary>A 0.2 m sweep into a creature: the step slides or collides.</summary>
    [Benchmark]
    public object? BlockedCall() => _sweep.RunTransition(_mover, _blockedFrom, _blockedTo, false);

    /// <summary>One world tick: 101 walkers, each sweeping against the crowd; mean per tick.</summary>
    [Benchmark(OperationsPerInvoke = Ticks)]
    public bool CrowdTick()
    {
        bool ticked = false;
        for (int i = 0; i < Ticks; i++)
        {
            _now += Dt;
            ticked |= _world.Tick(_now);
        }

        return ticked;
    }

    private static Position Pos(float x, float y, float heading) =>
        new(LandDefs.LCoordToGid(0x40 * 8 + (int)(x / 24f), 0x40 * 8 + (int)(y / 24f)), Frame.FromHeading(new Vector3(x, y, 20f), heading));

    private static Position Moved(in Position p, float dx, float dy)
    {
        Position q = p;
        q.Frame.Origin = new Vector3(p.Frame.Origin.X + dx, p.Frame.Origin.Y + dy, p.Frame.Origin.Z);
        return q;
    }

    private static PhysicsObj Creature(PhysicsWorld world, uint id, in Position p)
    {
        SimplePartArray parts = Walkers.OneSphere();
        parts.Height = 1f;
        return Walkers.Create(world, id, p, parts, weenie: WeenieTraits.Creature);
    }
}
