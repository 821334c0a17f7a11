using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support.Shared;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// <c>world-map</c>: the Holtburg 3 × 3 (0xA8B3–0xAAB5) on the real terrain (<c>../shared/data/ac-terrain</c>) with synthetic
/// scene tables — a region whose every terrain type grows trees, bushes, rocks and grass from the terrain words' scene
/// slots, and landblock infos with a few houses and statics — streamed by the <see cref="Landscape"/>, a walker driven north
/// across the centre block's northern edge, and the top-down picture of what collides (<see cref="TopDownMap"/>, drawn
/// through the debug view). Writes <c>artifacts/world-map/holtburg-3x3.svg</c>; <c>--update-docs</c>:
/// <c>docs/world-holtburg.svg</c>; <c>--out DIR</c> anywhere.
/// </summary>
internal static class HoltburgMap
{
    public const uint SouthWest = 0xA8B3FFFFu, Centre = 0xA9B4FFFFu;
    private const uint Trunk = 0x01000011, Rock = 0x01000012, House = 0x01000013, Hut = 0x01000014;
    private const uint Tree = 0x02000010, Grass = 0x02000011, Bush = 0x02000012;
    private const uint Grove = 0x12000010, Rocks = 0x12000020, Meadow = 0x12000021, Copse = 0x12000022;

    public static int Run(ReadOnlySpan<string> args)
    {
        string root = TerrainDataDir.RepoRoot() ?? Directory.GetCurrentDirectory();
        string path = Path.Combine(root, "artifacts", "world-map", "holtburg-3x3.svg");
        for (int i = 0; i < args.Length; i++)
        {
            if (args[i] == "--update-docs")
            {
                path = Path.Combine(root, "docs", "world-holtburg.svg");
            }
            else if (args[i] == "--out" && i + 1 < args.Length)
            {
                path = Path.Combine(Path.GetFullPath(args[++i]), "holtburg-3x3.svg");
            }
            else
            {
                Console.Error.WriteLine($"world-map: unknown argument '{args[i]}' (use --update-docs or --out DIR)");
                return 2;
            }
        }

        string? dir = TerrainDataDir.Find(out string reason);
        if (dir is null)
        {
            Console.Error.WriteLine($"world-map: the real terrain was not found ({reason})");
            return 1;
        }

        (LandHeightTable table, List<LandBlockEntry> blocks) = Holtburg.Read(dir);
        PhysicsWorld world = BuildWorld(table, blocks, out IReadOnlyList<WorldBlock> built);
        List<Position> path2 = WalkAcross(world);
        string svg = TopDownMap.Render(world, built, path2, SouthWest,
            "Holtburg 0xA8B3–0xAAB5: real terrain, synthetic scene tables");
        Directory.CreateDirectory(Path.GetDirectoryName(path)!);
        File.WriteAllText(path, svg);
        Console.WriteLine($"world-map: {path} ({built.Count} blocks, {world.ObjectCount} objects, walker from 0x{path2[0].ObjCellId:X8} to 0x{path2[^1].ObjCellId:X8})");
        return 0;
    }

    /// <summary>
    /// The nine blocks as the landscape streams them around the walker's start (<see cref="Landscape"/>, radius 1): a world over
    /// the real height table, a data source with the blocks' terrain, their infos, the region, the scenes and the models. The
    /// walk is drawn over the 3 × 3 as it was built (the walk itself does not move the landscape, so the picture keeps the
    /// whole 3 × 3).
    /// </summary>
    public static PhysicsWorld BuildWorld(LandHeightTable table, List<LandBlockEntry> blocks, out IReadOnlyList<WorldBlock> built)
    {
        TerrainWorld heights = Holtburg.World((table, blocks));
        var entries = new Dictionary<uint, byte[]>();
        for (int k = 0; k < blocks.Count; k++)
        {
            LandBlockEntry b = blocks[k];
            entries[b.Id] = WorldDataBytes.LandBlock(b.Id, true, WithSceneSlots(b.Id, b.Terrain), b.Height);
            entries[(b.Id & 0xFFFF0000u) | 0xFFFEu] = Info(b.Id, heights);
        }

        entries[WorldLoader.DerethRegionId] = Region(table);
        AddScenesAndModels(entries);
        var world = new PhysicsWorld(0.0);
        world.Sweep = new RetailSweep(new WorldCells(new TerrainWorld(table)));
        // The landscape (retail's LScape) streams the 3 x 3 around the walker's start; a grid of radius 1 holds just those.
        var landscape = new Landscape(new WorldLoader(world, new WorldBench.Source(entries)));
        landscape.SetMidRadius(1);
        uint startCell = LandDefs.LCoordToGid(0xA9 * 8 + 1, 0xB4 * 8 + 6);
        built = landscape.ChangePosition(new Position(startCell, new Frame(new Vector3(40f, 150f, 0f), Quaternion.Identity)), blocking: true).Built;
        return world;
    }

