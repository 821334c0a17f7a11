using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class PolygonTests
{
    private static Polygon Tri(Vector3 a, Vector3 b, Vector3 c) => new(0, [a, b, c], [0, 1, 2]);

    [Fact]
    public void MakePlane_FlatCounterClockwiseTriangle_NormalUpAndDMinusHeight()
    {
        Polygon p = Tri(new(0f, 0f, 7f), new(24f, 0f, 7f), new(24f, 24f, 7f));
        Assert.Equal(new Vector3(0f, 0f, 1f), p.Plane.N);
        Assert.Equal(-7f, p.Plane.D);
    }

    [Fact]
    public void MakePlane_ClockwiseTriangle_NormalDown()
    {
        Polygon p = Tri(new(0f, 0f, 7f), new(24f, 24f, 7f), new(24f, 0f, 7f));
        Assert.Equal(new Vector3(0f, 0f, -1f), p.Plane.N);
        Assert.Equal(7f, p.Plane.D);
    }

    [Fact]
    public void MakePlane_SlopedTerrainTriangle_HandComputed()
    {
        // SW (0,0,10), SE (24,0,20), NE (24,24,20). a = SE - SW = (24, 0, 10), b = NE - SW = (24, 24, 10).
        // a × b = (0*10 - 10*24, 10*24 - 24*10, 24*24 - 0*24) = (-240, 0, 576); |n| = sqrt(57600 + 331776) = 624.
        // N = (-240/624, 0, 576/624) = (-5/13, 0, 12/13). Each vertex has N·v = 120/13 (e.g. SW: 12/13 * 10), so d = -120/13.
        Polygon p = Tri(new(0f, 0f, 10f), new(24f, 0f, 20f), new(24f, 24f, 20f));
        Assert.Equal((float)(-5.0 / 13.0), p.Plane.N.X);
        Assert.Equal(0f, p.Plane.N.Y);
        Assert.Equal((float)(12.0 / 13.0), p.Plane.N.Z);
        Assert.Equal((float)(-120.0 / 13.0), p.Plane.D, 5);
    }

    [Fact]
    public void MakePlane_Quad_SumsFanCrossProducts()
    {
        // A unit-height-step quad wound CCW: (0,0,0) (2,0,0) (2,2,2) (0,2,2): the plane z = y, N = (0, -1, 1)/sqrt 2.
        // Fan: (v1-v0)×(v2-v0) = (2,0,0)×(2,2,2) = (0*2-0*2, 0*2-2*2, 2*2-0*2) = (0,-4,4);
        //      (v2-v0)×(v3-v0) = (2,2,2)×(0,2,2) = (2*2-2*2, 2*0-2*2, 2*2-2*0) = (0,-4,4). Sum (0,-8,8).
        var p = new Polygon(0, [new(0f, 0f, 0f), new(2f, 0f, 0f), new(2f, 2f, 2f), new(0f, 2f, 2f)], [0, 1, 2, 3]);
        float s = (float)(1.0 / Math.Sqrt(2.0));
        Assert.Equal(0f, p.Plane.N.X);
        Assert.Equal(-s, p.Plane.N.Y, 6);
        Assert.Equal(s, p.Plane.N.Z, 6);
        Assert.Equal(0f, p.Plane.D, 6);
    }

    [Theory]
    [InlineData(20f, 4f, true)]    // inside
    [InlineData(12f, 12f, true)]   // on the diagonal edge (x = y)
    [InlineData(24f, 10f, true)]   // on the east edge
    [InlineData(24f, 24f, true)]   // on a vertex
    [InlineData(4f, 20f, false)]   // the other half of the square
    [InlineData(25f, 1f, false)]   // east of the triangle
    [InlineData(10f, -0.001f, false)] // just south
    public void PointInPoly2D_CounterClockwiseTriangle_EdgesInclusive(float x, float y, bool inside)
    {
        Polygon p = Tri(new(0f, 0f, 50f), new(24f, 0f, 60f), new(24f, 24f, 70f));
        Assert.Equal(inside, p.PointInPoly2D(new Vector3(x, y, -1000f), Sidedness.Positive));
    }

    [Fact]
    public void PointInPoly2D_NegativeSide_AcceptsClockwiseInterior()
    {
        Polygon cw = Tri(new(0f, 0f, 0f), new(24f, 24f, 0f), new(24f, 0f, 0f));
        Assert.True(cw.PointInPoly2D(new Vector3(20f, 4f, 0f), Sidedness.Negative));
        Assert.False(cw.PointInPoly2D(new Vector3(20f, 4f, 0f), Sidedness.Positive));
    }

    [Fact]
    public void Constructor_BadInput_Throws()
    {
        Assert.Throws<ArgumentException>(() => new Polygon(0, [Vector3.Zero, Vector3.One], [0, 1]));
        Assert.Throws<ArgumentException>(() => new Polygon(0, [Vector3.Zero, Vector3.One, Vector3.UnitX], [0, 1]));
        Assert.Throws<ArgumentException>(() => new Polygon(0, [Vector3.Zero, new(float.NaN, 0f, 0f), Vector3.UnitX], [0, 1, 2]));
    }
}
