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
/// The per-tick cost between crossings: <see cref="StaticWorldTickBenchmarks"/>'s walker in the same populated 3 × 3, built by
/// the landscape, which is asked every tick (the cell does not change: nothing to do). Against
/// <see cref="StaticWorldTickBenchmarks"/> with <c>Populated = true</c> the two rows should agree within noise, at 0 B.
/// </summary>
[MemoryDiagnoser]
public class LandscapeTickBenchmarks
{
    private const int Ticks = 10;
    private const double Dt = 0.034;
    private PhysicsWorld _world = null!;
    private Landscape _landscape = null!;
    private PhysicsObj _player = null!;
    private double _now;

    [GlobalSetup]
    public void Setup()
    {
        _world = WorldBench.World();
        _landscape = new Landscape(WorldBench.Loader(_world, WorldBench.Entries(true), scenery: true));
        var start = new Position(LandDefs.LCoordToGid(0x80 * 8 + 4, 0x80 * 8 + 4), new Frame(new Vector3(96f, 86f, 20f), Quaternion.Identity));
        _landscape.ChangePosition(start, blocking: true);
        var parts = Walkers.OneSphere(0.48f, 0.6f, 1.5f);
        _player = Walkers.Create(_world, 0x50000001, start, parts);
        parts.SequenceVelocity = new Vector3(0f, 2f, 0f);
        parts.SequenceOmega = new Vector3(0f, 0f, 0.2f);
        _world.Player = _player;
        _now = 0.0;
        for (int i = 0; i < 100; i++)
        {
            _now += Dt;
            _landscape.ChangePosition(_player.Position);
            _world.Tick(_now);
        }
    }

    /// <summary>The landscape asked with the player's position, then one world tick.</summary>
    [Benchmark(OperationsPerInvoke = Ticks)]
    public bool Tick()
    {
        bool ticked = false;
        for (int i = 0; i < Ticks; i++)
        {
            _now += Dt;
            _landscape.ChangePosition(_player.Position);
            ticked = _world.Tick(_now);
        }

        return ticked;
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
