using System;
using AcDream.Core.Physics.Scenery;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// The scenery's one hash (<see cref="SceneryHash"/>) against the decompilation: each draw of <c>get_land_scenes</c>,
/// <c>ObjectDesc::Place</c>, <c>GetObjFrame</c> and <c>ScaleObj</c> is <c>h(x, y, k)</c> with its salt, and <c>u</c> is
/// exactly <c>h · 2⁻³²</c>.
/// </summary>
public class SceneryHashTests
{
    // Vertex coordinates spread over the world (0..2040) and past it (the arithmetic wraps either way).
    private static readonly (uint X, uint Y)[] Points =
        [(0, 0), (1, 0), (0, 1), (42, 314), (1000, 1000), (1352, 1440), (2040, 2040), (7, 2033), (1999, 3), (65535, 12345)];

    [Fact]
    public void ScenePick_OfVertex42_314_Is0x7F0E8239()
    {
        // Also asserted by a third-party client (holtburger, tests/golden_decomp.rs).
        Assert.Equal(0x7F0E8239u, SceneryHash.Hash(42, 314, SceneryHash.ScenePickSalt));
    }

    [Fact]
    public void ScenePick_IsTheDecompiledExpression()
    {
        // acclient.c:352640: y * (712977289 * x + 1813693831) - 1109124029 * x + 2139937281. With salt 11257:
        // 11257 * 1360117743 = 15310845432951 = 3564 * 2^32 + 3581990007, and 3581990007 = 2^32 - 712977289;
        // 11257 * 1888038839 = 21253653210623 = 4948 * 2^32 + 2155030015, and 2^32 - 2155030015 = 2139937281.
        Assert.Equal(3581990007u, unchecked(11257u * 1360117743u));
        Assert.Equal(unchecked((uint)-712977289), unchecked(11257u * 1360117743u));
        Assert.Equal(2139937281u, unchecked(0u - 11257u * 1888038839u));
        foreach ((uint x, uint y) in Points)
        {
            uint decompiled = unchecked(y * (712977289u * x + 1813693831u) - 1109124029u * x + 2139937281u);
            Assert.Equal(decompiled, SceneryHash.Hash(x, y, SceneryHash.ScenePickSalt));
        }
    }

    [Fact]
    public void Quadrant_IsTheDecompiledExpression_WithoutTheObjectIndex()
    {
        // acclient.c:462630 (ObjectDesc::Place): 1813693831 * y - x * (1870387557 * y + 1109124029) - 402451965.
        // 59371 * 1360117743 = 80751550620453 = 18801 * 2^32 + 1870387557; 59371 * 1888038839 mod 2^32 = 402451965.
        Assert.Equal(1870387557u, unchecked(59371u * 1360117743u));
        Assert.Equal(402451965u, unchecked(59371u * 1888038839u));
        foreach ((uint x, uint y) in Points)
        {
            uint decompiled = unchecked(1813693831u * y - x * (1870387557u * y + 1109124029u) - 402451965u);
            Assert.Equal(decompiled, SceneryHash.Hash(x, y, SceneryHash.QuadrantSalt));
        }
    }

    [Fact]
    public void Frequency_IsTheStrengthReducedLoop_OfSalt23399PlusK()
    {
        // acclient.c:352659-352731: v38 = 1360117743*x*y + 1888038839; draw = -1109124029*x + 1813693831*y - v17, with
        // v17 = 23399 * v38 for object 0 and v17 += v38 for each next object.
        foreach ((uint x, uint y) in Points)
        {
            uint v38 = unchecked(1360117743u * x * y + 1888038839u);
            uint v17 = unchecked(23399u * v38);
            for (uint k = 0; k < 40; k++)
            {
                uint draw = unchecked(0u - 1109124029u * x + 1813693831u * y - v17);
                Assert.Equal(draw, SceneryHash.Hash(x, y, SceneryHash.FrequencySalt + k));
                v17 = unchecked(v17 + v38);
            }
        }
    }

