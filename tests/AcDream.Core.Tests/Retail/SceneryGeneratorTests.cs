using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Scenery;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Tests.Support;
using Xunit;
using static AcDream.Core.Tests.Support.SceneryScene;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// <c>CLandBlock::get_land_scenes</c> (acclient.c:352529) as <see cref="SceneryGenerator.Generate(LandBlock, RegionEntry, Func{uint, SceneEntry}, Func{uint, bool}, List{ScenePlacement})"/>:
/// each filter and their order, on synthetic blocks of 0xA9B4 (vertex (i, j) is global (1352 + i, 1440 + j)).
/// </summary>
public class SceneryGeneratorTests
{
    private static readonly ushort Single = Word(1, 1);  // slot 1: scene type 0, one scene
    private static readonly ushort Triple = Word(1, 2);  // slot 2: scene type 1, three scenes

    [Fact]
    public void OneSpot_LandsAtEveryVertex_TurnedByItsQuadrant_InRetailOrder()
    {
        List<ScenePlacement> got = Generate(Block(Single), Scenes((SingleScene, [Spot(new Vector3(6f, 6f, 3f))])));
        var expected = new List<(int I, int J, Vector2 P)>();
        for (int i = 0; i < 9; i++)
        {
            for (int j = 0; j < 9; j++)
            {
                Vector2 p = Turn(1352u + (uint)i, 1440u + (uint)j, new Vector2(6f, 6f)) + new Vector2(24f * i, 24f * j);
                if (p.X >= 0f && p.Y >= 0f && p.X < 192f && p.Y < 192f)
                {
                    expected.Add((i, j, p));
                }
            }
        }

        Assert.Equal(expected.Count, got.Count);
        for (int n = 0; n < got.Count; n++)
        {
            ScenePlacement s = got[n];
            Assert.Equal((expected[n].I, expected[n].J), (s.VertexX, s.VertexY));
            Assert.Equal(new Vector3(expected[n].P, 20f), s.Frame.Origin); // flat at height index 10: z = 20 m
            uint cell = 0xA9B40000u | (uint)((int)(s.Frame.Origin.X / 24f) * 8 + (int)(s.Frame.Origin.Y / 24f) + 1);
            Assert.Equal(cell, s.LandCellId);
            Assert.Equal((0x02000001u, SingleScene, 0, 1f), (s.ObjectId, s.SceneId, s.ObjectIndex, s.Scale));
        }
    }

    [Fact]
    public void TheScenePick_IsFloorOfUTimesCount()
    {
        // Three scenes of one spot each, object ids 0x02000020..22, placed at the vertex itself (origin 0).
        Func<uint, SceneEntry?> scenes = Scenes(TripleScenes.Select(id => (id, new[] { Spot(Vector3.Zero, id: 0x02000000u | (id & 0xFF)) })).ToArray());
        List<ScenePlacement> got = Generate(Block(Triple), scenes);
        Assert.Equal(64, got.Count); // vertices 0..7 in each direction: (24 i, 24 j) is inside, 192 is not
        foreach (ScenePlacement s in got)
        {
            uint pick = (uint)Math.Floor(SceneryHash.Unit(1352u + (uint)s.VertexX, 1440u + (uint)s.VertexY, 11257) * 3);
            Assert.Equal(TripleScenes[pick], s.SceneId);
            Assert.Equal(0x02000000u | (TripleScenes[pick] & 0xFF), s.ObjectId);
        }

        // Vertex (0, 0) = global (1352, 1440): h = 0x4B261039, u = 0.29355..., floor(3u) = 0.
        Assert.Equal(TripleScenes[0], got[0].SceneId);
    }

