using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Tests.Support;
using Xunit;
using AcDream.Core.Physics.Data;

namespace AcDream.Core.Tests.Retail;

/// <summary>Scenes on the real Dereth heightfield (fixtures from ACDREAM_TERRAIN_DIR).</summary>
public class RealTerrainTests
{
    [TerrainDataFact]
    public void HeightTable_HasRetailShape()
    {
        LandHeightTable t = TerrainTestData.RealTable;
        // 0..200: 2 * i.
        for (int i = 0; i <= 200; i++)
        {
            Assert.Equal(2f * i, t[(byte)i]);
        }

        // 201..240: steps of 4 from 400 -> 560; 241..250: steps of 8 -> 640; then 650, 660, 670, 680, 700.
        for (int i = 201; i <= 240; i++)
        {
            Assert.Equal(400f + 4f * (i - 200), t[(byte)i]);
        }

        for (int i = 241; i <= 250; i++)
        {
            Assert.Equal(560f + 8f * (i - 240), t[(byte)i]);
        }

        Assert.Equal(new[] { 650f, 660f, 670f, 680f, 700f }, t.Heights[251..].ToArray());
    }

    [TerrainDataFact]
    public void Landblock9AB1_KnownVerticesMapThroughTheTable()
    {
        // Height[0, 1, 40, 79, 80] = 120, 139, 93, 93, 110 (the values DatReaderWriter asserts against the retail dat);
        // through the table (2 * i below 201): 240, 278, 186, 186, 220 m.
        LandBlock b = TerrainTestData.SampleBlock(0x9AB1FFFFu).ToLandBlock(TerrainTestData.RealTable);
        int[] idx = [0, 1, 40, 79, 80];
        byte[] expectedIndex = [120, 139, 93, 93, 110];
        float[] expectedMetres = [240f, 278f, 186f, 186f, 220f];
        for (int k = 0; k < idx.Length; k++)
        {
            Assert.Equal(expectedIndex[k], b.Height[idx[k]]);
            Assert.Equal(expectedMetres[k], b.Vertices[idx[k]].Z);
        }

        // Index 40 = vx 4, vy 4: position (96, 96).
        Assert.Equal(new Vector3(96f, 96f, 186f), b.Vertices[40]);
    }

    [TerrainDataFact]
    public void Landblock9AB1_HeightQueryAtEveryVertexEqualsTheTable()
    {
        // The query evaluates a float plane, so a vertex comes back within rounding: |d| <= ~700 with float ulp 6e-5,
        // normal components ulp 6e-8 times coordinates <= 192 -> well under 1e-3 m.
        TerrainWorld world = TerrainTestData.SampleWorld(0x9AB1FFFFu);
        LandBlock b = world.GetLandBlock(0x9AB1FFFFu)!;
        for (int vx = 0; vx < 8; vx++)
        {
            for (int vy = 0; vy < 8; vy++)
            {
                var p = new Position(0x9AB10001u, new Vector3(vx * 24f, vy * 24f, 0f));
                Assert.True(world.TryGetTerrainHeight(p, out float z));
                Assert.Equal(b.Vertices[vx * 9 + vy].Z, z, 0.001f);
            }
        }
    }

