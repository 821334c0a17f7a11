using System.Numerics;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class LandDefsTests
{
    [Fact]
    public void CellId_Encoding_RoundTripsThroughLCoord()
    {
        // Landblock 0xA9B4, cell column 3, row 5: cell = 3 * 8 + 5 + 1 = 30 = 0x1E.
        // lcoord x = 0xA9 * 8 + 3 = 169 * 8 + 3 = 1355; y = 0xB4 * 8 + 5 = 180 * 8 + 5 = 1445.
        Assert.True(LandDefs.GidToLCoord(0xA9B4001Eu, out int x, out int y));
        Assert.Equal(1355, x);
        Assert.Equal(1445, y);
        Assert.Equal(0xA9B4001Eu, LandDefs.LCoordToGid(1355, 1445));
    }

    [Fact]
    public void LCoordToGid_OutsideWorld_IsZero()
    {
        Assert.Equal(0u, LandDefs.LCoordToGid(-1, 0));
        Assert.Equal(0u, LandDefs.LCoordToGid(0, 2040));
        Assert.Equal(0x00000001u, LandDefs.LCoordToGid(0, 0));
        // The north-east-most cell: block 0xFE, column 7, row 7 -> cell 64.
        Assert.Equal(0xFEFE0040u, LandDefs.LCoordToGid(2039, 2039));
    }

    [Fact]
    public void InboundValidCellId_AcceptsOutdoorIndoorAndBlock_RejectsOthers()
    {
        Assert.True(LandDefs.InboundValidCellId(0xA9B40001u));
        Assert.True(LandDefs.InboundValidCellId(0xA9B40040u));
        Assert.True(LandDefs.InboundValidCellId(0xA9B40100u));
        Assert.True(LandDefs.InboundValidCellId(0xA9B4FFFFu));
        Assert.False(LandDefs.InboundValidCellId(0xA9B40000u));
        Assert.False(LandDefs.InboundValidCellId(0xA9B40041u));
        Assert.False(LandDefs.InboundValidCellId(0xA9B4FFFEu));
        // Block column 0xFF is past the world (0xFF * 8 = 2040).
        Assert.False(LandDefs.InboundValidCellId(0xFF000001u));
    }

    [Theory]
    [InlineData(0xA9B40001u, 0xAAB40001u, 192f, 0f)]     // one block east
    [InlineData(0xA9B40001u, 0xA8B40001u, -192f, 0f)]    // one block west
    [InlineData(0xA9B40001u, 0xA9B50001u, 0f, 192f)]     // one block north
    [InlineData(0xA9B40001u, 0xA9B30001u, 0f, -192f)]    // one block south
    [InlineData(0xA9B40001u, 0xA8B50040u, -192f, 192f)]  // north-west diagonal
    [InlineData(0xA9B40001u, 0xA9B40040u, 0f, 0f)]       // same block, other cell
    [InlineData(0xA9B40001u, 0xA9B40105u, 0f, 0f)]       // same block, indoor cell
    [InlineData(0x10200001u, 0x12230001u, 384f, 576f)]   // two east (2 * 192), three north (3 * 192)
    public void GetBlockOffset_IsWholeBlocksTimes192(uint from, uint to, float dx, float dy)
    {
        Assert.Equal(new Vector3(dx, dy, 0f), LandDefs.GetBlockOffset(from, to));
    }

    [Fact]
    public void AdjustToOutside_XJustWestOfBlock_MovesToWesternNeighbourCell57()
    {
        // x = -0.04 in block 0xA9B4: lcoord x = 169 * 8 + floor(-0.04 / 24) = 1352 - 1 = 1351 -> block 0xA8, column 7.
        // y = 10: row 0. cell = 7 * 8 + 0 + 1 = 57 = 0x39. x wraps to -0.04 + 192 = 191.96.
        uint id = 0xA9B40001u;
        var loc = new Vector3(-0.04f, 10f, 5f);
        Assert.True(LandDefs.AdjustToOutside(ref id, ref loc));
        Assert.Equal(0xA8B40039u, id);
        Assert.Equal(191.96f, loc.X);
        Assert.Equal(10f, loc.Y);
        Assert.Equal(5f, loc.Z);
    }

    [Fact]
    public void AdjustToOutside_YJustNorthOfBlock_MovesToNorthernNeighbourCell1()
    {
        // y = 192.08: lcoord y = 180 * 8 + floor(192.08 / 24) = 1440 + 8 = 1448 -> block 0xB5, row 0; x = 10: column 0.
        // y wraps to 192.08f - 192 = 0.0800018310546875 (192.08f is 192.08000183105469).
        uint id = 0xA9B40001u;
        var loc = new Vector3(10f, 192.08f, 0f);
        Assert.True(LandDefs.AdjustToOutside(ref id, ref loc));
        Assert.Equal(0xA9B50001u, id);
        Assert.Equal(0.0800018310546875f, loc.Y);
    }

    [Fact]
    public void AdjustToOutside_WithinEpsilonOfZero_SnapsToZeroAndStaysInBlock()
    {
        // |x| < EPSILON is snapped to 0 before the cell is found, so -0.0001 stays in the same block.
        uint id = 0xA9B40001u;
        var loc = new Vector3(-0.0001f, 30f, 0f);
        Assert.True(LandDefs.AdjustToOutside(ref id, ref loc));
        Assert.Equal(0f, loc.X);
        // y = 30: row 1 -> cell 0 * 8 + 1 + 1 = 2.
        Assert.Equal(0xA9B40002u, id);
    }

    [Fact]
    public void AdjustToOutside_PastWorldEdge_FailsAndZeroesCellIdAsRetail()
    {
        // Block 0xFE is the last column: 254 * 8 + floor(192.5 / 24) = 2032 + 8 = 2040, past the 2040-cell world.
        uint id = 0xFE100001u;
        var loc = new Vector3(192.5f, 10f, 0f);
        Assert.False(LandDefs.AdjustToOutside(ref id, ref loc));
        Assert.Equal(0u, id);

        uint west = 0x00100001u;
        var westLoc = new Vector3(-1f, 10f, 0f);
        Assert.False(LandDefs.AdjustToOutside(ref west, ref westLoc));
        Assert.Equal(0u, west);
    }

    [Fact]
    public void TryAdjustToOutside_PastWorldEdge_LeavesPositionUnchanged()
    {
        var p = new Position(0xFE100001u, new Vector3(192.5f, 10f, 3f));
        Position before = p;
        Assert.False(p.TryAdjustToOutside());
        Assert.Equal(before, p);
    }

    [Fact]
    public void WithinBlock_RequiresRadiusClearanceFromEveryEdge()
    {
        Assert.True(LandDefs.WithinBlock(new Vector3(1f, 1f, 0f), 0.5f));
        Assert.False(LandDefs.WithinBlock(new Vector3(0.4f, 1f, 0f), 0.5f));
        Assert.False(LandDefs.WithinBlock(new Vector3(191.6f, 1f, 0f), 0.5f)); // 192 - 0.5 = 191.5 < 191.6
    }
}