    [Fact]
    public void SlotsAndTypesWithoutScenes_AreSkipped()
    {
        Func<uint, SceneEntry?> scenes = Scenes((SingleScene, [Spot(Vector3.Zero)]));
        Assert.Empty(Generate(Block(Word(1, 0)), scenes)); // slot 0: a null scene type
        Assert.Empty(Generate(Block(Word(1, 3)), scenes)); // slot 3: past the type's three slots
        Assert.Empty(Generate(Block(Word(0, 1)), scenes)); // type 0 has no slots
        Assert.Empty(Generate(Block(Word(7, 1)), scenes)); // type 7 is not in the region
        Assert.Empty(Generate(Block(Single), _ => null));  // the scene is not in the data
        Assert.Equal(64, Generate(Block(Single), scenes).Count);
    }

    [Fact]
    public void WeenieSpots_AreTheServers_AndAreSkipped_WhateverTheirId()
    {
        Assert.Empty(Generate(Block(Single), Scenes((SingleScene, [Spot(Vector3.Zero, id: 0x02000001, weenie: 1)]))));
        // An id of 0 without the weenie flag is placed (retail tests weenie_obj, not the id).
        Assert.Equal(64, Generate(Block(Single), Scenes((SingleScene, [Spot(Vector3.Zero, id: 0)]))).Count);
    }

    [Fact]
    public void EachSpotIsDrawn_WithSalt23399PlusItsIndex()
    {
        ObjectDesc[] spots = [Spot(new Vector3(1f, 1f, 0f), freq: 0.5f), Spot(new Vector3(2f, 2f, 0f), freq: 0.5f), Spot(Vector3.Zero, freq: 0f)];
        List<ScenePlacement> got = Generate(Block(Single), Scenes((SingleScene, spots)));
        for (int i = 1; i < 8; i++)
        {
            for (int j = 1; j < 8; j++)
            {
                // Interior vertices: any quarter turn of (1, 1) or (2, 2) stays in the block.
                int[] placed = got.Where(s => s.VertexX == i && s.VertexY == j).Select(s => s.ObjectIndex).ToArray();
                int[] drawn = Enumerable.Range(0, 3)
                    .Where(k => SceneryHash.Unit(1352u + (uint)i, 1440u + (uint)j, 23399u + (uint)k) < spots[k].Frequency).ToArray();
                Assert.Equal(drawn, placed);
            }
        }

        Assert.DoesNotContain(got, s => s.ObjectIndex == 2); // freq 0: never (u >= 0)
        Assert.Contains(got, s => s.ObjectIndex == 1);
    }

    [Fact]
    public void TheBounds_AreStrict_ZeroIn_192Out()
    {
        // Origin 0 at every vertex: (24 i, 24 j), the quarter turn of 0 being +-0. i or j = 8 gives 192: out.
        List<ScenePlacement> got = Generate(Block(Single), Scenes((SingleScene, [Spot(Vector3.Zero)])));
        Assert.Equal(64, got.Count);
        Assert.All(got, s => Assert.True(s.VertexX < 8 && s.VertexY < 8));
        Assert.Contains(got, s => s.Frame.Origin.X == 0f && s.Frame.Origin.Y == 0f);
    }

    [Fact]
    public void RoadPoints_AreSkipped()
    {
        // Roads on every vertex of column 4: the strips x in (91, 101) of cells 3 and 4 are road.
        LandBlock roads = Block(Single, words: (i, j) => Word(1, 1, i == 4 ? 1 : 0));
        ObjectDesc[] spots = [Spot(new Vector3(3f, 9f, 0f)), Spot(new Vector3(-3f, 9f, 0f)), Spot(new Vector3(9f, 9f, 0f))];
        List<ScenePlacement> free = Generate(Block(Single), Scenes((SingleScene, spots)));
        List<ScenePlacement> got = Generate(roads, Scenes((SingleScene, spots)));
        Assert.All(got, s => Assert.False(SceneryGenerator.OnRoad(roads.Terrain, s.Frame.Origin.X, s.Frame.Origin.Y)));
        Assert.All(got, s => Assert.False(s.Frame.Origin.X > 91f && s.Frame.Origin.X < 101f));
        Assert.Equal(free.Count(s => !(s.Frame.Origin.X > 91f && s.Frame.Origin.X < 101f)), got.Count);
        Assert.True(got.Count < free.Count);
        Assert.Empty(Generate(Block(Word(1, 1, 3)), Scenes((SingleScene, spots)))); // every corner a road: all road
    }

