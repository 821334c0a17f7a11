using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using Xunit;

namespace AcDream.Core.Tests.Retail;

// CPolygon::check_walkable (acclient.c:360226) and check_small_walkable (acclient.c:360311) under the one reading of the
// lost compare (BSP-B1, docs/divergences.md): a centre outside an edge by more than the radius is not walkable; within the
// radius it goes on to the edge-segment test (walkable when it projects onto the segment) and the vertex test.
public class CheckWalkableTests
{
    private static readonly Vector3 Up = new(0f, 0f, 1f);

    // The floor square (0,0)-(2,0)-(2,2)-(0,2) at z = 0, counter-clockwise from above: N = (0, 0, 1), D = 0. The edge loop
    // runs v3→v0 (x = 0), v0→v1 (y = 0), v1→v2 (x = 2), v2→v3 (y = 2).
    private static Polygon Floor() =>
        new(0, [new(0f, 0f, 0f), new(2f, 0f, 0f), new(2f, 2f, 0f), new(0f, 2f, 0f)], [0, 1, 2, 3]);

    [Fact]
    public void CentreOutsideAnEdgeByLessThanTheRadius_OverTheSegment_IsWalkable()
    {
        // Centre (2.3, 1, 0.5), r 0.5, dropped along +z onto z = 0: (2.3, 1, 0). Edge v1→v2 = (0, 2, 0), disp = (0.3, 1, 0):
        // cross = disp · (N × edge) = (0.3, 1, 0) · (-2, 0, 0) = -0.6 < 0 (outside); cross² = 0.36 <= r² |edge|² = 0.25 · 4 = 1 (within the
        // radius: 0.3 < 0.5); along = disp · edge = 1 · 2 = 2 in [0, 4]: on the segment → walkable. (The earlier reading,
        // "outside an edge → not walkable at once", answered false here.)
        Assert.True(Floor().CheckWalkable(new Sphere(new Vector3(2.3f, 1f, 0.5f), 0.5f), Up));
    }

    [Fact]
    public void CentreOutsideAnEdgeByMoreThanTheRadius_IsNotWalkable()
    {
        // (2.6, 1): outside x = 2 by 0.6; cross² = (0.6 · 2)² = 1.44 > 0.25 · 4 = 1 → false at once.
        Assert.False(Floor().CheckWalkable(new Sphere(new Vector3(2.6f, 1f, 0.5f), 0.5f), Up));
    }

    [Fact]
    public void CentreBeyondACorner_WalkableOnlyWithinTheRadiusOfTheVertex()
    {
        // (2.3, 2.3): v1→v2 outside by 0.3 (within r) but along = 2.3 · 2 = 4.6 > 4 (past the segment), vertex v1 = (2, 0)
        // at 0.09 + 5.29 > 0.25; v2→v3 = (-2, 0, 0): outside by 0.3, along = 0.3 · -2 = -0.6 < 0, vertex v2 = (2, 2) at
        // 0.3² + 0.3² = 0.18 <= 0.25 → walkable. At (2.4, 2.4) the vertex is 0.32 > 0.25 away and no edge is met → false.
        Assert.True(Floor().CheckWalkable(new Sphere(new Vector3(2.3f, 2.3f, 0.5f), 0.5f), Up));
        Assert.False(Floor().CheckWalkable(new Sphere(new Vector3(2.4f, 2.4f, 0.5f), 0.5f), Up));
    }

    [Fact]
    public void SmallWalkable_UsesHalfTheRadius()
    {
        // check_small_walkable: inside = r² · 0.25 = 0.0625 (half the radius, 0.25). (2.2, 1): cross² = (0.2 · 2)² = 0.16 <=
        // 0.0625 · 4 = 0.25 → on the segment → true; (2.3, 1): 0.36 > 0.25 → false. check_walkable with the same sphere
        // accepts both (0.36 <= 1).
        Polygon floor = Floor();
        Assert.True(floor.CheckSmallWalkable(new Sphere(new Vector3(2.2f, 1f, 0.5f), 0.5f), Up));
        Assert.False(floor.CheckSmallWalkable(new Sphere(new Vector3(2.3f, 1f, 0.5f), 0.5f), Up));
        Assert.True(floor.CheckWalkable(new Sphere(new Vector3(2.2f, 1f, 0.5f), 0.5f), Up));
    }

    [Fact]
    public void CentreInside_IsWalkable_AndUpAlongThePlane_IsNot()
    {
        // Inside every edge → true; up = (1, 0, 0) runs along the plane (|N · up| = 0 < EPSILON) → false.
        Assert.True(Floor().CheckWalkable(new Sphere(new Vector3(1f, 1f, 3f), 0.5f), Up));
        Assert.False(Floor().CheckWalkable(new Sphere(new Vector3(1f, 1f, 3f), 0.5f), new Vector3(1f, 0f, 0f)));
    }
}
