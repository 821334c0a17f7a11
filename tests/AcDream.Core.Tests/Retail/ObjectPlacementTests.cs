using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Scenery;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// An object spot's placement functions against the decompilation: <c>ObjectDesc::Place</c> (acclient.c:462604),
/// <c>GetObjFrame</c> (462659), <c>ObjAlign</c> (462707), <c>CheckSlope</c> (351354), <c>ScaleObj</c> (351360). Values are
/// worked from the hash's golden draws at vertex (42, 314) (<see cref="SceneryHashTests"/>).
/// </summary>
public class ObjectPlacementTests
{
    internal static ObjectDesc Spot(Vector3 origin, float dx = 0f, float dy = 0f, float minScale = 1f, float maxScale = 1f,
        float maxRot = 0f, float minSlope = 0f, float maxSlope = 1f, uint align = 0, float freq = 1f, uint id = 0x02000247,
        uint weenie = 0, Frame? frame = null)
    {
        Frame f = frame ?? Frame.Identity;
        f.Origin = origin;
        return new ObjectDesc(id, f, freq, dx, dy, minScale, maxScale, maxRot, minSlope, maxSlope, align, 0, weenie);
    }

    // The quarter turn of vertex (x, y), written as the decompilation writes it (acclient.c:462630).
    private static double Quadrant(uint x, uint y) =>
        unchecked(1813693831u * y - x * (1870387557u * y + 1109124029u) - 402451965u) * Math.ScaleB(1.0, -32);

    [Fact]
    public void Place_DisplacesThenTurnsByTheVertexQuadrant()
    {
        // At (42, 314), k = 0: u(45773) = 0.8297583453822881, u(72719) = 0.4336220824625343, quadrant 0.5004085 (in [1/2, 3/4):
        // (x, y) -> (-x, -y)). Displacements 10 m: x = 8.297583453822881 (stored to float), y = 4.336220824625343 (not).
        Vector3 p = ObjectPlacement.Place(Spot(new Vector3(0f, 0f, 1.5f), dx: 10f, dy: 10f), 42, 314, 0);
        Assert.Equal(-(float)8.297583453822881, p.X);
        Assert.Equal((float)-4.336220824625343, p.Y);
        Assert.Equal(1.5f, p.Z);
    }

    [Theory]
    [InlineData(0, 1f, 2f)]   // q < 1/4: (x, y)
    [InlineData(1, -2f, 1f)]  // q < 1/2: (-y, x)
    [InlineData(2, -1f, -2f)] // q < 3/4: (-x, -y)
    [InlineData(3, 2f, -1f)]  // else: (y, -x)
    public void Place_EachQuarterTurn_SharedByEveryObjectOfTheVertex(int quarter, float ex, float ey)
    {
        // The first vertex along a row whose quadrant draw falls in the quarter.
        uint x = 0, y = 100;
        while ((int)(Quadrant(x, y) * 4) != quarter)
        {
            x++;
        }

        ObjectDesc spot = Spot(new Vector3(1f, 2f, 3f));
        for (uint k = 0; k < 4; k++)
        {
            Assert.Equal(new Vector3(ex, ey, 3f), ObjectPlacement.Place(spot, x, y, k));
        }
    }

    [Fact]
    public void Place_ADisplacementOfZeroOrLess_KeepsTheBase()
    {
        // Retail tests displace > 0 (the weenie spot of Scene 0x12000074 stores -0.66): (1, 2) rotated by quadrant 0.5004.
        Vector3 p = ObjectPlacement.Place(Spot(new Vector3(1f, 2f, 0f), dx: -0.66f, dy: 0f), 42, 314, 0);
        Assert.Equal(new Vector3(-1f, -2f, 0f), p);
    }

    [Fact]
    public void GetObjFrame_SetsTheRandomHeading_OrKeepsTheBaseRotation()
    {
        var loc = new Vector3(10f, 20f, 30f);
        // u(63127) at (42, 314) = 0.8996555951889604; max_rot 360: heading (float)323.87601... degrees.
        Frame f = ObjectPlacement.GetObjFrame(Spot(Vector3.Zero, maxRot: 360f), 42, 314, 0, loc);
        Assert.Equal(loc, f.Origin);
        Assert.Equal(0.8996555951889604 * 360.0, f.Heading, 3);

        Frame base30 = Frame.FromHeading(Vector3.Zero, 30.0);
        Frame g = ObjectPlacement.GetObjFrame(Spot(Vector3.Zero, maxRot: 0f, frame: base30), 42, 314, 0, loc);
        Assert.Equal(loc, g.Origin);
        Assert.Equal(base30.Rotation, g.Rotation);

        // Object k uses salt 63127 + k.
        Frame h = ObjectPlacement.GetObjFrame(Spot(Vector3.Zero, maxRot: 100f), 42, 314, 3, loc);
        Assert.Equal(SceneryHash.Unit(42, 314, 63130) * 100.0, h.Heading, 3);
    }

