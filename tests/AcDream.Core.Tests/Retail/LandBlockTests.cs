using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class LandBlockTests
{
    private static readonly LandHeightTable Table = TerrainTestData.IdentityTable();

    [Fact]
    public void Vertices_AreOn24mGridWithTableHeights_IndexXMajor()
    {
        // Height index = 10 * vx + vy, and the test table maps index i to i metres.
        var block = new LandBlock(0x9AB1FFFFu, TerrainTestData.Heights((vx, vy) => 10 * vx + vy), TerrainTestData.Terrain(1), Table);
        // Vertex (vx = 3, vy = 5) is index 3 * 9 + 5 = 32 at (72, 120, 35).
        Assert.Equal(new Vector3(72f, 120f, 35f), block.Vertices[32]);
        Assert.Equal(new Vector3(0f, 0f, 0f), block.Vertices[0]);
        Assert.Equal(new Vector3(192f, 192f, 88f), block.Vertices[80]);
        Assert.Equal(0x9A, block.BlockX);
        Assert.Equal(0xB1, block.BlockY);
    }

    [Fact]
    public void Cells_IdsOriginsAndIndexing()
    {
        var block = new LandBlock(0x9AB1FFFFu, new byte[81], TerrainTestData.Terrain(1), Table);
        // Cell (x = 3, y = 5): low word 3 * 8 + 5 + 1 = 30 = 0x1E; centre ((2*3+1)*12, (2*5+1)*12) = (84, 132).
        LandCell c = block.GetCell(3, 5);
        Assert.Equal(0x9AB1001Eu, c.Id);
        Assert.Equal(new Vector3(84f, 132f, 0f), c.Origin);
        Assert.Same(c, block.Cells[3 * 8 + 5]);
        Assert.Same(c, block.GetLandCell(0x9AB1001Eu));
        Assert.Null(block.GetLandCell(0x9AB2001Eu));   // another block
        Assert.Null(block.GetLandCell(0x9AB10100u));   // indoor
        Assert.Same(block, c.LandBlock);
    }

    [Fact]
    public void AllTriangles_AreCounterClockwise_NormalsUp()
    {
        var rnd = new Random(5);
        var block = new LandBlock(0x4B2FFFFFu, TerrainTestData.Heights((_, _) => rnd.Next(256)), TerrainTestData.Terrain(1), Table);
        foreach (Polygon p in block.Polygons)
        {
            Assert.True(p.Plane.N.Z > 0f);
            Assert.Equal(3, p.NumPoints);
        }
    }

    [Fact]
    public void FindTerrainPoly_CoversTheCellAndRejectsOutside()
    {
        var block = new LandBlock(0x0000FFFFu, new byte[81], TerrainTestData.Terrain(1), Table);
        LandCell c = block.GetCell(0, 0); // SW-NE cut
        Assert.True(c.FindTerrainPoly(new Vector3(20f, 4f, 0f), out Polygon? p0));
        Assert.Same(c.Polygon0, p0);
        Assert.True(c.FindTerrainPoly(new Vector3(4f, 20f, 0f), out Polygon? p1));
        Assert.Same(c.Polygon1, p1);
        // On the diagonal both match; polygons[0] wins.
        Assert.True(c.FindTerrainPoly(new Vector3(12f, 12f, 0f), out Polygon? pd));
        Assert.Same(c.Polygon0, pd);
        Assert.False(c.FindTerrainPoly(new Vector3(24.01f, 3f, 0f), out Polygon? none));
        Assert.Null(none);
        Assert.True(c.PointInCell(new Vector3(24f, 24f, 0f)));
    }

    [Fact]
    public void Water_CellTypesAndDepths_ByNearestCorner()
    {
        // Grass (type 1) everywhere; vertex (3, 4) water (type 16): it is the NE corner of cell (2, 3).
        ushort[] t = TerrainTestData.Terrain(1);
        TerrainTestData.SetType(t, 3, 4, 16);
        // Cell (5, 5) entirely water: corners (5,5) (6,5) (5,6) (6,6).
        TerrainTestData.SetType(t, 5, 5, 17);
        TerrainTestData.SetType(t, 6, 5, 18);
        TerrainTestData.SetType(t, 5, 6, 19);
        TerrainTestData.SetType(t, 6, 6, 20);
        var block = new LandBlock(0x1020FFFFu, new byte[81], t, Table);

        LandCell c = block.GetCell(2, 3);
        Assert.Equal(WaterType.PartiallyWater, c.WaterType);
        Assert.Equal(WaterType.PartiallyWater, block.GetCell(3, 4).WaterType); // (3,4) is its SW corner
        Assert.Equal(WaterType.NotWater, block.GetCell(0, 0).WaterType);
        Assert.Equal(WaterType.EntirelyWater, block.GetCell(5, 5).WaterType);
        Assert.Equal(WaterType.PartiallyWater, block.WaterType);
        Assert.Equal(WaterType.PartiallyWater, c.BlockWaterType);

        // Cell (2, 3) spans x 48..72, y 72..96; centre lines x = 60, y = 84.
        Assert.Equal(0.45f, c.GetWaterDepth(new Vector3(68f, 92f, 0f)));  // NE quadrant: water corner
        Assert.Equal(0.1f, c.GetWaterDepth(new Vector3(52f, 76f, 0f)));   // SW quadrant: solid corner
        Assert.Equal(0.1f, c.GetWaterDepth(new Vector3(60f, 92f, 0f)));   // x on the centre line -> west (NW, solid)
        Assert.Equal(0.1f, c.GetWaterDepth(new Vector3(68f, 84f, 0f)));   // y on the centre line -> south (SE, solid)
        Assert.Equal(0.45f, c.GetWaterDepth(new Vector3(60.0001f, 84.0001f, 0f)));
        Assert.Equal(0.9f, block.GetCell(5, 5).GetWaterDepth(new Vector3(130f, 130f, 0f)));
        Assert.Equal(0f, block.GetCell(0, 0).GetWaterDepth(new Vector3(12f, 12f, 0f)));
        Assert.Equal(16, block.GetTerrain(c.Id, new Vector3(68f, 92f, 0f)));
        Assert.Equal(1, block.GetTerrain(c.Id, new Vector3(52f, 92f, 0f)));
    }

    [Fact]
    public void Water_AllWaterBlock_IsEntirelyWater()
    {
        var block = new LandBlock(0x1020FFFFu, new byte[81], TerrainTestData.Terrain(16), Table);
        Assert.Equal(WaterType.EntirelyWater, block.WaterType);
        var dry = new LandBlock(0x1020FFFFu, new byte[81], TerrainTestData.Terrain(0), Table);
        Assert.Equal(WaterType.NotWater, dry.WaterType);
    }

    [Fact]
    public void WaterDepthConstants_RetailValuesAndBits()
    {
        // 0.89999998 (0.9f), 0.44999999 (0.45f), 0.1 (acclient.c:347232, 353645).
        Assert.Equal(0x3F666666, BitConverter.SingleToInt32Bits(LandCell.EntirelyWaterDepth));
        Assert.Equal(0x3EE66666, BitConverter.SingleToInt32Bits(LandBlock.PartialWaterDepthWaterCorner));
        Assert.Equal(0x3DCCCCCD, BitConverter.SingleToInt32Bits(LandBlock.PartialWaterDepthSolidCorner));
    }

    [Theory]
    [InlineData(16, SurfChar.Water)]
    [InlineData(20, SurfChar.Water)]
    [InlineData(15, SurfChar.Solid)]
    [InlineData(21, SurfChar.Solid)]
    [InlineData(0, SurfChar.Solid)]
    [InlineData(31, SurfChar.Solid)]
    public void TerrainSurfChar_Types16To20AreWater(int type, SurfChar expected) =>
        Assert.Equal(expected, TerrainTypes.SurfCharOf(type));

    [Fact]
    public void TerrainWord_Packing()
    {
        // road 2, type 13, scene 5: 2 | 13 << 2 | 5 << 11 = 2 + 52 + 10240 = 10294.
        ushort w = TerrainTypes.MakeWord(2, 13, 5);
        Assert.Equal(10294, w);
        Assert.Equal(13, TerrainTypes.TypeOf(w));
        Assert.Equal(2, TerrainTypes.RoadOf(w));
        Assert.Equal(5, TerrainTypes.SceneOf(w));
    }

    [Fact]
    public void LandLimits_MaxPlus200MinMinus1()
    {
        var block = new LandBlock(0x1020FFFFu, TerrainTestData.Heights((vx, vy) => 30 + vx + vy), TerrainTestData.Terrain(1), Table);
        Assert.Equal(46f + 200f, block.MaxZval);   // max index 30 + 8 + 8
        Assert.Equal(30f - 1f, block.MinZval);
    }

    [Fact]
    public void Constructor_BadInput_Throws()
    {
        Assert.Throws<ArgumentException>(() => new LandBlock(0x9AB1u, new byte[81], new ushort[81], Table));       // not 0xXXYYFFFF
        Assert.Throws<ArgumentException>(() => new LandBlock(0xFF10FFFFu, new byte[81], new ushort[81], Table));   // column 255
        Assert.Throws<ArgumentException>(() => new LandBlock(0x1010FFFFu, new byte[80], new ushort[81], Table));
        Assert.Throws<ArgumentException>(() => new LandBlock(0x1010FFFFu, new byte[81], new ushort[82], Table));
        Assert.Throws<ArgumentNullException>(() => new LandBlock(0x1010FFFFu, new byte[81], new ushort[81], null!));
        Assert.Throws<ArgumentException>(() => new LandBlock(0x1010FFFFu, new byte[81], new ushort[81], Table).CalcWaterDepth(0x10100100u, Vector3.Zero));
    }

    [Fact]
    public void HeightTable_RetailValidation()
    {
        Assert.Throws<ArgumentException>(() => new LandHeightTable(new float[255]));
        var h = new float[256];
        h[7] = 800.5f;   // above 1000 - 200
        Assert.Throws<ArgumentException>(() => new LandHeightTable(h));
        h[7] = -0.5f;
        Assert.Throws<ArgumentException>(() => new LandHeightTable(h));
        h[7] = float.NaN;
        Assert.Throws<ArgumentException>(() => new LandHeightTable(h));
        h[7] = 800f;     // the bound itself is accepted
        Assert.Equal(800f, new LandHeightTable(h)[7]);
        Assert.Equal(800f, LandHeightTable.MaxHeight);
    }
}
