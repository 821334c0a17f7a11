using System;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Bsp;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class BspConstantsTests
{
    [Fact]
    public void CellSphereMargin_Is0Point01_AsRetailsFloat()
    {
        // BSPNODE::sphere_intersects_cell_bsp (acclient.c:362979) adds 0.0099999998 (the float nearest 0.01) to the radius.
        Assert.Equal(0.0099999998f, BspTree.CellSphereMargin);
        Assert.Equal(0x3C23D70A, BitConverter.SingleToInt32Bits(BspTree.CellSphereMargin));
    }

    [Fact]
    public void PlacementAndAdjustLimits_AreRetails()
    {
        // BSPTREE::placement_insert loops while i < 20 (acclient.c:360778); adjust_to_plane stops at 15 iterations and a
        // time bracket under 0.02 (acclient.c:360915).
        Assert.Equal(20, BspTree.MaxPlacementRounds);
        Assert.Equal(15, BspTree.MaxAdjustIterations);
        Assert.Equal(0.02, BspTree.AdjustTimeTolerance);
        Assert.Equal(0x3F947AE147AE147BL, BitConverter.DoubleToInt64Bits(BspTree.AdjustTimeTolerance));
    }

    [Theory]
    // The tags BSPNODE::UnPack compares (acclient.c:363185): 1112557902, +32, +9440, 1112567406, 1114655054, 1114664526;
    // 'LEAF' 1279607110 and 'PORT' 1347375700 (BSPNODE::pack_child_size, acclient.c:363290).
    [InlineData(BspNodeType.SplitBothChildren, 1112557902u, "BPIN")]
    [InlineData(BspNodeType.SplitPositiveChild, 1112557934u, "BPIn")]
    [InlineData(BspNodeType.SplitBothChildrenUnmarked, 1112567374u, "BPnN")]
    [InlineData(BspNodeType.SplitPositiveChildUnmarked, 1112567406u, "BPnn")]
    [InlineData(BspNodeType.SplitNegativeChild, 1114655054u, "BpIN")]
    [InlineData(BspNodeType.SplitNegativeChildUnmarked, 1114664526u, "BpnN")]
    [InlineData(BspNodeType.Leaf, 1279607110u, "LEAF")]
    [InlineData(BspNodeType.Portal, 1347375700u, "PORT")]
    public void NodeTypeTags_AreRetailsFourCharacterCodes(BspNodeType type, uint value, string tag)
    {
        Assert.Equal(value, (uint)type);
        uint v = (uint)type;
        string decoded = new(new[] { (char)(v >> 24), (char)((v >> 16) & 0xFF), (char)((v >> 8) & 0xFF), (char)(v & 0xFF) });
        Assert.Equal(tag, decoded);
    }

    [Fact]
    public void OutsidePortalId_IsMinusOne()
    {
        // CCellPortal::UnPack (acclient.c:362346): flag 4 stores other_cell_id = -1.
        Assert.Equal(0xFFFFFFFFu, CellPortal.OutsideCellId);
    }
}
