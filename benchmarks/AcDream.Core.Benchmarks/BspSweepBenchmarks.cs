using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Cost of one retail sweep (<c>CPhysicsObj::transition</c>) of a walker (one sphere, r = 0.5 m) through a building
/// whose physics BSP has 1,000+ polygons (a 15 × 15 grid of pillars, a long wall and a five-step staircase: 1,386
/// polygons), on flat terrain. Each call sweeps a 0.2 m move (one step, 4 m/s at 20 Hz): sliding along the wall at 10
/// degrees, stepping up the first stair, and walking between the pillars (BSP traversal with no hit). The sweep does not
/// change the object, so every invoke repeats the same sweep.
/// </summary>
[MemoryDiagnoser]
public class BspSweepBenchmarks
{
    private RetailSweep _sweep = null!;
    private PhysicsObj _wall = null!, _stair = null!, _open = null!;
    private Position _wallTo, _stairTo, _openTo;

    /// <summary>Number of polygons in the building's BSP (set up in <see cref="Setup"/>).</summary>
    public int PolygonCount { get; private set; }

    /// <summary>Builds the building and the three walkers.</summary>
    [GlobalSetup]
    public void Setup()
    {
        TerrainWorld terrain = SyntheticTerrain.Metres();
        SyntheticTerrain.AddBlock(terrain, 0x40, 0x40, (_, _) => 20);
        var cells = new WorldCells(terrain);

        // Building at (100, 100, 20): pillars 0.5 x 0.5 x 3 every 2 m over x, y 10..38; a wall x 0..40, y 0..0.5; stairs
        // (1 m deep, rise 0.55) x 45..50, y 10..13.
        var polys = new List<Polygon>();
        for (int i = 0; i < 15; i++)
        {
            for (int j = 0; j < 15; j++)
            {
                BoxShapes.AddBox(polys, new Vector3(10f + 2f * i, 10f + 2f * j, 0f), new Vector3(10.5f + 2f * i, 10.5f + 2f * j, 3f));
            }
        }

        BoxShapes.AddBox(polys, new Vector3(0f, 0f, 0f), new Vector3(40f, 0.5f, 3f));
        for (int i = 0; i < 5; i++)
        {
            BoxShapes.AddBox(polys, new Vector3(45f + i, 10f, 0f), new Vector3(46f + i, 13f, 0.55f * (i + 1)));
        }

        PolygonCount = polys.Count;
        var origin = new Vector3(100f, 100f, 20f);
        BspTree bsp = BspBuilder.Build(polys.ToArray());
        var building = new BuildingObj(new PhysicsPart(new GfxObjPhysics(bsp), Pos(origin.X, origin.Y, origin.Z, 0f), Vector3.One), Array.Empty<BldPortal>());
        for (int cx = 3; cx <= 6; cx++)
        {
            for (int cy = 3; cy <= 6; cy++)
            {
                terrain.GetLandCell(LandDefs.LCoordToGid(0x40 * 8 + cx, 0x40 * 8 + cy))!.Building = building;
            }
        }

        var world = new PhysicsWorld(0.0);
        _sweep = new RetailSweep(cells);
        world.Sweep = _sweep;
        PhysicsState noEdgeSlide = (PhysicsState)PhysicsGlobals.DefaultState & ~PhysicsState.EdgeSlide;

        // Against the wall's south face (y = 100), heading 80: centre 0.5 south of it.
        _wall = Walker(world, 1, Pos(120f, 99.5f, 20f, 80f), 0.6f, null);
        _wallTo = Moved(_wall.Position, 80f, 0.2f);
        // In front of the first riser (x = 145), facing east; step-up 0.4 (reach 0.6 > 0.55).
        _stair = Walker(world, 2, Pos(144.45f, 111.5f, 20f, 90f), 0.4f, noEdgeSlide);
        _stairTo = Moved(_stair.Position, 90f, 0.2f);
        // Between pillar columns (x 111.25), walking north.
        _open = Walker(world, 3, Pos(111.25f, 111.25f, 20f, 0f), 0.6f, null);
        _openTo = Moved(_open.Position, 0f, 0.2f);
    }

    /// <summary>One 0.2 m sweep sliding along the wall at 10 degrees.</summary>
    [Benchmark]
    public object? AlongWall() => _sweep.RunTransition(_wall, _wall.Position, _wallTo, false);

    /// <summary>One 0.2 m sweep into the first stair riser (step up onto the tread).</summary>
    [Benchmark]
    public object? UpStair() => _sweep.RunTransition(_stair, _stair.Position, _stairTo, false);

    /// <summary>One 0.2 m sweep between the pillars (no contact with the building).</summary>
    [Benchmark]
    public object? BetweenPillars() => _sweep.RunTransition(_open, _open.Position, _openTo, false);

    private static Position Pos(float x, float y, float z, float heading) =>
        new(LandDefs.LCoordToGid(0x40 * 8 + (int)(x / 24f), 0x40 * 8 + (int)(y / 24f)), Frame.FromHeading(new Vector3(x, y, z), heading));

    private static Position Moved(in Position p, float headingDegrees, float distance)
    {
        double a = headingDegrees * Math.PI / 180.0;
        Position q = p;
        q.Frame.Origin = new Vector3(p.Frame.Origin.X + (float)(Math.Sin(a) * distance), p.Frame.Origin.Y + (float)(Math.Cos(a) * distance), p.Frame.Origin.Z);
        return q;
    }

    private static PhysicsObj Walker(PhysicsWorld world, uint id, in Position p, float stepUp, PhysicsState? state) =>
        Walkers.Create(world, id, p, Walkers.OneSphere(0.5f, stepUp, stepUp), state);
}