    [Fact]
    public void ACellHoldingABuilding_GrowsNoScenery()
    {
        Func<uint, SceneEntry?> scenes = Scenes((SingleScene, [Spot(new Vector3(6f, 6f, 0f)), Spot(new Vector3(-6f, 6f, 0f))]));
        List<ScenePlacement> all = Generate(Block(Single), scenes);
        var buildings = new HashSet<uint> { 0xA9B40001, 0xA9B4001C, 0xA9B40040 };
        List<ScenePlacement> got = Generate(Block(Single), scenes, buildings.Contains);
        Assert.DoesNotContain(got, s => buildings.Contains(s.LandCellId));
        Assert.Equal(all.Where(s => !buildings.Contains(s.LandCellId)), got);
        Assert.Contains(all, s => s.LandCellId == 0xA9B4001C);
    }

    [Fact]
    public void TheSlopeWindow_IsInclusive_AndZLiesOnTheTerrain()
    {
        // Heights 12 * i m: a plane rising 12 m per 24 m eastward, N = (-1, 0, 2) / sqrt 5, N.z = 0.8944272.
        LandBlock ramp = Block(Single, height: (i, j) => 6 * i);
        float nz = ramp.Cells[0].Polygon0.Plane.N.Z;
        Assert.Equal(2.0 / Math.Sqrt(5.0), nz, 6);
        ObjectDesc at = Spot(new Vector3(6f, 6f, 0f), minSlope: nz, maxSlope: nz);
        List<ScenePlacement> got = Generate(ramp, Scenes((SingleScene, [at])));
        Assert.NotEmpty(got);
        foreach (ScenePlacement s in got)
        {
            Assert.Equal(s.Frame.Origin.X / 2f, s.Frame.Origin.Z, 3);
            Assert.True(ramp.GetLandCell(s.LandCellId)!.TryGetHeight(s.Frame.Origin, out float z));
            Assert.Equal(z, s.Frame.Origin.Z);
        }

        float above = BitConverter.Int32BitsToSingle(BitConverter.SingleToInt32Bits(nz) + 1);
        Assert.Empty(Generate(ramp, Scenes((SingleScene, [Spot(new Vector3(6f, 6f, 0f), minSlope: above)]))));
        Assert.Empty(Generate(ramp, Scenes((SingleScene, [Spot(new Vector3(6f, 6f, 0f), maxSlope: 0.89f)]))));
    }

    [Fact]
    public void AlignedSpots_FaceUphill_WithoutTilt()
    {
        // The ramp rises eastward: its normal leans west (downhill), so -N, and the heading, point east (90 degrees).
        // (The research note's "downhill heading" reads -N as downhill; the normal itself is.)
        LandBlock ramp = Block(Single, height: (i, j) => 6 * i);
        List<ScenePlacement> got = Generate(ramp, Scenes((SingleScene, [Spot(new Vector3(6f, 6f, 0f), align: 1, maxRot: 360f)])));
        Assert.NotEmpty(got);
        Assert.All(got, s =>
        {
            Assert.Equal(90.0, s.Frame.Heading, 4);
            Assert.Equal(1f, s.Frame.LocalToGlobalVec(Vector3.UnitZ).Z, 6);
        });
    }

