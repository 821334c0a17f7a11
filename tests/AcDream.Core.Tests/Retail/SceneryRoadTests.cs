using System;
using AcDream.Core.Physics.Scenery;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// <c>CLandBlock::on_road</c> (acclient.c:352237), the road test of the scenery: sixteen cases of the road bits of the four
/// corners of the land cell holding the point (A south-west, B north-west, C south-east, D north-east), with the road width
/// 5 and the far bound 24 − 5 = 19. Ten are legible in the decompilation; six (the diagonals and single corners) are
/// reconstructed and must follow the symmetries of the cell that the ten follow.
/// </summary>
public class SceneryRoadTests
{
    private const int CellX = 3, CellY = 5;

    // A block whose only road bits are on the chosen corners of cell (3, 5): mask bits A = 1, B = 2, C = 4, D = 8.
    private static ushort[] Terrain(int mask)
    {
        var t = new ushort[81];
        int c = CellX * 9 + CellY;
        if ((mask & 1) != 0) t[c] = 1;       // A: vertex (3, 5)
        if ((mask & 2) != 0) t[c + 1] = 2;   // B: vertex (3, 6)
        if ((mask & 4) != 0) t[c + 9] = 3;   // C: vertex (4, 5)
        if ((mask & 8) != 0) t[c + 10] = 1;  // D: vertex (4, 6)
        for (int i = 0; i < t.Length; i++)
        {
            t[i] |= (5 << 2) | (7 << 11); // a terrain type and a scene slot: only bits 0-1 are roads
        }

        return t;
    }

    private static bool On(int mask, double dx, double dy) =>
        SceneryGenerator.OnRoad(Terrain(mask), (float)(CellX * 24 + dx), (float)(CellY * 24 + dy));

    [Theory]
    // none, all four
    [InlineData(0b0000, 12, 12, false)]
    [InlineData(0b0000, 0.1, 0.1, false)]
    [InlineData(0b1111, 12, 12, true)]
    [InlineData(0b1111, 23.9, 0.1, true)]
    // edges (legible): A B dx < 5, A C dy < 5, C D dx > 19, B D dy > 19; strict at the bound
    [InlineData(0b0011, 4.75, 12, true)]
    [InlineData(0b0011, 5, 12, false)]
    [InlineData(0b0011, 20, 12, false)]
    [InlineData(0b0101, 12, 4.75, true)]
    [InlineData(0b0101, 12, 5, false)]
    [InlineData(0b1100, 19.25, 12, true)]
    [InlineData(0b1100, 19, 12, false)]
    [InlineData(0b1010, 12, 19.25, true)]
    [InlineData(0b1010, 12, 19, false)]
    // three corners (legible): the union of the two edge strips
    [InlineData(0b0111, 4, 20, true)]
    [InlineData(0b0111, 20, 4, true)]
    [InlineData(0b0111, 12, 12, false)]
    [InlineData(0b0111, 20, 20, false)]
    [InlineData(0b1011, 4, 4, true)]
    [InlineData(0b1011, 20, 20, true)]
    [InlineData(0b1011, 20, 4, false)]
    [InlineData(0b1101, 20, 20, true)]
    [InlineData(0b1101, 4, 4, true)]
    [InlineData(0b1101, 4, 20, false)]
    [InlineData(0b1110, 20, 4, true)]
    [InlineData(0b1110, 4, 20, true)]
    [InlineData(0b1110, 4, 4, false)]
    // diagonals (reconstructed): A D |dx - dy| < 5, B C |dx + dy - 24| < 5
    [InlineData(0b1001, 12, 12, true)]
    [InlineData(0b1001, 12, 16.75, true)]
    [InlineData(0b1001, 12, 17, false)]
    [InlineData(0b1001, 4, 20, false)]
    [InlineData(0b0110, 12, 12, true)]
    [InlineData(0b0110, 4, 20, true)]
    [InlineData(0b0110, 4, 15, false)]
    [InlineData(0b0110, 4, 4, false)]
    // single corners (reconstructed): the corner's triangle of legs 5
    [InlineData(0b0001, 2, 2, true)]
    [InlineData(0b0001, 2.5, 2.5, false)]
    [InlineData(0b0010, 1, 23, true)]
    [InlineData(0b0010, 2.5, 21.5, false)]
    [InlineData(0b0100, 23, 1, true)]
    [InlineData(0b0100, 21.5, 2.5, false)]
    [InlineData(0b1000, 22, 22, true)]
    [InlineData(0b1000, 21.5, 21.5, false)]
    public void EachCase(int mask, double dx, double dy, bool onRoad) => Assert.Equal(onRoad, On(mask, dx, dy));