    [TerrainDataFact]
    public void Landblock9AB1_InterpolatedHeightsInsideBothTriangles_HandComputed()
    {
        // Cell (0, 0): global cell (1232, 1416), split value 2305726851 >= 2^31 -> cut SW-NE.
        // Corners: SW (0,0,240), SE (24,0,246), NE (24,24,278), NW (0,24,278) (indices 120, 123, 139, 139).
        // Triangle 0 (SW, SE, NE): (SE-SW) x (NE-SW) = (24,0,6) x (24,24,38) = (0*38-6*24, 6*24-24*38, 24*24) = (-144, -768, 576)
        //   -> z = 240 + (144 x + 768 y) / 576 = 240 + x/4 + 4y/3. At (16, 4): 240 + 4 + 16/3 = 249.3333.
        // Triangle 1 (SW, NE, NW): (24,24,38) x (0,24,38) = (24*38-38*24, 38*0-24*38, 24*24) = (0, -912, 576)
        //   -> z = 240 + 912 y / 576 = 240 + 19y/12. At (4, 16): 240 + 25.3333 = 265.3333.
        TerrainWorld world = TerrainTestData.SampleWorld(0x9AB1FFFFu);
        Assert.True(world.GetLandBlock(0x9AB1FFFFu)!.IsCellSWtoNECut(0, 0));
        Assert.True(world.TryGetTerrainHeight(new Position(0x9AB10001u, new Vector3(16f, 4f, 0f)), out float z0));
        Assert.Equal(240.0 + 4.0 + 16.0 / 3.0, z0, 0.001);
        Assert.True(world.TryGetTerrainHeight(new Position(0x9AB10001u, new Vector3(4f, 16f, 0f)), out float z1));
        Assert.Equal(240.0 + 19.0 * 16.0 / 12.0, z1, 0.001);

        // The same points through global coordinates: block 0x9A spans x from 154 * 192 = 29568, 0xB1 y from 177 * 192 = 33984.
        Assert.Equal(z0, world.GetTerrainHeight(29568.0 + 16.0, 33984.0 + 4.0));
    }

    [TerrainDataFact]
    public void Holtburg3x3_TerrainIsContinuousAcrossLandblockEdges()
    {
        uint[] ids = [0xA8B3FFFFu, 0xA8B4FFFFu, 0xA8B5FFFFu, 0xA9B3FFFFu, 0xA9B4FFFFu, 0xA9B5FFFFu, 0xAAB3FFFFu, 0xAAB4FFFFu, 0xAAB5FFFFu];
        TerrainWorld world = TerrainTestData.SampleWorld(ids);
        for (int bx = 0xA8; bx <= 0xAA; bx++)
        {
            for (int by = 0xB3; by <= 0xB5; by++)
            {
                LandBlock b = world.GetLandBlock(bx, by)!;
                LandBlock? east = world.GetLandBlock(bx + 1, by);
                LandBlock? north = world.GetLandBlock(bx, by + 1);
                for (int k = 0; k <= 8 * 4; k++)
                {
                    float s = k * 6f; // every 6 m along the edge, vertices and mid-edge points
                    int cell = Math.Min(k / 4, 7);
                    if (east is not null)
                    {
                        // Shared vertices are the same data, and both sides' triangles agree along the edge line.
                        Assert.Equal(b.Vertices[8 * 9 + k / 4].Z, east.Vertices[k / 4].Z);
                        Assert.True(b.GetCell(7, cell).TryGetHeight(new Vector3(192f, s, 0f), out float zw));
                        Assert.True(east.GetCell(0, cell).TryGetHeight(new Vector3(0f, s, 0f), out float ze));
                        Assert.Equal(zw, ze, 0.001f);
                    }

                    if (north is not null)
                    {
                        Assert.Equal(b.Vertices[(k / 4) * 9 + 8].Z, north.Vertices[(k / 4) * 9].Z);
                        Assert.True(b.GetCell(cell, 7).TryGetHeight(new Vector3(s, 192f, 0f), out float zs));
                        Assert.True(north.GetCell(cell, 0).TryGetHeight(new Vector3(s, 0f, 0f), out float zn));
                        Assert.Equal(zs, zn, 0.001f);
                    }
                }
            }
        }
    }