    [Fact]
    public void TheScale_IsScaleObjs()
    {
        ObjectDesc[] spots = [Spot(new Vector3(6f, 6f, 0f), minScale: 0.7f, maxScale: 1.5f), Spot(new Vector3(-6f, 6f, 0f), minScale: 2f, maxScale: 2f)];
        List<ScenePlacement> got = Generate(Block(Single), Scenes((SingleScene, spots)));
        Assert.All(got.Where(s => s.ObjectIndex == 1), s => Assert.Equal(2f, s.Scale));
        Assert.All(got.Where(s => s.ObjectIndex == 0), s =>
        {
            Assert.InRange(s.Scale, 0.7f, 1.5f);
            Assert.Equal(ObjectPlacement.ScaleObj(spots[0], 1352u + (uint)s.VertexX, 1440u + (uint)s.VertexY, 0), s.Scale);
        });
    }

    [Fact]
    public void TheFilters_RunInRetailsOrder()
    {
        // Bounds and road first, then the cell's building, then the terrain triangle and the slope.
        var asked = new List<uint>();
        bool Building(uint cell)
        {
            asked.Add(cell);
            return false;
        }

        Func<uint, SceneEntry?> steep = Scenes((SingleScene, [Spot(Vector3.Zero, minSlope: 2f)])); // no slope passes
        Assert.Empty(Generate(Block(Single), steep, Building));
        Assert.Equal(64, asked.Count); // the building test ran for every in-bounds point, before the slope refused it

        asked.Clear();
        Assert.Empty(Generate(Block(Word(1, 1, 2)), Scenes((SingleScene, [Spot(Vector3.Zero)])), Building));
        Assert.Empty(asked); // all on road: the building test never ran
    }

    [Fact]
    public void TheDataSourceOverload_ReadsScenesFromTheFiles_AndBadBytesAppendNothing()
    {
        var source = new DictionarySource();
        source.Entries[SingleScene] = RegionSceneBytes.Scene(SingleScene, [Spot(new Vector3(6f, 6f, 0f))]);
        RegionEntry region = Region();
        LandBlock block = Block(Single);
        var entry = new LandBlockEntry(BlockId, block.Height, block.Terrain);
        var list = new List<ScenePlacement> { default };
        int n = SceneryGenerator.Generate(entry, region, source, new HashSet<uint> { 0xA9B40001 }, list);
        Assert.Equal(list.Count - 1, n);
        Assert.Equal(Generate(block, Scenes((SingleScene, [Spot(new Vector3(6f, 6f, 0f))])), c => c == 0xA9B40001), list.Skip(1));

        source.Entries[SingleScene] = source.Entries[SingleScene].AsSpan(0, 50).ToArray();
        Assert.Throws<RetailDataFormatException>(() => SceneryGenerator.Generate(entry, region, source, null, list));
        Assert.Equal(n + 1, list.Count);

        // A delegate that throws part-way: what was appended before is taken back.
        int calls = 0;
        SceneEntry good = SceneEntry.UnPack(RegionSceneBytes.Scene(SingleScene, [Spot(new Vector3(6f, 6f, 0f))]));
        Assert.Throws<InvalidOperationException>(() => SceneryGenerator.Generate(block, region,
            _ => ++calls < 10 ? good : throw new InvalidOperationException(), null, list));
        Assert.Equal(n + 1, list.Count);
    }

    [Fact]
    public void NullArguments_Throw()
    {
        RegionEntry region = Region();
        LandBlock block = Block(Single);
        var list = new List<ScenePlacement>();
        Assert.Throws<ArgumentNullException>(() => SceneryGenerator.Generate((LandBlock)null!, region, _ => null, null, list));
        Assert.Throws<ArgumentNullException>(() => SceneryGenerator.Generate(block, null!, _ => null, null, list));
        Assert.Throws<ArgumentNullException>(() => SceneryGenerator.Generate(block, region, null!, null, list));
        Assert.Throws<ArgumentNullException>(() => SceneryGenerator.Generate(block, region, _ => null, null, null!));
        Assert.Throws<ArgumentNullException>(() => SceneryGenerator.Generate((LandBlockEntry)null!, region, new DictionarySource(), null, list));
    }
}
