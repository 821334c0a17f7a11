using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support.Shared;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// The landscape's streaming (issue #36) over <see cref="WorldBench"/>'s blocks, widened to five columns (0x7E–0x82 by
/// 0x7F–0x81, each with 100 statics and 300 scenery objects): the player's cell crossing from 0x8080 into 0x8180 and back.
/// Each crossing builds the three blocks entering the 3 × 3 (their 1,200 objects made and shadowed; models cached after
/// the first) and releases the three leaving it. It is the worst frame of a run across the world: the library builds a
/// block in one call (there is no incremental loading).
/// </summary>
[MemoryDiagnoser]
public class LandscapeCrossingBenchmarks
{
    private Landscape _landscape = null!;
    private Position _west, _east;

    /// <summary>The grid's radius: 1 (the 3 × 3 only) or retail's default 5 (11 × 11, of which the data holds 15 blocks).</summary>
    [Params(1, 5)]
    public int Radius { get; set; }

    /// <summary>Five columns of three blocks.</summary>
    public static uint[] Blocks()
    {
        var ids = new List<uint>();
        for (int x = 0x7E; x <= 0x82; x++)
        {
            for (int y = 0x7F; y <= 0x81; y++)
            {
                ids.Add(((uint)x << 24) | ((uint)y << 16) | 0xFFFFu);
            }
        }

        return ids.ToArray();
    }

    /// <summary>A landscape over the five columns, with scenery through the loader's scenery seam.</summary>
    public static Landscape Make(PhysicsWorld world, int radius)
    {
        var landscape = new Landscape(WorldBench.Loader(world, WorldBench.Entries(true, Blocks()), scenery: true));
        landscape.SetMidRadius(radius);
        return landscape;
    }

    [GlobalSetup]
    public void Setup()
    {
        _landscape = Make(WorldBench.World(), Radius);
        _west = new Position(LandDefs.LCoordToGid(0x80 * 8 + 7, 0x80 * 8 + 4), new Frame(new Vector3(190f, 96f, 20f), Quaternion.Identity));
        _east = new Position(LandDefs.LCoordToGid(0x81 * 8, 0x80 * 8 + 4), new Frame(new Vector3(2f, 96f, 20f), Quaternion.Identity));
        _landscape.ChangePosition(_west, blocking: true);
        _landscape.ChangePosition(_east);
        _landscape.ChangePosition(_west);
    }

    /// <summary>One crossing (east, then back west: two per invocation).</summary>
    [Benchmark(OperationsPerInvoke = 2)]
    public int Crossing()
    {
        int built = _landscape.ChangePosition(_east).Built.Count;
        return built + _landscape.ChangePosition(_west).Built.Count;
    }
}

/// <summary>
/// The per-tick cost between crossings: a walker circling (1 m/s, 0.2 rad/s: radius 5 m) inside one cell of the populated
/// 3 × 3 (<see cref="WorldBench"/>: 3,590 statics and scenery objects), with the world built by the loader alone
/// (<c>Landscape = false</c>) or by the landscape, asked every tick with the player's position (<c>true</c>: the cell does
/// not change, so it has nothing to do). The two rows should agree within noise, at 0 B.
/// </summary>
[MemoryDiagnoser]
public class LandscapeTickBenchmarks
{
    private const int Ticks = 10;
    private const double Dt = 0.034;
    private PhysicsWorld _world = null!;
    private Landscape? _landscape;
    private PhysicsObj _player = null!;
    private double _now;

    /// <summary>True: the landscape built the world and is asked every tick; false: the loader built it.</summary>
    [Params(false, true)]
    public bool Landscape { get; set; }

    [GlobalSetup]
    public void Setup()
    {
        _world = WorldBench.World();
        WorldLoader loader = WorldBench.Loader(_world, WorldBench.Entries(true), scenery: true);
        // Cell (4, 3) of the centre block, x 96..120, y 72..96: the circle's centre (108, 84), radius 5 m.
        var start = new Position(LandDefs.LCoordToGid(0x80 * 8 + 4, 0x80 * 8 + 3), new Frame(new Vector3(113f, 84f, 20f), Quaternion.Identity));
        if (Landscape)
        {
            _landscape = new Landscape(loader);
            _landscape.ChangePosition(start, blocking: true);
        }
        else
        {
            loader.Load(WorldBench.Blocks);
        }

        var parts = Walkers.OneSphere(0.48f, 0.6f, 1.5f);
        _player = Walkers.Create(_world, 0x50000001, start, parts);
        parts.SequenceVelocity = new Vector3(0f, 1f, 0f);
        parts.SequenceOmega = new Vector3(0f, 0f, 0.2f);
        _world.Player = _player;
        _now = 0.0;
        for (int i = 0; i < 100; i++)
        {
            Step();
        }

        if (_player.CellId != start.ObjCellId)
        {
            throw new InvalidOperationException($"the walker left its cell: 0x{_player.CellId:X8}");
        }
    }

