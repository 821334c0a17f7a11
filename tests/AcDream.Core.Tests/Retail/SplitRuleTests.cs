using System;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class SplitRuleTests
{
    [Fact]
    public void SplitValue_HandWorkedCells()
    {
        // v = gy * (214614067 * gx + 1813693831) - 1109124029 * gx - 1369149221, wrapping at 2^32.
        // (0, 0): v = -1369149221 -> 2^32 - 1369149221 = 2925818075 >= 2^31 -> SW-NE cut.
        Assert.Equal(2925818075u, LandBlock.SplitValue(0, 0));
        Assert.True(LandBlock.IsSWtoNECut(0, 0));
        // (1, 0): v = -1109124029 - 1369149221 = -2478273250 -> 4294967296 - 2478273250 = 1816694046 < 2^31 -> SE-NW cut.
        Assert.Equal(1816694046u, LandBlock.SplitValue(1, 0));
        Assert.False(LandBlock.IsSWtoNECut(1, 0));
        // (0, 1): v = 1813693831 - 1369149221 = 444544610 < 2^31 -> SE-NW cut.
        Assert.Equal(444544610u, LandBlock.SplitValue(0, 1));
        Assert.False(LandBlock.IsSWtoNECut(0, 1));
    }

    [Fact]
    public void SplitValue_LandblockSouthWestCellOf0x9AB1()
    {
        // Landblock 0x9AB1: gx = 0x9A * 8 = 1232, gy = 0xB1 * 8 = 1416.
        // 214614067 * 1232 + 1813693831 = 264404530544 + 1813693831 = 266218224375.
        // v = 1416 * 266218224375 - 1109124029 * 1232 - 1369149221
        //   = 376965005715000 - 1366440803728 - 1369149221 = 375597195762051 (exact), mod 2^32 = 2305726851 >= 2^31 -> cut.
        Assert.Equal(2305726851u, LandBlock.SplitValue(1232, 1416));
        Assert.True(LandBlock.IsSWtoNECut(1232, 1416));
    }

    [Fact]
    public void SplitScale_IsTwoToMinus32_FloatBits0x2F800000()
    {
        // The decompilation prints 2.3283064e-10: the shortest decimal of float 0x2F800000 = 2^-32.
        Assert.Equal(0x2F800000, BitConverter.SingleToInt32Bits((float)LandBlock.SplitScale));
        Assert.Equal(0x2F800000, BitConverter.SingleToInt32Bits(2.3283064e-10f));
        Assert.Equal(1.0, LandBlock.SplitScale * 4294967296.0);
    }

    [Fact]
    public void SplitRule_EveryDerethCell_IsTheTopBitAndFarFromTheThreshold()
    {
        // Retail's double test equals the top bit of v. Whatever the exact scale constant or x87 precision, the threshold
        // could move by at most ~64 around 2^31; no world cell lies within 440 of it (closest: gx 657, gy 1857, v = 2^31 + 440).
        long closest = long.MaxValue;
        for (int gx = 0; gx < LandDefs.LCoordLimit; gx++)
        {
            for (int gy = 0; gy < LandDefs.LCoordLimit; gy++)
            {
                uint v = LandBlock.SplitValue(gx, gy);
                if (LandBlock.IsSWtoNECut(gx, gy) != (v >= 0x80000000u))
                {
                    Assert.Fail($"cell ({gx}, {gy})");
                }

                closest = Math.Min(closest, Math.Abs((long)v - 0x80000000L));
            }
        }

        Assert.Equal(440L, closest);
        Assert.Equal(0x80000000u + 440u, LandBlock.SplitValue(657, 1857));
    }

    [Fact]
    public void LandBlock_PolygonsFollowTheCut()
    {
        // Landblock 0x0000FFFF: cell (0,0) is global (0,0) -> SW-NE; cell (1,0) is global (1,0) -> SE-NW.
        var block = new LandBlock(0x0000FFFFu, new byte[81], new ushort[81], TerrainTestData.IdentityTable());
        Assert.True(block.IsCellSWtoNECut(0, 0));
        Assert.False(block.IsCellSWtoNECut(1, 0));

        // Cell (0,0): SW = 0, SE = 9, NE = 10, NW = 1. Cut: (SW, SE, NE), (SW, NE, NW).
        Assert.Equal(new ushort[] { 0, 9, 10 }, block.Polygons[0].VertexIds.ToArray());
        Assert.Equal(new ushort[] { 0, 10, 1 }, block.Polygons[1].VertexIds.ToArray());

        // Cell (1,0) is polygon pair 2 * (1 * 8 + 0) = 16: SW = 9, SE = 18, NE = 19, NW = 10.
        // No cut: (SW, SE, NW), (NE, NW, SE).
        Assert.Equal(new ushort[] { 9, 18, 10 }, block.Polygons[16].VertexIds.ToArray());
        Assert.Equal(new ushort[] { 19, 10, 18 }, block.Polygons[17].VertexIds.ToArray());
        Assert.Same(block.Polygons[16], block.GetCell(1, 0).Polygon0);
        Assert.Equal((short)17, block.GetCell(1, 0).Polygon1.PolyId);
    }
}
