using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class PlaneTests
{
    // The plane z = 10: N = (0, 0, 1), d = -10.
    private static readonly CollisionPlane Floor10 = new(new Vector3(0f, 0f, 1f), -10f);

    [Fact]
    public void WhichSide_AboveBelowAndWithinEpsilon()
    {
        Assert.Equal(Sidedness.Positive, Floor10.WhichSide(new Vector3(3f, 4f, 10.5f), PhysicsGlobals.Epsilon));
        Assert.Equal(Sidedness.Negative, Floor10.WhichSide(new Vector3(3f, 4f, 9.5f), PhysicsGlobals.Epsilon));
        // 10.0001 - 10 = 0.0001 <= 0.0002: in plane.
        Assert.Equal(Sidedness.InPlane, Floor10.WhichSide(new Vector3(0f, 0f, 10.0001f), PhysicsGlobals.Epsilon));
    }

    [Fact]
    public void DotProduct_IsSignedDistanceForUnitNormal()
    {
        // N = (0.6, 0, 0.8), d = -2: at (10, 7, 5): 0.8*5 + 0*7 + 0.6*10 - 2 = 4 + 6 - 2 = 8.
        var p = new CollisionPlane(new Vector3(0.6f, 0f, 0.8f), -2f);
        Assert.Equal(8.0, p.DotProduct(new Vector3(10f, 7f, 5f)), 6);
    }

    [Fact]
    public void SetHeight_DropsPointOntoSlopedPlane()
    {
        // N = (-5/13, 0, 12/13), d = -120/13 (the plane z = 10 + x * 5/12): at x = 12: z = 10 + 5 = 15.
        var p = new CollisionPlane(new Vector3(-5f / 13f, 0f, 12f / 13f), -120f / 13f);
        var v = new Vector3(12f, 3f, 999f);
        Assert.True(p.SetHeight(ref v));
        Assert.Equal(15f, v.Z, 4);
        Assert.Equal(12f, v.X);
        Assert.Equal(3f, v.Y);
    }

    [Fact]
    public void SetHeight_VerticalPlane_FailsAndLeavesPoint()
    {
        // |N.z| = 0.0001 <= EPSILON: retail refuses.
        var p = new CollisionPlane(new Vector3(1f, 0f, 0.0001f), 0f);
        var v = new Vector3(1f, 2f, 3f);
        Assert.False(p.SetHeight(ref v));
        Assert.Equal(new Vector3(1f, 2f, 3f), v);
    }

    [Fact]
    public void ComputeTimeOfIntersection_RayDownOntoFloor()
    {
        // From z = 15 moving (0, 0, -2) per unit t: reaches z = 10 at t = (15 - 10) / 2 = 2.5.
        Assert.True(Floor10.ComputeTimeOfIntersection(new Vector3(1f, 1f, 15f), new Vector3(0f, 0f, -2f), out double t));
        Assert.Equal(2.5, t, 12);
    }

    [Fact]
    public void ComputeTimeOfIntersection_ParallelOrBehind_IsFalse()
    {
        Assert.False(Floor10.ComputeTimeOfIntersection(new Vector3(0f, 0f, 15f), new Vector3(1f, 0f, 0f), out _));
        // Moving up from above: t = (15 - 10) * (-1 / 1) = -5 < 0.
        Assert.False(Floor10.ComputeTimeOfIntersection(new Vector3(0f, 0f, 15f), new Vector3(0f, 0f, 1f), out double t));
        Assert.Equal(-5.0, t, 12);
    }
}
