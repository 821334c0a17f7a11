using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class PositionTests
{
    [Fact]
    public void GetOffset_AcrossLandblockEast_AddsBlockLength()
    {
        // a at x = 190 in 0xA9B4; b at x = 2 in 0xAAB4 (the block to the east): offset = 192 + 2 - 190 = 4.
        var a = new Position(0xA9B40039u, new Vector3(190f, 10f, 0f));
        var b = new Position(0xAAB40001u, new Vector3(2f, 10f, 1f));
        Assert.Equal(new Vector3(4f, 0f, 1f), a.GetOffset(b));
        Assert.Equal(new Vector3(-4f, 0f, -1f), b.GetOffset(a));
    }

    [Fact]
    public void GetOffset_KeepsTheXSumInDouble_AndRoundsYAndZ_AsRetail()
    {
        // acclient.c:311690: x = (192 + p.x) stays in an x87 register, y and z sums are spilled to floats.
        // x: 192 + 0.1f = 192.100000001490116 (double) - 191.9f (191.899993896484375) = 0.200006105005741 -> float 0.2000061.
        //    Rounded through float first it would be 192.1000061 - 191.8999939 = 0.2000122.
        // y: 192 + 0.1f rounds to 192.100006103515625 (float), minus 191.9f = 0.20001220703125.
        var a = new Position(0xA9B40039u, new Vector3(191.9f, 191.9f, 0f));
        var b = new Position(0xAAB50001u, new Vector3(0.1f, 0.1f, 0f));
        Vector3 off = a.GetOffset(b);
        Assert.Equal((float)(192.0 + (double)0.1f - (double)191.9f), off.X);
        Assert.Equal(0.20001220703125f, off.Y);
        Assert.NotEqual(off.Y, off.X);
    }

    [Fact]
    public void Distance_AcrossLandblockCorner_IsHypotenuse()
    {
        // a at (191, 191) in 0xA9B4; b at (2, 3) in 0xAAB5 (north-east): offset (3, 4, 0) -> 5.
        var a = new Position(0xA9B40040u, new Vector3(191f, 191f, 0f));
        var b = new Position(0xAAB50001u, new Vector3(2f, 3f, 0f));
        Assert.Equal(5f, a.Distance(b));
        Assert.Equal(5f, a.XYDistance(b));
    }

    [Fact]
    public void Heading_ToTargetDueEast_Is90_DueNorth_Is0()
    {
        var a = new Position(0xA9B40001u, new Vector3(10f, 10f, 0f));
        Assert.Equal(90.0, a.HeadingTo(new Position(0xA9B40001u, new Vector3(20f, 10f, 0f))), 9);
        Assert.Equal(0.0, a.HeadingTo(new Position(0xA9B40001u, new Vector3(10f, 20f, 0f))), 9);
        Assert.Equal(180.0, a.HeadingTo(new Position(0xA9B40001u, new Vector3(10f, 0f, 0f))), 9);
        Assert.Equal(0.0, a.HeadingTo(a));
    }

    [Fact]
    public void LocalToLocal_PointAheadOfOtherBody_InOwnFrame()
    {
        // p faces east at (2, 10) in the block east of us; its local point (0, 1, 0) is global (3, 10) there,
        // i.e. (195, 10) in our block; we are at (190, 10) facing north, so it is 5 m to our right (+X local).
        var me = new Position(0xA9B40039u, new Vector3(190f, 10f, 0f));
        var p = new Position(0xAAB40001u, Frame.FromHeading(new Vector3(2f, 10f, 0f), 90f));
        Vector3 local = me.LocalToLocal(p, new Vector3(0f, 1f, 0f));
        Assert.Equal(5f, local.X, 5);
        Assert.Equal(0f, local.Y, 5);
    }

    [Fact]
    public void CylinderDistance_SideBySideAndStacked()
    {
        // Same height range, centres 3 m apart, radii 0.5 + 0.5: 3 - 1 = 2 (radial distance only).
        var a = new Position(0xA9B40001u, new Vector3(10f, 10f, 0f));
        var b = new Position(0xA9B40001u, new Vector3(13f, 10f, 0f));
        Assert.Equal(2f, Position.CylinderDistance(0.5f, 2f, a, 0.5f, 2f, b));
        // Retail's "radial" term is the full 3-D centre distance minus the radii (acclient.c:467220), not the x-y distance.
        // c stands 3 m above a: radial = 3 - 1 = 2; vertical gap = 3 - (0 + 2) = 1; both positive -> sqrt(1² + 2²) = sqrt 5.
        var c = new Position(0xA9B40001u, new Vector3(10f, 10f, 3f));
        Assert.Equal((float)Math.Sqrt(5.0), Position.CylinderDistance(0.5f, 2f, a, 0.5f, 2f, c), 5);
        // c stands 1.5 m above a (height ranges overlap, vertical = 1.5 - 2 = -0.5): radial = 1.5 - 1 = 0.5 > 0 -> 0.5.
        var d = new Position(0xA9B40001u, new Vector3(10f, 10f, 1.5f));
        Assert.Equal(0.5f, Position.CylinderDistance(0.5f, 2f, a, 0.5f, 2f, d), 5);
        // Overlapping heights and centres 0.6 m apart (radial = 0.6 - 1 = -0.4): -sqrt(vertical² + radial²) with
        // vertical = 0 - 2 = -2 -> -sqrt(4 + 0.16).
        var e = new Position(0xA9B40001u, new Vector3(10.6f, 10f, 0f));
        Assert.Equal((float)-Math.Sqrt(4.16), Position.CylinderDistance(0.5f, 2f, a, 0.5f, 2f, e), 4);
    }

    [Fact]
    public void RelativeFrame_ExpressesOtherPositionInMyFrame_AcrossBlocks()
    {
        var me = new Position(0xA9B40039u, Frame.FromHeading(new Vector3(190f, 10f, 0f), 90f));
        var other = new Position(0xAAB40001u, Frame.FromHeading(new Vector3(2f, 10f, 0f), 90f));
        Frame rel = Position.RelativeFrame(other, me);
        // Other is 4 m east = straight ahead of an east-facing body, same heading.
        Assert.Equal(0f, rel.Origin.X, 5);
        Assert.Equal(4f, rel.Origin.Y, 5);
        Assert.Equal(0.0, Math.Min(rel.Heading, 360.0 - rel.Heading), 3);
    }

    [Fact]
    public void IsValid_NeedsValidCellAndFrame()
    {
        Assert.True(new Position(0xA9B40001u, Vector3.Zero).IsValid());
        Assert.False(new Position(0xA9B40000u, Vector3.Zero).IsValid());
    }
}
