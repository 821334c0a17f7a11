using System;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>LandDefs.OutdoorCellId: the outdoor cell of a landblock-local point, 0xXXYY0000 | (cx · 8 + cy + 1) with cx, cy the
/// 24 m cell column and row (docs/terrain.md).</summary>
public sealed class OutdoorCellIdTests
{
    [Theory]
    [InlineData(0xA9B4FFFFu, 100f, 100f, 0xA9B40025u)]   // cx = cy = 4: 4 * 8 + 4 + 1 = 37 = 0x25 (the quickstart's cell)
    [InlineData(0xA9B4FFFFu, 0f, 0f, 0xA9B40001u)]       // south-west corner: cell 1
    [InlineData(0xA9B4FFFFu, 23.999998f, 0f, 0xA9B40001u)] // the last float of column 0
    [InlineData(0xA9B4FFFFu, 24f, 0f, 0xA9B40009u)]      // column 1, row 0: 1 * 8 + 0 + 1 = 9
    [InlineData(0xA9B4FFFFu, 0f, 24f, 0xA9B40002u)]      // column 0, row 1: 2
    [InlineData(0xA9B4FFFFu, 191.99998f, 191.99998f, 0xA9B40040u)] // north-east corner: 7 * 8 + 7 + 1 = 64 = 0x40
    [InlineData(0x00000000u, 60f, 40f, 0x00000012u)]     // block 0x0000: column 2, row 1: 16 + 1 + 1 = 18 = 0x12
    [InlineData(0xFEFE0123u, 12f, 180f, 0xFEFE0008u)]    // the last landblock; the low word is ignored: row 7: 8
    public void OutdoorCellId_IsTheCellUnderThePoint(uint block, float x, float y, uint expected)
    {
        Assert.Equal(expected, LandDefs.OutdoorCellId(block, x, y));
        // Retail's own numbering agrees: lcoord_to_gid of the point's global cell coordinates.
        int bx = (int)(block >> 24), by = (int)((block >> 16) & 0xFF);
        Assert.Equal(LandDefs.LCoordToGid(bx * 8 + (int)(x / 24f), by * 8 + (int)(y / 24f)), expected);
    }

    [Theory]
    [InlineData(0xFFB4FFFFu, 10f, 10f, "landblockId")]
    [InlineData(0xA9FFFFFFu, 10f, 10f, "landblockId")]
    [InlineData(0xA9B4FFFFu, -0.001f, 10f, "x")]
    [InlineData(0xA9B4FFFFu, 192f, 10f, "x")]
    [InlineData(0xA9B4FFFFu, float.NaN, 10f, "x")]
    [InlineData(0xA9B4FFFFu, 10f, float.PositiveInfinity, "y")]
    [InlineData(0xA9B4FFFFu, 10f, 200f, "y")]
    public void OutdoorCellId_OutsideTheWorldOrTheBlock_Throws(uint block, float x, float y, string param)
    {
        var e = Assert.Throws<ArgumentOutOfRangeException>(() => LandDefs.OutdoorCellId(block, x, y));
        Assert.Equal(param, e.ParamName);
    }
}