    // The terrain fixtures carry each vertex's height, type and road but no scene slot (bits 11-15): the synthetic tables
    // give every vertex one of the slots 0-3 from a fixed mix of its global coordinates (0 grows nothing).
    private static ushort[] WithSceneSlots(uint block, ReadOnlySpan<ushort> terrain)
    {
        var words = terrain.ToArray();
        uint bx = (block >> 24) * 8, by = ((block >> 16) & 0xFF) * 8;
        for (uint i = 0; i < 9; i++)
        {
            for (uint j = 0; j < 9; j++)
            {
                uint slot = ((bx + i) * 7 + (by + j) * 13 + (bx + i) * (by + j)) % 4;
                words[i * 9 + j] = (ushort)((uint)(words[i * 9 + j] & 0x07FF) | (slot << 11));
            }
        }

        return words;
    }

    // Each block's houses and statics, on the ground (a landblock info's frames are stored with their heights).
    private static byte[] Info(uint block, TerrainWorld heights)
    {
        var rnd = new Random((int)(block >> 16));
        double gx = (block >> 24) * 192.0, gy = ((block >> 16) & 0xFF) * 192.0;
        Frame At(float x, float y, float heading)
        {
            heights.TryGetTerrainHeight(gx + x, gy + y, out float z);
            return Frame.FromHeading(new Vector3(x, y, z), heading);
        }

        var houses = new List<(uint, Frame)>();
        int n = block == Centre ? 5 : 2;
        for (int i = 0; i < n; i++)
        {
            houses.Add((i % 2 == 0 ? House : Hut, At(30f + (float)rnd.NextDouble() * 132f, 30f + (float)rnd.NextDouble() * 132f,
                                                      (float)rnd.Next(4) * 90f + 15f)));
        }

        var statics = new List<(uint, Frame)>();
        for (int i = 0; i < 12; i++)
        {
            statics.Add((i % 3 == 0 ? Tree : Rock, At(8f + (float)rnd.NextDouble() * 176f, 8f + (float)rnd.NextDouble() * 176f,
                                                     (float)rnd.NextDouble() * 360f)));
        }

        return WorldDataBytes.LandBlockInfo((block & 0xFFFF0000u) | 0xFFFEu, statics.ToArray(), houses.ToArray());
    }

    // Every terrain type: slot 0 grows nothing, odd slots a grove, even slots rocks, a meadow or a copse.
    private static byte[] Region(LandHeightTable table)
    {
        var slots = new int[32];
        for (int s = 0; s < slots.Length; s++)
        {
            slots[s] = s == 0 ? -1 : s % 2;
        }

        var types = new TerrainTypeDef[32];
        for (int t = 0; t < types.Length; t++)
        {
            types[t] = new TerrainTypeDef($"Type{t}", 0, slots);
        }

        return RegionSceneBytes.Region(new RegionDef(
            SceneTypes: [new SceneTypeDef(-1, [Grove]), new SceneTypeDef(-1, [Rocks, Meadow, Copse])],
            TerrainTypes: types,
            Heights: table.Heights.ToArray(),
            Sky: false,
            SoundTables: 0));
    }

    private static ObjectDesc Spot(uint id, float x, float y, float freq, float displace, float minScale, float maxScale) =>
        new(id, new Frame(new Vector3(x, y, 0f), Quaternion.Identity), freq, displace, displace, minScale, maxScale, 360f, 0f, 1f,
            0, 0, 0);