    [TerrainDataFact]
    public void Holtburg_WaterToTheSouthOfA9B5_CellTypesAndDepths()
    {
        // In 0xA9B5 the corners of cell (4, 7) are all water (types 16..20): entirely water, depth 0.9.
        // Cell (0, 7) has two water corners: partly water.
        TerrainWorld world = TerrainTestData.SampleWorld(0xA9B5FFFFu);
        LandBlock b = world.GetLandBlock(0xA9B5FFFFu)!;
        Assert.Equal(WaterType.PartiallyWater, b.WaterType);
        LandCell full = b.GetCell(4, 7);
        Assert.Equal(WaterType.EntirelyWater, full.WaterType);
        Assert.True(world.TryGetWaterDepth(new Position(full.Id, full.Origin), out float d));
        Assert.Equal(0.9f, d);

        LandCell part = b.GetCell(0, 7);
        Assert.Equal(WaterType.PartiallyWater, part.WaterType);
        int water = 0;
        for (int c = 0; c < 4; c++)
        {
            int vx = c >> 1, vy = 7 + (c & 1);
            bool isWater = TerrainTypes.SurfCharOf(TerrainTypes.TypeOf(b.Terrain[vx * 9 + vy])) == SurfChar.Water;
            water += isWater ? 1 : 0;
            // A point 2 m from that corner inside the cell takes the corner's depth.
            var pt = new Vector3(vx * 24f + (vx == 0 ? 2f : -2f), vy * 24f + (vy == 7 ? 2f : -2f), 0f);
            Assert.Equal(isWater ? 0.45f : 0.1f, part.GetWaterDepth(pt));
        }

        Assert.Equal(2, water);
        Assert.Equal(WaterType.NotWater, b.GetCell(0, 0).WaterType);
    }

    [TerrainDataFact]
    public void TerrainPng_DecodesToTheSampleCsvExactly()
    {
        foreach (LandBlockEntry sample in TerrainTestData.Sample)
        {
            LandBlockEntry fromImage = TerrainTestData.Image.GetLandBlockEntry((int)(sample.Id >> 24), (int)((sample.Id >> 16) & 0xFF));
            Assert.Equal(sample.Id, fromImage.Id);
            Assert.Equal(sample.Height.ToArray(), fromImage.Height.ToArray());
            Assert.Equal(sample.Terrain.ToArray(), fromImage.Terrain.ToArray());
        }
    }

    [TerrainDataFact]
    public void WholeWorld_NeighbouringLandblocksShareTheirEdgeVertices()
    {
        // Every pair of neighbouring landblocks built from terrain.png repeats the same 9 edge vertices.
        TerrainImage img = TerrainTestData.Image;
        for (int bx = 0; bx < 254; bx += 7)
        {
            for (int by = 0; by < 254; by += 5)
            {
                LandBlockEntry a = img.GetLandBlockEntry(bx, by);
                LandBlockEntry e = img.GetLandBlockEntry(bx + 1, by);
                LandBlockEntry n = img.GetLandBlockEntry(bx, by + 1);
                for (int k = 0; k < 9; k++)
                {
                    Assert.Equal(a.Height[8 * 9 + k], e.Height[k]);
                    Assert.Equal(a.Height[k * 9 + 8], n.Height[k * 9]);
                }
            }
        }
    }

    [TerrainDataFact]
    public void WalkingAcrossHoltburg_HeightQueryNeverFailsInsideTheLoadedBlocks()
    {
        // A straight line from the SW corner of 0xA8B3 to the NE corner of 0xAAB5, sampled every 0.37 m in global
        // coordinates: every sample resolves a cell and a triangle, including exact cell and landblock edges.
        uint[] ids = [0xA8B3FFFFu, 0xA8B4FFFFu, 0xA8B5FFFFu, 0xA9B3FFFFu, 0xA9B4FFFFu, 0xA9B5FFFFu, 0xAAB3FFFFu, 0xAAB4FFFFu, 0xAAB5FFFFu];
        TerrainWorld world = TerrainTestData.SampleWorld(ids);
        double x0 = 0xA8 * 192.0, y0 = 0xB3 * 192.0;
        for (double s = 0; s < 576.0; s += 0.37)
        {
            Assert.True(world.TryGetTerrainHeight(x0 + s, y0 + s, out float z));
            Assert.InRange(z, 0f, 800f);
        }

        Assert.True(world.TryGetTerrainHeight(x0 + 192.0, y0 + 192.0, out _));   // exact block corner
        Assert.False(world.TryGetTerrainHeight(x0 + 576.0, y0 + 10.0, out _));   // next block not loaded
    }
}
