using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Cost of one retail sweep (<c>CPhysicsObj::transition</c>) of a walker (one sphere, r = 0.5 m, step heights 0.6 m) over
/// synthetic terrain: flat ground, a walkable slope (rise 27 m per 24 m cell), into a hillside (rise 40 m per cell, a wall to
/// walkers) and across a landblock edge. "Call" sweeps a 0.2 m move (one step, a 4 m/s walker at 20 Hz); "Step" sweeps a
/// 10 m move (ceil(10 / 0.5) = 20 steps) and reports the mean per step. The sweep does not change the object, so every
/// invoke repeats the same sweep.
/// </summary>
[MemoryDiagnoser]
public class SweepBenchmarks
{
    private const int LongSteps = 20;
    private RetailSweep _sweep = null!;
    private PhysicsObj _flat = null!, _slope = null!, _hill = null!, _edge = null!;
    private Position _flatTo, _flatFar, _slopeTo, _slopeFar, _hillTo, _hillFar, _edgeTo, _edgeFar;

    /// <summary>Builds the four scenes in one terrain world.</summary>
    [GlobalSetup]
    public void Setup()
    {
        TerrainWorld terrain = SyntheticTerrain.Metres();
        SyntheticTerrain.AddBlock(terrain, 0x40, 0x40, (_, _) => 20);
        SyntheticTerrain.AddBlock(terrain, 0x41, 0x40, (_, _) => 20);
        SyntheticTerrain.AddBlock(terrain, 0x50, 0x50, (vx, _) => 10 + 27 * vx);
        SyntheticTerrain.AddBlock(terrain, 0x60, 0x60, (vx, _) => vx <= 4 ? 10 : 10 + 40 * (vx - 4));
        var world = new PhysicsWorld(0.0);
        _sweep = new RetailSweep(terrain);
        world.Sweep = _sweep;

        _flat = Walker(world, 1, Pos(0x40, 0x40, 100f, 100f, 20f));
        _flatTo = Moved(_flat.Position, 0.2f);
        _flatFar = Moved(_flat.Position, 10f);
        _slope = Walker(world, 2, Pos(0x50, 0x50, 60f, 100f, (float)(10 + 27.0 / 24.0 * 60.0)));
        _slopeTo = Moved(_slope.Position, 0.2f);
        _slopeFar = Moved(_slope.Position, 10f);
        _hill = Walker(world, 3, Pos(0x60, 0x60, 95.5f, 100f, 10f));
        _hillTo = Moved(_hill.Position, 0.2f);
        _hillFar = Moved(_hill.Position, 10f);
        _edge = Walker(world, 4, Pos(0x40, 0x40, 191.9f, 100f, 20f));
        _edgeTo = Moved(_edge.Position, 0.2f);
        _edgeFar = Moved(_edge.Position, 10f);
    }

    /// <summary>One 0.2 m sweep on flat ground.</summary>
    [Benchmark]
    public object? FlatCall() => _sweep.RunTransition(_flat, _flat.Position, _flatTo, false);

    /// <summary>A 10 m sweep on flat ground; mean per step.</summary>
    [Benchmark(OperationsPerInvoke = LongSteps)]
    public object? FlatStep() => _sweep.RunTransition(_flat, _flat.Position, _flatFar, false);

    /// <summary>One 0.2 m sweep up a walkable slope.</summary>
    [Benchmark]
    public object? SlopeCall() => _sweep.RunTransition(_slope, _slope.Position, _slopeTo, false);

    /// <summary>A 10 m sweep up a walkable slope; mean per step.</summary>
    [Benchmark(OperationsPerInvoke = LongSteps)]
    public object? SlopeStep() => _sweep.RunTransition(_slope, _slope.Position, _slopeFar, false);

    /// <summary>One 0.2 m sweep into a too-steep hillside (cliff slide, rejected step).</summary>
    [Benchmark]
    public object? HillsideCall() => _sweep.RunTransition(_hill, _hill.Position, _hillTo, false);

    /// <summary>A 10 m sweep into the hillside; mean per step (the sweep stops at the first blocked step).</summary>
    [Benchmark(OperationsPerInvoke = LongSteps)]
    public object? HillsideStep() => _sweep.RunTransition(_hill, _hill.Position, _hillFar, false);

    /// <summary>One 0.2 m sweep across a landblock edge (cell change, block offset).</summary>
    [Benchmark]
    public object? EdgeCall() => _sweep.RunTransition(_edge, _edge.Position, _edgeTo, false);

    /// <summary>A 10 m sweep across a landblock edge; mean per step.</summary>
    [Benchmark(OperationsPerInvoke = LongSteps)]
    public object? EdgeStep() => _sweep.RunTransition(_edge, _edge.Position, _edgeFar, false);

    private static Position Pos(int bx, int by, float x, float y, float z) =>
        new(LandDefs.LCoordToGid(bx * 8 + (int)(x / 24f), by * 8 + (int)(y / 24f)), Frame.FromHeading(new Vector3(x, y, z), 90f));

    private static Position Moved(in Position p, float dx)
    {
        Position q = p;
        q.Frame.Origin = new Vector3(p.Frame.Origin.X + dx, p.Frame.Origin.Y, p.Frame.Origin.Z);
        return q;
    }

    private static PhysicsObj Walker(PhysicsWorld world, uint id, in Position p) => Walkers.Create(world, id, p, Walkers.OneSphere());
}
