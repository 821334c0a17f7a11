using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support.Shared;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// A synthetic full-detail world from retail entries (issue #35): flat landblocks (height index 20 of the one-metre table),
/// each with 100 static objects in its landblock info (40 tree Setups with one cylinder, 30 rock GfxObjs with a physics BSP
/// box, 30 grass Setups without shapes) and 300 scenery objects (the same three models, scale 0.8–1.2), on jittered grids
/// that leave the centre block's four middle cells (72..120 m) clear for the walking player.
/// </summary>
internal static class WorldBench
{
    public const uint Tree = 0x02000010, Grass = 0x02000011, Rock = 0x01000012, Trunk = 0x01000011;

    public static readonly uint[] Blocks = MakeBlocks();

    private static uint[] MakeBlocks()
    {
        var ids = new List<uint>();
        for (int bx = 0x7F; bx <= 0x81; bx++)
        {
            for (int by = 0x7F; by <= 0x81; by++)
            {
                ids.Add(((uint)bx << 24) | ((uint)by << 16) | 0xFFFFu);
            }
        }

        return ids.ToArray();
    }

    /// <summary>The entries: every block (with or without its info and objects) and the three models.</summary>
    public static Dictionary<uint, byte[]> Entries(bool populated) => Entries(populated, Blocks);

    /// <summary>The entries of <paramref name="blocks"/> and the three models.</summary>
    public static Dictionary<uint, byte[]> Entries(bool populated, uint[] blocks)
    {
        var e = new Dictionary<uint, byte[]>();
        var height = new byte[81];
        Array.Fill(height, (byte)20);
        var rnd = new Random(35);
        foreach (uint block in blocks)
        {
            e[block] = WorldDataBytes.LandBlock(block, populated, new ushort[81], height);
            if (populated)
            {
                var objects = new (uint, Frame)[100];
                int n = 0;
                foreach (Vector2 p in Grid(rnd, 10, block))
                {
                    uint id = n < 40 ? Tree : n < 70 ? Rock : Grass;
                    objects[n++] = (id, new Frame(new Vector3(p, 20f), Quaternion.Identity));
                    if (n == objects.Length)
                    {
                        break;
                    }
                }

                e[(block & 0xFFFF0000u) | 0xFFFEu] = WorldDataBytes.LandBlockInfo((block & 0xFFFF0000u) | 0xFFFEu, objects[..n], []);
            }
        }

        e[Trunk] = WorldDataBytes.DrawingGfxObj(Trunk, new Vector3(-1f, -1f, 0f), new Vector3(1f, 1f, 10f));
        e[Tree] = WorldDataBytes.CylinderSetup(Tree, Trunk, 0.8f, 12f, -1f);
        e[Grass] = WorldEntries.Setup(new SetupDef(Grass, [Trunk]) { Placements = [(0x65, [Frame.Identity])] });
        e[Rock] = WorldDataBytes.BoxGfxObj(Rock, new Vector3(-0.8f, -0.8f, -0.2f), new Vector3(0.8f, 0.8f, 0.6f));
        return e;
    }

    /// <summary>300 scenery placements of a block (the scenery seam's input).</summary>
    public static IReadOnlyList<SceneryItem> Scenery(uint block)
    {
        var rnd = new Random((int)(block >> 16));
        var items = new List<SceneryItem>(300);
        int n = 0;
        foreach (Vector2 p in Grid(rnd, 18, block))
        {
            uint id = (n % 3) switch { 0 => Tree, 1 => Grass, _ => Rock };
            uint cell = LandDefs.LCoordToGid((int)(block >> 24) * 8 + (int)(p.X / 24f), (int)((block >> 16) & 0xFF) * 8 + (int)(p.Y / 24f));
            items.Add(new SceneryItem(id, cell, new Frame(new Vector3(p, 20f), Quaternion.Identity), 0.8f + 0.4f * (float)rnd.NextDouble()));
            if (++n == 300)
            {
                break;
            }
        }

        return items;
    }

    // A jittered k × k grid over the block, 4 m from its edges, skipping the centre block's four middle cells (72..120 m).
    private static IEnumerable<Vector2> Grid(Random rnd, int k, uint block)
    {
        bool centre = block == 0x8080FFFFu;
        float step = 184f / k;
        for (int i = 0; i < k; i++)
        {
            for (int j = 0; j < k; j++)
            {
                var p = new Vector2(4f + step * (i + (float)rnd.NextDouble()), 4f + step * (j + (float)rnd.NextDouble()));
                p = Vector2.Min(p, new Vector2(188f));
                if (centre && p.X > 72f && p.X < 120f && p.Y > 72f && p.Y < 120f)
                {
                    continue;
                }

                yield return p;
            }
        }
    }

