using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// The landscape grid's arithmetic, from the decompilation: <c>LScape::get_block_shift</c> (acclient.c:306318),
/// <c>get_block_orient</c> (306680) and <c>LandDefs::get_block_did</c> (306907).
/// </summary>
public class LandscapeGridTests
{
    [Fact]
    public void TheDefaultMidRadius_IsTheLScapeConstructors()
    {
        // LScape::LScape (acclient.c:306925): mid_radius = 5, mid_width = 11.
        Assert.Equal(5, Landscape.DefaultMidRadius);
        Landscape l = LandscapeEntries.Landscape(LandscapeEntries.Source(), out _, out _, radius: Landscape.DefaultMidRadius);
        Assert.Equal(11, l.MidWidth);
    }

    [Theory]
    // (0xA9B4, 0xAAB4): x (cell_id >> 21) & 0x7F8 = 0xA9 * 8 -> 0xAA * 8, one block east.
    [InlineData(0xA9B4001Cu, 0xAAB40001u, 1, 0)]
    [InlineData(0xA9B4001Cu, 0xA9B30040u, 0, -1)]
    [InlineData(0xA9B4001Cu, 0xA7B70105u, -2, 3)]
    // cell_id2 0 counts as block (0, 0).
    [InlineData(0x0203001Cu, 0u, -2, -3)]
    public void GetBlockShift_IsTheBlockDifference(uint from, uint to, int x, int y)
    {
        Assert.True(Landscape.GetBlockShift(from, to, out int xs, out int ys));
        Assert.Equal((x, y), (xs, ys));
    }

    [Fact]
    public void GetBlockShift_FromCellZero_IsNoShift_AndFalse()
    {
        Assert.False(Landscape.GetBlockShift(0u, 0xA9B4001Cu, out int xs, out int ys));
        Assert.Equal((0, 0), (xs, ys));
    }

    [Theory]
    // Radius 5 (11 × 11): the centre and its ring are size 1 (8 cells a side); ring 2 size 2; rings 3 and 4 size 4; beyond 8.
    [InlineData(5, 5, 1, LandscapeDirection.InViewerBlock)]
    [InlineData(6, 6, 1, LandscapeDirection.Northeast)]
    [InlineData(6, 4, 1, LandscapeDirection.Southeast)]
    [InlineData(6, 5, 1, LandscapeDirection.East)]
    [InlineData(4, 6, 1, LandscapeDirection.Northwest)]
    [InlineData(4, 4, 1, LandscapeDirection.Southwest)]
    [InlineData(4, 5, 1, LandscapeDirection.West)]
    [InlineData(5, 6, 1, LandscapeDirection.North)]
    [InlineData(5, 4, 1, LandscapeDirection.South)]
    [InlineData(7, 5, 2, LandscapeDirection.East)]
    [InlineData(5, 3, 2, LandscapeDirection.South)]
    [InlineData(6, 7, 2, LandscapeDirection.North)]
    // Ring 4: v = 4, so dx = 4 is the edge.
    [InlineData(9, 9, 4, LandscapeDirection.Northeast)]
    [InlineData(9, 6, 4, LandscapeDirection.East)]
    // Ring 3 is size 4 too, but compared with v = 4 it matches no edge: direction 0 (retail's quirk).
    [InlineData(8, 5, 4, LandscapeDirection.InViewerBlock)]
    [InlineData(8, 8, 4, LandscapeDirection.InViewerBlock)]
    [InlineData(10, 10, 8, LandscapeDirection.InViewerBlock)]
    [InlineData(0, 5, 8, LandscapeDirection.InViewerBlock)]
    public void GetBlockOrient_SizeAndDirection(int ix, int iy, int size, LandscapeDirection dir)
    {
        Landscape.GetBlockOrient(5, ix, iy, out int s, out LandscapeDirection d);
        Assert.Equal((size, dir), (s, d));
    }

    [Theory]
    // ((y >> 3) | 32 * (x & ~7)) << 16 | 0xFFFF: block (x / 8, y / 8).
    [InlineData(0xA9 * 8, 0xB4 * 8, 0xA9B4FFFFu)]
    [InlineData(0xA9 * 8 + 7, 0xB4 * 8 + 5, 0xA9B4FFFFu)]
    [InlineData(0, 0, 0x0000FFFFu)]
    [InlineData(2039, 2039, 0xFEFEFFFFu)]
    [InlineData(2040, 0, 0u)]
    [InlineData(0, -1, 0u)]
    public void GetBlockDid(int x, int y, uint id) => Assert.Equal(id, Landscape.GetBlockDid(x, y));
}