    private static int MirrorX(int m) => ((m & 1) << 2) | ((m & 4) >> 2) | ((m & 2) << 2) | ((m & 8) >> 2); // A<->C, B<->D
    private static int MirrorY(int m) => ((m & 1) << 1) | ((m & 2) >> 1) | ((m & 4) << 1) | ((m & 8) >> 1); // A<->B, C<->D
    private static int Transpose(int m) => (m & 9) | ((m & 2) << 1) | ((m & 4) >> 1);                      // B<->C

    [Fact]
    public void TheSixteenCases_FollowTheCellsSymmetries()
    {
        // The legible ten map onto each other under x -> 24 - x (A<->C, B<->D), y -> 24 - y (A<->B, C<->D) and x <-> y (B<->C),
        // with a strict near bound (< 5) becoming a strict far bound (> 19). The reconstruction of the other six must do the
        // same: checked over a quarter-metre grid, every mask, every symmetry.
        for (int mask = 0; mask < 16; mask++)
        {
            for (double dx = 0.25; dx < 24; dx += 0.5)
            {
                for (double dy = 0.25; dy < 24; dy += 0.5)
                {
                    bool on = On(mask, dx, dy);
                    Assert.Equal(on, On(MirrorX(mask), 24 - dx, dy));
                    Assert.Equal(on, On(MirrorY(mask), dx, 24 - dy));
                    Assert.Equal(on, On(Transpose(mask), dy, dx));
                }
            }
        }
    }

    [Fact]
    public void TheCorners_AreReadWithRowStride9()
    {
        // Only vertex (4, 5) has a road: it is C of cell (3, 5) and A of cell (4, 5).
        ushort[] t = new ushort[81];
        t[4 * 9 + 5] = 1;
        Assert.True(SceneryGenerator.OnRoad(t, 3 * 24 + 23f, 5 * 24 + 1f));  // C's triangle
        Assert.True(SceneryGenerator.OnRoad(t, 4 * 24 + 1f, 5 * 24 + 1f));   // A's triangle
        Assert.True(SceneryGenerator.OnRoad(t, 4 * 24 + 1f, 4 * 24 + 23f));  // cell (4, 4): B = vertex (4, 5)
        Assert.True(SceneryGenerator.OnRoad(t, 3 * 24 + 23f, 4 * 24 + 23f)); // cell (3, 4): D = vertex (4, 5)
        Assert.False(SceneryGenerator.OnRoad(t, 4 * 24 + 12f, 4 * 24 + 12f)); // the middle of cell (4, 4)
        Assert.False(SceneryGenerator.OnRoad(t, 5 * 24 + 1f, 5 * 24 + 1f));  // cell (5, 5): no road corner
    }

    [Fact]
    public void BadArguments_Throw()
    {
        ushort[] t = new ushort[81];
        Assert.Throws<ArgumentException>(() => SceneryGenerator.OnRoad(new ushort[80], 1f, 1f));
        Assert.Throws<ArgumentOutOfRangeException>(() => SceneryGenerator.OnRoad(t, 192f, 1f));
        Assert.Throws<ArgumentOutOfRangeException>(() => SceneryGenerator.OnRoad(t, 1f, -0.001f));
        Assert.Throws<ArgumentOutOfRangeException>(() => SceneryGenerator.OnRoad(t, float.NaN, 1f));
        Assert.Equal(5f, SceneryGenerator.RoadWidth);
    }
}