    [Theory]
    [InlineData(0.6f, 0f, 270.0)]  // the normal leans east (downhill): -N, uphill, is west
    [InlineData(0f, 0.6f, 180.0)]  // leans north: faces south
    [InlineData(-0.6f, 0f, 90.0)]  // leans west: faces east
    [InlineData(0f, 0f, 0.0)]      // flat: no heading (get_heading of a short vector is 0)
    public void ObjAlign_FacesMinusN_Uphill_WithoutTilt(float nx, float ny, double heading)
    {
        var plane = new CollisionPlane { N = new Vector3(nx, ny, MathF.Sqrt(1f - nx * nx - ny * ny)), D = 0f };
        Frame f = ObjectPlacement.ObjAlign(Spot(Vector3.Zero, align: 1), plane, new Vector3(5f, 6f, 7f));
        Assert.Equal(new Vector3(5f, 6f, 7f), f.Origin);
        Assert.Equal(heading, f.Heading, 4);
        Vector3 up = f.LocalToGlobalVec(Vector3.UnitZ);
        Assert.Equal(0f, up.X, 6);
        Assert.Equal(0f, up.Y, 6);
        Assert.Equal(1f, up.Z, 6);
    }

    [Fact]
    public void CheckSlope_IncludesBothBounds()
    {
        ObjectDesc s = Spot(Vector3.Zero, minSlope: 0.5f, maxSlope: 0.9f);
        Assert.True(ObjectPlacement.CheckSlope(s, 0.5f));
        Assert.True(ObjectPlacement.CheckSlope(s, 0.9f));
        Assert.False(ObjectPlacement.CheckSlope(s, 0.49999997f));
        Assert.False(ObjectPlacement.CheckSlope(s, 0.90000004f));
        // The constructor default max_slope is 90.0 (acclient.c:462677): every cosine passes.
        Assert.True(ObjectPlacement.CheckSlope(Spot(Vector3.Zero, maxSlope: 90f), 1f));
    }

    [Fact]
    public void ScaleObj_IsMaxWhenEqual_ElseLogUniform()
    {
        Assert.Equal(1.25f, ObjectPlacement.ScaleObj(Spot(Vector3.Zero, minScale: 1.25f, maxScale: 1.25f), 42, 314, 0));

        // Scene 0x12000074's object 0: 0.7 - 1.5. At (42, 314), k = 0, u(32593) = 0.35210214206017554:
        // ln(s / 0.7) / ln(1.5 / 0.7) = u.
        ObjectDesc s = Spot(Vector3.Zero, minScale: 0.7f, maxScale: 1.5f);
        float scale = ObjectPlacement.ScaleObj(s, 42, 314, 0);
        Assert.Equal(0.35210214206017554, Math.Log(scale / (double)0.7f) / Math.Log(1.5f / (double)0.7f), 6);
        for (uint k = 0; k < 200; k++)
        {
            Assert.InRange(ObjectPlacement.ScaleObj(s, 1000, 1000 + k, k), 0.7f, 1.5f);
        }
    }

    [Fact]
    public void NullSpot_Throws()
    {
        Assert.Throws<ArgumentNullException>(() => ObjectPlacement.Place(null!, 0, 0, 0));
        Assert.Throws<ArgumentNullException>(() => ObjectPlacement.ScaleObj(null!, 0, 0, 0));
        Assert.Throws<ArgumentNullException>(() => ObjectPlacement.CheckSlope(null!, 0f));
        Assert.Throws<ArgumentNullException>(() => ObjectPlacement.GetObjFrame(null!, 0, 0, 0, Vector3.Zero));
        Assert.Throws<ArgumentNullException>(() => ObjectPlacement.ObjAlign(null!, default, Vector3.Zero));
    }
}