    public static PhysicsWorld World()
    {
        var world = new PhysicsWorld(0.0);
        world.Sweep = new RetailSweep(new WorldCells(SyntheticTerrain.Metres()));
        return world;
    }

    public static WorldLoader Loader(PhysicsWorld world, Dictionary<uint, byte[]> entries, bool scenery) =>
        new(world, new Source(entries)) { ScenerySource = scenery ? (b, _) => Scenery(b) : null };

    public sealed class Source(Dictionary<uint, byte[]> entries) : IRetailDataSource
    {
        public bool TryGetEntry(uint id, out ReadOnlyMemory<byte> bytes)
        {
            bool found = entries.TryGetValue(id, out byte[]? b);
            bytes = b;
            return found;
        }
    }
}

/// <summary>
/// Building one full-detail landblock (its 100 statics and 300 scenery objects) from entries through <see cref="WorldLoader"/>:
/// cold (a new world and loader: every entry unpacked, every model built) and warm (the block unloaded and loaded again by
/// one loader: models cached, objects made and shadowed again).
/// </summary>
[MemoryDiagnoser]
public class WorldBuildBenchmarks
{
    private Dictionary<uint, byte[]> _entries = null!;
    private WorldLoader _warm = null!;

    [GlobalSetup]
    public void Setup()
    {
        _entries = WorldBench.Entries(populated: true);
        _warm = WorldBench.Loader(WorldBench.World(), _entries, scenery: true);
        _warm.Load(0x8080FFFFu);
    }

    /// <summary>A new world, loader and factory, then the block.</summary>
    [Benchmark]
    public int BlockCold() => WorldBench.Loader(WorldBench.World(), _entries, scenery: true).Load(0x8080FFFFu)[0].Objects.Count;

    /// <summary>The block unloaded and loaded again by a loader whose models are cached.</summary>
    [Benchmark]
    public int BlockWarm()
    {
        _warm.Unload(0x8080FFFFu);
        return _warm.Load(0x8080FFFFu)[0].Objects.Count;
    }
}

/// <summary>
/// The per-tick cost of a 3 × 3 world with one walking player (a circle of 10 m at 2 m/s in the centre block's clear
/// middle): terrain only, against the same world with every block's 100 statics and 300 scenery objects (3,600 static
/// objects). Static objects are never visited (retail does not update them; here they sleep from their first visit), so
/// the two rows should agree within noise, at 0 B per tick.
/// </summary>
[MemoryDiagnoser]
public class StaticWorldTickBenchmarks
{
    private const int Ticks = 10;
    private const double Dt = 0.034;
    private PhysicsWorld _world = null!;
    private double _now;

    /// <summary>True: the world's statics and scenery are built; false: terrain only.</summary>
    [Params(false, true)]
    public bool Populated { get; set; }

    [GlobalSetup]
    public void Setup()
    {
        _world = WorldBench.World();
        WorldBench.Loader(_world, WorldBench.Entries(Populated), scenery: Populated).Load(WorldBench.Blocks);
        var parts = Walkers.OneSphere(0.48f, 0.6f, 1.5f);
        PhysicsObj player = Walkers.Create(_world, 0x50000001,
            new Position(LandDefs.LCoordToGid(0x80 * 8 + 4, 0x80 * 8 + 4), new Frame(new Vector3(96f, 86f, 20f), Quaternion.Identity)), parts);
        parts.SequenceVelocity = new Vector3(0f, 2f, 0f);
        parts.SequenceOmega = new Vector3(0f, 0f, 0.2f);
        _world.Player = player;
        _now = 0.0;
        for (int i = 0; i < 100; i++)
        {
            _now += Dt;
            _world.Tick(_now);
        }
    }

    /// <summary>One world tick.</summary>
    [Benchmark(OperationsPerInvoke = Ticks)]
    public bool Tick()
    {
        bool ticked = false;
        for (int i = 0; i < Ticks; i++)
        {
            _now += Dt;
            ticked = _world.Tick(_now);
        }

        return ticked;
    }
}