    private static void AddScenesAndModels(Dictionary<uint, byte[]> e)
    {
        e[Grove] = RegionSceneBytes.Scene(Grove, [Spot(Tree, 12f, 12f, 0.5f, 10f, 0.8f, 1.2f), Spot(Bush, 4f, 18f, 0.4f, 4f, 0.7f, 1.3f)]);
        e[Rocks] = RegionSceneBytes.Scene(Rocks, [Spot(Rock, 6f, 6f, 0.35f, 6f, 0.6f, 1.4f), Spot(Grass, 16f, 10f, 0.8f, 6f, 1f, 1f)]);
        e[Meadow] = RegionSceneBytes.Scene(Meadow, [Spot(Grass, 12f, 12f, 0.9f, 10f, 1f, 1f), Spot(Bush, 18f, 4f, 0.3f, 4f, 0.8f, 1.2f)]);
        e[Copse] = RegionSceneBytes.Scene(Copse, [Spot(Tree, 6f, 16f, 0.4f, 5f, 0.9f, 1.3f), Spot(Tree, 18f, 8f, 0.3f, 5f, 0.9f, 1.3f)]);
        e[Trunk] = WorldDataBytes.DrawingGfxObj(Trunk, new Vector3(-0.5f, -0.5f, 0f), new Vector3(0.5f, 0.5f, 8f));
        e[Tree] = WorldDataBytes.CylinderSetup(Tree, Trunk, 0.6f, 10f, -1f);
        e[Bush] = WorldEntries.Setup(new SetupDef(Bush, [Trunk])
        {
            Spheres = [(new Vector3(0f, 0f, 0.9f), 1.1f)],
            Height = 2f,
            Radius = 1.1f,
            Placements = [(0x65, [Frame.Identity])],
        });
        e[Grass] = WorldEntries.Setup(new SetupDef(Grass, [Trunk]) { Placements = [(0x65, [Frame.Identity])] });
        e[Rock] = WorldDataBytes.BoxGfxObj(Rock, new Vector3(-1.2f, -0.9f, -0.3f), new Vector3(1.2f, 0.9f, 1.1f));
        e[House] = WorldDataBytes.BoxGfxObj(House, new Vector3(-7f, -5f, -1f), new Vector3(7f, 5f, 6f));
        e[Hut] = WorldDataBytes.BoxGfxObj(Hut, new Vector3(-4f, -4f, -1f), new Vector3(4f, 4f, 4f));
    }

    /// <summary>The first walk, from (x, 150) of the centre block for x = 40, 50, ... 150, that ends in another landblock
    /// (scenery may stop a walker: it is removed and the next start tried); the last one tried when none does.</summary>
    public static List<Position> WalkAcross(PhysicsWorld world)
    {
        List<Position> path = [];
        for (float x = 40f; x <= 150f; x += 10f)
        {
            if (world.Player is { } previous)
            {
                world.Player = null;
                world.RemoveObject(previous);
            }

            path = Walk(world, new Vector2(x, 150f), seconds: 16.0);
            if ((path[^1].ObjCellId >> 16) != (Centre >> 16))
            {
                break;
            }
        }

        return path;
    }

    /// <summary>A walker (one sphere, r 0.48 m) from <paramref name="start"/> of the centre block, heading north at 4 m/s
    /// with a slight turn to the east, for <paramref name="seconds"/> of 30 Hz ticks: its positions, one per tick.</summary>
    public static List<Position> Walk(PhysicsWorld world, Vector2 start, double seconds)
    {
        SimplePartArray parts = Walkers.OneSphere(0.48f, 0.6f, 1.5f);
        parts.SequenceVelocity = new Vector3(0f, 4f, 0f);
        parts.SequenceOmega = new Vector3(0f, 0f, -0.06f);
        uint cell = LandDefs.LCoordToGid(0xA9 * 8 + (int)(start.X / 24f), 0xB4 * 8 + (int)(start.Y / 24f));
        TerrainWorld terrain = ((WorldCells)((RetailSweep)world.Sweep).Cells).Terrain;
        terrain.TryGetTerrainHeight(0xA9 * 192.0 + start.X, 0xB4 * 192.0 + start.Y, out float z);
        PhysicsObj player = Walkers.Create(world, 0x50000001, new Position(cell, new Frame(new Vector3(start, z), Quaternion.Identity)), parts);
        world.Player = player;
        var path = new List<Position> { player.Position };
        double now = world.CurrentTime;
        for (int i = 0; i < (int)(seconds * 30.0); i++)
        {
            now += 1.0 / 30.0;
            world.Tick(now);
            path.Add(player.Position);
        }

        return path;
    }
}
