using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>Positions at 0, just under 192, exactly 192, -0.0 and -1e-7 land in the right cell and landblock.</summary>
public class CellCoordinatesAtEdgesTests
{
    private const uint Block = 0xA9B40000u; // lcoord origin (1352, 1440)

    [Theory]
    // x, expected cell id, expected local x. Row 0 (y = 10) so cell = column * 8 + 1.
    [InlineData(0f, 0xA9B40001u, 0f)]               // the west edge belongs to this block
    [InlineData(191.99998f, 0xA9B40039u, 191.99998f)] // floor(7.9999992) = 7 -> column 7 -> cell 57
    [InlineData(192f, 0xAAB40001u, 0f)]             // exactly 192 belongs to the eastern neighbour, x wraps to 0
    [InlineData(-1e-7f, 0xA9B40001u, 0f)]           // within EPSILON: snapped to 0, stays
    [InlineData(-0.0003f, 0xA8B40039u, 191.9997f)]  // beyond EPSILON: western neighbour, column 7
    public void AdjustToOutside_AtBlockEdgesInX(float x, uint expectedCell, float expectedX)
    {
        uint id = Block | 1u;
        var loc = new Vector3(x, 10f, 0f);
        Assert.True(LandDefs.AdjustToOutside(ref id, ref loc));
        Assert.Equal(expectedCell, id);
        Assert.Equal(expectedX, loc.X);
        if (expectedX == 0f)
        {
            // Retail writes the integer 0, a positive zero.
            Assert.Equal(0, System.BitConverter.SingleToInt32Bits(loc.X));
        }
    }

    [Theory]
    [InlineData(0f, 0xA9B40001u)]
    [InlineData(191.99998f, 0xA9B40008u)] // row 7 -> cell 8
    [InlineData(192f, 0xA9B50001u)]
    [InlineData(-1e-7f, 0xA9B40001u)]
    public void AdjustToOutside_AtBlockEdgesInY(float y, uint expectedCell)
    {
        uint id = Block | 1u;
        var loc = new Vector3(10f, y, 0f);
        Assert.True(LandDefs.AdjustToOutside(ref id, ref loc));
        Assert.Equal(expectedCell, id);
        Assert.InRange(loc.Y, 0f, 191.99999f);
    }

    [Fact]
    public void AdjustToOutside_NegativeZero_SnapsToPositiveZeroInBothAxes()
    {
        // -0.0 is within EPSILON of 0: retail writes the integer 0 (a positive zero) and the cell stays.
        uint id = Block | 1u;
        var loc = new Vector3(-0.0f, -0.0f, 0f);
        Assert.True(LandDefs.AdjustToOutside(ref id, ref loc));
        Assert.Equal(Block | 1u, id);
        Assert.Equal(0, System.BitConverter.SingleToInt32Bits(loc.X));
        Assert.Equal(0, System.BitConverter.SingleToInt32Bits(loc.Y));
    }

    [Fact]
    public void WalkerCrossingLandblockCorner_VisitsEachNeighbourConsistently()
    {
        // Walk diagonally north-east through the corner (192, 192) of block 0xA9B4 in 1 cm steps; after every step the
        // global position (block origin + local) must equal the start plus the distance walked. Each float addition near
        // 128..256 m rounds by at most half a spacing (2^-17 / 2 * 2 = 1.53e-5 m), so after 400 steps the drift is at most
        // 400 * 1.53e-5 = 6.1e-3 m; the re-homing itself adds nothing (192 is exact). Bound 6.2e-3 m.
        var p = new Position(Block | 0x40u, new Vector3(190f, 190f, 0f));
        double startGX = 1352 * 24.0 + 190.0, startGY = 1440 * 24.0 + 190.0;
        for (int i = 1; i <= 400; i++)
        {
            p.Frame.Origin += new Vector3(0.01f, 0.01f, 0f);
            Assert.True(p.TryAdjustToOutside());
            Assert.True(LandDefs.GidToLCoord(p.ObjCellId, out int lx, out int ly));
            double gx = (lx & ~7) * 24.0 + p.Frame.Origin.X;
            double gy = (ly & ~7) * 24.0 + p.Frame.Origin.Y;
            Assert.True(Math.Abs(gx - (startGX + 0.01 * i)) < 6.2e-3, $"step {i}: x {gx}");
            Assert.True(Math.Abs(gy - (startGY + 0.01 * i)) < 6.2e-3, $"step {i}: y {gy}");
            // The cell's column/row agrees with the local coordinate.
            Assert.Equal((int)(p.Frame.Origin.X / 24f), lx & 7);
            Assert.Equal((int)(p.Frame.Origin.Y / 24f), ly & 7);
        }

        // 4 m past the corner: block 0xAAB5, cell 1.
        Assert.Equal(0xAAB50001u, p.ObjCellId);
    }

    [Fact]
    public void WorldEdge_IsRefusedWithoutLosingThePosition()
    {
        var p = new Position(0xFEFE0040u, new Vector3(191.9f, 191.9f, 0f));
        p.Frame.Origin += new Vector3(0.2f, 0f, 0f);
        Position before = p;
        Assert.False(p.TryAdjustToOutside());
        Assert.Equal(before, p);
    }
}