    /// <summary>The landscape asked with the player's position (when it built the world), then one world tick.</summary>
    [Benchmark(OperationsPerInvoke = Ticks)]
    public bool Tick()
    {
        bool ticked = false;
        for (int i = 0; i < Ticks; i++)
        {
            ticked = Step();
        }

        return ticked;
    }

    private bool Step()
    {
        _now += Dt;
        _landscape?.ChangePosition(_player.Position);
        return _world.Tick(_now);
    }
}

/// <summary>
/// A cell change inside the centre block of the populated 3 × 3 (no shift of the grid): retail's second pass runs again over
/// the nine blocks (<c>init_static_objs</c>' later call: <c>adjust_scene_obj_height</c> over the scenery, and the statics
/// not shadowed everywhere re-listed), as each ChangePosition to a new cell does. One change per operation, back and forth
/// between two neighbouring cells.
/// </summary>
[MemoryDiagnoser]
public class LandscapeCellChangeBenchmarks
{
    private Landscape _landscape = null!;
    private Position _a, _b;

    /// <summary>The grid's radius: 1 (the 3 × 3, all held) or 5 (11 × 11: the empty slots past the data are tried again at
    /// each change, as retail's <c>update_loadpoint</c> does at the world's edge).</summary>
    [Params(1, 5)]
    public int Radius { get; set; }

    [GlobalSetup]
    public void Setup()
    {
        _landscape = new Landscape(WorldBench.Loader(WorldBench.World(), WorldBench.Entries(true), scenery: true));
        _landscape.SetMidRadius(Radius);
        _a = new Position(LandDefs.LCoordToGid(0x80 * 8 + 4, 0x80 * 8 + 3), new Frame(new Vector3(110f, 84f, 20f), Quaternion.Identity));
        _b = new Position(LandDefs.LCoordToGid(0x80 * 8 + 4, 0x80 * 8 + 4), new Frame(new Vector3(110f, 100f, 20f), Quaternion.Identity));
        _landscape.ChangePosition(_a, blocking: true);
        _landscape.ChangePosition(_b);
    }

    /// <summary>One cell change (two per invocation).</summary>
    [Benchmark(OperationsPerInvoke = 2)]
    public LandscapeStatus CellChange()
    {
        _landscape.ChangePosition(_a);
        return _landscape.ChangePosition(_b).Status;
    }
}

/// <summary><c>landscape-memory</c>: the managed memory a full 3 × 3 holds (<see cref="WorldBench"/>'s blocks with their
/// statics and scenery, built by the landscape), measured as the heap after a full collection before and after.</summary>
public static class LandscapeMemory
{
    /// <summary>Prints the figures; returns 0.</summary>
    public static int Run()
    {
        for (int radius = 1; radius <= 5; radius += 4)
        {
            PhysicsWorld world = WorldBench.World();
            Dictionary<uint, byte[]> entries = WorldBench.Entries(true, LandscapeCrossingBenchmarks.Blocks());
            long before = GC.GetTotalMemory(true);
            var landscape = new Landscape(WorldBench.Loader(world, entries, scenery: true));
            landscape.SetMidRadius(radius);
            LandscapeChange c = landscape.ChangePosition(
                new Position(LandDefs.LCoordToGid(0x80 * 8 + 4, 0x80 * 8 + 4), new Frame(new Vector3(96f, 86f, 20f), Quaternion.Identity)), blocking: true);
            long after = GC.GetTotalMemory(true);
            int objects = 0;
            foreach (WorldBlock b in c.Built)
            {
                objects += b.Objects.Count;
            }

            Console.WriteLine($"radius {radius}: {c.Built.Count} blocks at full detail, {objects} objects, {world.ObjectCount} in the world: {(after - before) / 1024.0 / 1024.0:F2} MiB held ({(after - before) / Math.Max(objects, 1)} B per object, the loader's model cache included)");
            GC.KeepAlive(landscape);
            GC.KeepAlive(entries);
        }

        return 0;
    }
}
