using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Scenery;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// Whole-world invariants of the procedural scenery over the real Dereth terrain (<c>../shared/data/ac-terrain</c>: real
/// heights, terrain types and roads). The fixture has no scene-type slots (bits 11–15 of the terrain word are not in it), so
/// each vertex's slot is synthesised with the scenery hash itself: <c>h(x, y, 0x5107) mod 4</c> (slot 0 is a null scene
/// type). The region has all 32 terrain types with slots [none, one scene, three scenes, two scenes] and the real height
/// table; buildings are synthesised too (two land cells per block). Every placement must lie in its block, off the road,
/// outside the building cells, on the terrain surface, within its slope window and scale range; and the placements are the
/// same whatever order the blocks are generated in.
/// </summary>
public class RealTerrainSceneryTests
{
    private const uint SlotSalt = 0x5107;

    // Around Holtburg (0xA9B4): 20 x 20 blocks.
    private static readonly (int X, int Y)[] Blocks =
        Enumerable.Range(0xA9 - 10, 20).SelectMany(x => Enumerable.Range(0xB4 - 10, 20).Select(y => (x, y))).ToArray();

    private static readonly Dictionary<uint, ObjectDesc[]> SceneSpots = new()
    {
        [0x12000001] = [Spot(0x02000247, 0.352f, 7.38f, 7.02f, 0.7f, 1.5f, 360f, 0f, 1f), Spot(0, 1f, -0.66f, 1.38f, weenie: 1)],
        [0x12000002] = [Spot(0x020002D3, 0.5f, 12f, 12f, 0.9f, 1.2f, 360f, 0.95f, 1f), Spot(0x02000246, 0.8f, 4f, 0f, 1f, 1f, 0f, 0.7f, 0.95f)],
        [0x12000003] = [Spot(0x02000258, 1f, 0f, 10f, 1f, 2f, 0f, 0f, 1f, align: 1)],
        [0x12000004] = [Spot(0x01000100, 0.25f, 24f, 24f, 0.5f, 0.5f, 90f, 0.5f, 0.8f)],
        [0x12000005] = [Spot(0x02000300, 0.6f, 2f, 2f, 1f, 3f, 180f, 0f, 1f), Spot(0x02000301, 0.6f, 6f, 6f, 1f, 1f, 360f, 0.9f, 1f)],
        [0x12000006] = [Spot(0x02000302, 0.9f, 18f, 3f, 0.8f, 1f, 45f, 0.3f, 1f, align: 1)],
    };

    private static ObjectDesc Spot(uint id, float freq, float dx = 0f, float dy = 0f, float minScale = 1f, float maxScale = 1f,
        float maxRot = 0f, float minSlope = 0f, float maxSlope = 1f, uint align = 0, uint weenie = 0) =>
        SceneryScene.Spot(new Vector3(3f, -2f, 0f), id, freq, dx, dy, minScale, maxScale, maxRot, minSlope, maxSlope, align, weenie);

    private static RegionEntry Region() => RegionEntry.UnPack(RegionSceneBytes.Region(new RegionDef(
        SceneTypes:
        [
            new SceneTypeDef(-1, [0x12000001]),
            new SceneTypeDef(-1, [0x12000002, 0x12000003, 0x12000004]),
            new SceneTypeDef(-1, [0x12000005, 0x12000006]),
        ],
        TerrainTypes: Enumerable.Range(0, 32).Select(t => new TerrainTypeDef($"Type{t}", (uint)t, [-1, 0, 1, 2])).ToArray(),
        Heights: TerrainTestData.RealTable.Heights.ToArray(),
        Sky: false,
        SoundTables: 0)));

    private static readonly Lazy<Dictionary<uint, SceneEntry>> Scenes = new(() =>
        SceneSpots.ToDictionary(kv => kv.Key, kv => SceneEntry.UnPack(RegionSceneBytes.Scene(kv.Key, kv.Value))));

    // The real block with hash-synthesised scene slots.
    private static LandBlockEntry Entry(int bx, int by)
    {
        LandBlockEntry real = TerrainTestData.Image.GetLandBlockEntry(bx, by);
        var terrain = real.Terrain.ToArray();
        for (int i = 0; i < 9; i++)
        {
            for (int j = 0; j < 9; j++)
            {
                uint slot = SceneryHash.Hash((uint)(bx * 8 + i), (uint)(by * 8 + j), SlotSalt) % 4;
                terrain[i * 9 + j] = (ushort)((uint)(terrain[i * 9 + j] & 0x7FF) | (slot << 11));
            }
        }

        return new LandBlockEntry(real.Id, real.Height, terrain);
    }