    [Fact]
    public void PlaceFrameAndScale_UseTheirSaltsPlusK()
    {
        // ObjectDesc::Place (462604) (iq + 45773), (iq + 72719); GetObjFrame (462659) (k + 63127); ScaleObj (351360) (k + 32593):
        // each 1813693831*y - (salt + k) * (1360117743*y*x + 1888038839) - 1109124029*x.
        Assert.Equal(45773u, SceneryHash.DisplaceXSalt);
        Assert.Equal(72719u, SceneryHash.DisplaceYSalt);
        Assert.Equal(63127u, SceneryHash.HeadingSalt);
        Assert.Equal(32593u, SceneryHash.ScaleSalt);
        Assert.Equal(23399u, SceneryHash.FrequencySalt);
        foreach ((uint x, uint y) in Points)
        {
            for (uint k = 0; k < 5; k++)
            {
                foreach (uint salt in new[] { 45773u, 72719u, 63127u, 32593u })
                {
                    uint written = unchecked(1813693831u * y - (k + salt) * (1360117743u * y * x + 1888038839u) - 1109124029u * x);
                    Assert.Equal(written, SceneryHash.Hash(x, y, salt + k));
                }
            }
        }
    }

    [Fact]
    public void Unit_IsExactlyTwoToTheMinus32()
    {
        // The decompilation's 2.3283064e-10 is the float 0x2F800000 = 2^-32 exactly.
        Assert.Equal(0x2F800000, BitConverter.SingleToInt32Bits(2.3283064e-10f));
        Assert.Equal((double)2.3283064e-10f, Math.ScaleB(1.0, -32));
        Assert.Equal(SceneryHash.UnitScale, Math.ScaleB(1.0, -32));
        Assert.Equal(0x7F0E8239 * Math.ScaleB(1.0, -32), SceneryHash.Unit(42, 314, SceneryHash.ScenePickSalt));
        Assert.True(SceneryHash.Unit(0, 0, 0) < 1.0);
        Assert.True(uint.MaxValue * SceneryHash.UnitScale < 1.0); // u < 1 always
    }

    [Theory]
    // The research note's golden table (world-from-data.md §1.4), worked out by hand from the formula.
    [InlineData(42u, 314u, 0x7F0E8239u, 0.500408501, 0.5521346812602133, 0.8297583453822881, 0.4336220824625343, 0.35210214206017554, 0.8996555951889604)]
    [InlineData(1000u, 1000u, 0x813A0B51u, 0.41295885, 0.6743260135408491, 0.6727740031201392, 0.43840283690951765, 0.7516358739230782, 0.95922552770935)]
    [InlineData(1352u, 1440u, 0x4B261039u, 0.664703502, 0.0892961376812309, 0.2125076458323747, 0.03989914036355913, 0.9130561540368944, 0.4295547769870609)]
    public void GoldenValues(uint x, uint y, uint pick, double quadrant, double freq, double dx, double dy, double scale, double heading)
    {
        Assert.Equal(pick, SceneryHash.Hash(x, y, SceneryHash.ScenePickSalt));
        Assert.Equal(quadrant, SceneryHash.Unit(x, y, SceneryHash.QuadrantSalt), 8);
        Assert.Equal(freq, SceneryHash.Unit(x, y, SceneryHash.FrequencySalt), 15);
        Assert.Equal(dx, SceneryHash.Unit(x, y, SceneryHash.DisplaceXSalt), 15);
        Assert.Equal(dy, SceneryHash.Unit(x, y, SceneryHash.DisplaceYSalt), 15);
        Assert.Equal(scale, SceneryHash.Unit(x, y, SceneryHash.ScaleSalt), 15);
        Assert.Equal(heading, SceneryHash.Unit(x, y, SceneryHash.HeadingSalt), 15);
    }
}