    private static HashSet<uint> Buildings(uint blockId)
    {
        uint h = SceneryHash.Hash(blockId >> 24, (blockId >> 16) & 0xFF, 77);
        return [(blockId & 0xFFFF0000) | (h % 64 + 1), (blockId & 0xFFFF0000) | ((h >> 8) % 64 + 1)];
    }

    private static List<ScenePlacement> Generate(RegionEntry region, LandBlock block) =>
        Generate(region, block, Buildings(block.Id));

    private static List<ScenePlacement> Generate(RegionEntry region, LandBlock block, HashSet<uint> buildings)
    {
        var list = new List<ScenePlacement>();
        SceneryGenerator.Generate(block, region, id => Scenes.Value.TryGetValue(id, out SceneEntry? s) ? s : null, buildings.Contains, list);
        return list;
    }

    [TerrainDataFact]
    public void EveryPlacement_IsInItsBlock_OffRoad_OutOfBuildingCells_OnTheSurface_InItsSlopeAndScale()
    {
        RegionEntry region = Region();
        var world = new TerrainWorld(region.LandHeightTable);
        int total = 0, roadVertices = 0;
        foreach ((int bx, int by) in Blocks)
        {
            LandBlock block = world.AddLandBlock(LandBlock.MakeId(bx, by), Entry(bx, by).Height, Entry(bx, by).Terrain);
            roadVertices += block.Terrain.ToArray().Count(w => (w & 3) != 0);
            HashSet<uint> buildings = Buildings(block.Id);
            List<ScenePlacement> got = Generate(region, block);
            total += got.Count;
            foreach (ScenePlacement s in got)
            {
                Vector3 o = s.Frame.Origin;
                Assert.InRange(o.X, 0f, 191.99998f);
                Assert.InRange(o.Y, 0f, 191.99998f);
                Assert.False(SceneryGenerator.OnRoad(block.Terrain, o.X, o.Y));
                Assert.DoesNotContain(s.LandCellId, buildings);
                Assert.Equal(block.GetCell((int)(o.X / 24f), (int)(o.Y / 24f)).Id, s.LandCellId);

                // On the surface: the world's height query from global coordinates agrees within float rounding.
                float z = world.GetTerrainHeight(bx * 192.0 + o.X, by * 192.0 + o.Y);
                Assert.True(Math.Abs(z - o.Z) <= 1e-3f * Math.Max(1f, Math.Abs(z)), $"z {o.Z} vs terrain {z}");

                ObjectDesc spot = Scenes.Value[s.SceneId].Objects[s.ObjectIndex];
                Assert.Equal(0u, spot.WeenieObj);
                LandCell cell = block.GetLandCell(s.LandCellId)!;
                Assert.True(cell.FindTerrainPoly(o, out Polygon? poly));
                Assert.InRange(poly.Plane.N.Z, spot.MinSlope, spot.MaxSlope);
                Assert.InRange(s.Scale, spot.MinScale, spot.MaxScale);
            }
        }

        Assert.True(total > 5000, $"only {total} placements");
        Assert.True(roadVertices > 100, "the area has roads"); // Holtburg's roads: the road filter is exercised
    }

    [TerrainDataFact]
    public void ThePlacements_AreTheSame_WhateverTheLoadOrder()
    {
        RegionEntry region = Region();
        var forward = new Dictionary<uint, List<ScenePlacement>>();
        var world = new TerrainWorld(region.LandHeightTable);
        foreach ((int bx, int by) in Blocks)
        {
            LandBlock b = world.AddLandBlock(LandBlock.MakeId(bx, by), Entry(bx, by).Height, Entry(bx, by).Terrain);
            forward[b.Id] = Generate(region, b);
        }

        // Reverse order, each block alone in its own world, built through the entry overload from a data source.
        var source = new DictionarySource();
        foreach ((uint id, ObjectDesc[] spots) in SceneSpots)
        {
            source.Entries[id] = RegionSceneBytes.Scene(id, spots);
        }

        foreach ((int bx, int by) in Blocks.Reverse())
        {
            uint id = LandBlock.MakeId(bx, by);
            var list = new List<ScenePlacement>();
            SceneryGenerator.Generate(Entry(bx, by), region, source, Buildings(id), list);
            Assert.Equal(forward[id], list);
        }
    }
}
