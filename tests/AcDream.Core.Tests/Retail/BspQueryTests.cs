using System;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class BspQueryTests
{
    // The unit square on z = 0, counter-clockwise seen from above: N = (0, 0, 1), d = 0.
    private static Polygon Square() =>
        new(0, new[] { new Vector3(0f, 0f, 0f), new Vector3(1f, 0f, 0f), new Vector3(1f, 1f, 0f), new Vector3(0f, 1f, 0f) }, new ushort[] { 0, 1, 2, 3 });

    [Theory]
    // Over the middle, 0.3 above: |dist| 0.3 <= r - EPSILON = 0.4998, projection inside.
    [InlineData(0.5f, 0.5f, 0.3f, true)]
    // 0.4999 above: beyond r - EPSILON.
    [InlineData(0.5f, 0.5f, 0.4999f, false)]
    // In the plane, 0.3 east of the east edge: 0.3^2 = 0.09 <= 0.4998^2 = 0.2498 and the point projects onto the edge.
    [InlineData(1.3f, 0.5f, 0f, true)]
    // 0.6 east: 0.36 > 0.2498 -> miss (reading BSP-B1 of the flags-only compare).
    [InlineData(1.6f, 0.5f, 0f, false)]
    // Beyond the north-east corner by (0.3, 0.3): corner distance^2 0.18 <= 0.2498.
    [InlineData(1.3f, 1.3f, 0f, true)]
    // By (0.4, 0.4): 0.32 > 0.2498, and the point projects onto neither edge.
    [InlineData(1.4f, 1.4f, 0f, false)]
    public void PolygonHitsSphere_FaceEdgeAndCorner(float x, float y, float z, bool hit)
    {
        Polygon p = Square();
        var s = new Sphere(new Vector3(x, y, z), 0.5f);
        Assert.Equal(hit, p.PolygonHitsSphere(s, out _));
        Assert.Equal(hit, p.PolygonHitsSphereSlowButSure(s, out _));
        Assert.Equal(hit, p.HitsSphere(s));
    }

    [Fact]
    public void PolygonHitsSphere_ContactPointIsTheCentreDroppedOnThePlane()
    {
        Assert.True(Square().PolygonHitsSphere(new Sphere(new Vector3(0.25f, 0.75f, 0.3f), 0.5f), out Vector3 cp));
        Assert.Equal(new Vector3(0.25f, 0.75f, 0f), cp);
    }

    [Fact]
    public void PosHitsSphere_OnlyWhenMovingIntoTheFace_ButRecordsTheStruckPolygonEitherWay()
    {
        Polygon p = Square();
        var s = new Sphere(new Vector3(0.5f, 0.5f, 0.3f), 0.5f);
        Polygon? struck = null;
        // Moving down (N . m = -0.1 < 0): a hit.
        Assert.True(p.PosHitsSphere(s, new Vector3(0f, 0f, -0.1f), out _, ref struck));
        Assert.Same(p, struck);
        // Moving up (N . m = 0.1 >= 0): no hit, but the polygon is recorded (retail's negative-side hit).
        struck = null;
        Assert.False(p.PosHitsSphere(s, new Vector3(0f, 0f, 0.1f), out _, ref struck));
        Assert.Same(p, struck);
    }

    [Fact]
    public void AdjustSphereToPlane_MovesBackOntoThePlane_AndSpendsWalkInterp()
    {
        var path = new SpherePath { WalkInterp = 1f };
        var s = new Sphere(new Vector3(0.5f, 0.5f, 0.3f), 0.5f);
        // dist 0.3, N . m = -0.6: t = (0.3 - 0.5) / -0.6 = 1/3; centre z 0.3 + (1/3) * 0.6 = 0.5; interp (1 - 1/3) * 1.
        Assert.True(Square().AdjustSphereToPlane(path, ref s, new Vector3(0f, 0f, -0.6f)));
        Assert.Equal(0.5f, s.Center.Z, 6);
        Assert.Equal(2f / 3f, path.WalkInterp, 6);
    }

    [Fact]
    public void AdjustSphereToPlane_RefusesALiftBeyondHalfAStep_AndParallelMovement()
    {
        var path = new SpherePath { WalkInterp = 1f };
        // Centre 0.5 below the plane: t = (-0.5 - 0.5) / -0.6 = 1.667, interp -0.667 < -0.5: refused.
        var s = new Sphere(new Vector3(0.5f, 0.5f, -0.5f), 0.5f);
        Assert.False(Square().AdjustSphereToPlane(path, ref s, new Vector3(0f, 0f, -0.6f)));
        Assert.Equal(-0.5f, s.Center.Z);
        Assert.Equal(1f, path.WalkInterp);
        // Centre 0.35 below: t = (-0.35 - 0.5) / -0.6 = 1.4167, interp -0.4167 >= -0.5: accepted, z -0.35 + 0.85 = 0.5.
        s = new Sphere(new Vector3(0.5f, 0.5f, -0.35f), 0.5f);
        Assert.True(Square().AdjustSphereToPlane(path, ref s, new Vector3(0f, 0f, -0.6f)));
        Assert.Equal(0.5f, s.Center.Z, 5);
        // Movement along the plane (|N . m| <= EPSILON): nothing.
        path.WalkInterp = 1f;
        s = new Sphere(new Vector3(0.5f, 0.5f, 0.3f), 0.5f);
        Assert.False(Square().AdjustSphereToPlane(path, ref s, new Vector3(1f, 0f, 0f)));
    }

    [Fact]
    public void AdjustSphereToPoly_TimeOfTouch()
    {
        Polygon p = Square();
        var s = new Sphere(new Vector3(0.5f, 0.5f, 0f), 0.5f);
        // From z = 2 moving -2: touches at z = 0.5, t = (0.5 - 2) / -2 = 0.75.
        Assert.Equal(0.75, p.AdjustSphereToPoly(s, new Vector3(0.5f, 0.5f, 2f), new Vector3(0f, 0f, -2f)), 9);
        // From below (z = -2) moving +2: radius negated, t = (-0.5 + 2) / 2 = 0.75.
        Assert.Equal(0.75, p.AdjustSphereToPoly(s, new Vector3(0.5f, 0.5f, -2f), new Vector3(0f, 0f, 2f)), 9);
        // Already overlapping the plane at the start: 1. Moving along it: 0.
        Assert.Equal(1.0, p.AdjustSphereToPoly(s, new Vector3(0.5f, 0.5f, 0.3f), new Vector3(0f, 0f, -2f)));
        Assert.Equal(0.0, p.AdjustSphereToPoly(s, new Vector3(0.5f, 0.5f, 2f), new Vector3(1f, 0f, 0f)));
    }

    [Fact]
    public void AdjustToPlacementPoly_PushesBothSpheresOutAlongTheNormal()
    {
        var struck = new Sphere(new Vector3(0.5f, 0.5f, 0.2f), 0.5f);
        var other = new Sphere(new Vector3(0.5f, 0.5f, 1.2f), 0.5f);
        // Not a solid test: move = r - dist = 0.5 - 0.2 = 0.3 along +z for both.
        Square().AdjustToPlacementPoly(ref struck, ref other, 0.5f, false, false);
        Assert.Equal(0.5f, struck.Center.Z, 6);
        Assert.Equal(1.5f, other.Center.Z, 6);
        // Solid test with the centre in a solid leaf: radius negated (-0.5), dist 0.5 > 0: move = -0.5 - 0.5 = -1.
        struck = new Sphere(new Vector3(0.5f, 0.5f, 0.5f), 0.5f);
        Square().AdjustToPlacementPoly(ref struck, ref other, 0.5f, true, true);
        Assert.Equal(-0.5f, struck.Center.Z, 6);
    }

    [Fact]
    public void SphereIntersects_IsStrict()
    {
        var a = new Sphere(Vector3.Zero, 1f);
        Assert.False(a.Intersects(new Sphere(new Vector3(2f, 0f, 0f), 1f))); // touching: 4 < 4 is false
        Assert.True(a.Intersects(new Sphere(new Vector3(1.9f, 0f, 0f), 1f)));
    }

    [Fact]
    public void CellBsp_PointAndSphereTests()
    {
        BspTree cell = BspBuilder.BuildCell(BspBuilder.BoxCellPlanes(Vector3.Zero, Vector3.One));
        Assert.True(cell.PointInsideCellBsp(new Vector3(0.5f, 0.5f, 0.5f)));
        // 0.0001 past the x = 1 face: within EPSILON, counts as in the plane -> inside.
        Assert.True(cell.PointInsideCellBsp(new Vector3(1.0001f, 0.5f, 0.5f)));
        Assert.False(cell.PointInsideCellBsp(new Vector3(1.001f, 0.5f, 0.5f)));
        // r = 0.1, margin 0.01: inside when every plane distance >= 0.11, outside once one is <= -0.11.
        Assert.Equal(CellBspSphere.Inside, cell.SphereIntersectsCellBsp(new Sphere(new Vector3(0.5f, 0.5f, 0.5f), 0.1f)));
        Assert.Equal(CellBspSphere.Crossing, cell.SphereIntersectsCellBsp(new Sphere(new Vector3(1.05f, 0.5f, 0.5f), 0.1f)));
        Assert.Equal(CellBspSphere.Outside, cell.SphereIntersectsCellBsp(new Sphere(new Vector3(1.2f, 0.5f, 0.5f), 0.1f)));
    }

    [Fact]
    public void PlaneLocalToGlobal_RotatesTheNormalAndCarriesThePlanePoint()
    {
        // 'from' at (10, 0, 0) turned 90 degrees counter-clockwise about z (local x -> global y). The local plane x = 2
        // (N = (1, 0, 0), d = -2) becomes N = (0, 1, 0) through (10, 2, 0): y = 2, d = -2.
        var q = new Quaternion(0f, 0f, MathF.Sin(MathF.PI / 4f), MathF.Cos(MathF.PI / 4f));
        var from = new Position(0x80800001u, new Frame(new Vector3(10f, 0f, 0f), q));
        var to = new Position(0x80800001u, Vector3.Zero);
        CollisionPlane g = PlaneSpace.LocalToGlobal(to, from, new CollisionPlane(new Vector3(1f, 0f, 0f), -2f));
        Assert.Equal(0f, g.N.X, 6);
        Assert.Equal(1f, g.N.Y, 6);
        Assert.Equal(0f, g.N.Z, 6);
        Assert.Equal(-2f, g.D, 5);
    }

    [Fact]
    public void FindCollisions_GroundedSphereTouchingAPolygonItLeaves_WithTwoSpheres_RecordsANegativeStepUpHit()
    {
        BspTree tree = BspBuilder.Build(new[] { Square() });
        var t = new Transition(new TerrainWorld(new LandHeightTable(new float[LandHeightTable.Count])));
        t.ObjectInfo.State = ObjectInfoState.Contact;
        SpherePath path = t.SpherePath;
        path.InitSphere(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f), new Sphere(new Vector3(0f, 0f, 1.5f), 0.5f) }, 1f);
        path.LocalSpacePos = new Position(0x80800001u, Vector3.Zero);
        // Sphere 0 overlaps the square (0.3 above it) while moving up (+0.1): pos_hits_sphere records it without a hit;
        // sphere 1 (1.3 above) touches nothing. Retail: set_neg_poly_hit(step_up = 1, N) -> normal stored negated.
        path.LocalSpaceSphere[0] = new Sphere(new Vector3(0.5f, 0.5f, 0.3f), 0.5f);
        path.LocalSpaceSphere[1] = new Sphere(new Vector3(0.5f, 0.5f, 1.3f), 0.5f);
        path.LocalSpaceCurrCenter[0] = new Vector3(0.5f, 0.5f, 0.2f);
        Assert.Equal(TransitionState.Ok, tree.FindCollisions(t, 1f));
        Assert.True(path.NegPolyHit);
        Assert.True(path.NegStepUp);
        Assert.Equal(new Vector3(0f, 0f, -1f), path.NegCollisionNormal);

        // With one sphere retail's find_collisions never reaches set_neg_poly_hit (it sits inside the num_sphere > 1
        // branch, reading BSP-B4): nothing is recorded.
        path.NegPolyHit = false;
        path.InitSphere(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) }, 1f);
        Assert.Equal(TransitionState.Ok, tree.FindCollisions(t, 1f));
        Assert.False(path.NegPolyHit);
    }

    [Fact]
    public void FindCollisions_ClippedPath_CollidesOrWithPerfectClipBacksOffToTheTouchingPoint()
    {
        BspTree tree = BspBuilder.Build(new[] { Square() });
        var t = new Transition(new TerrainWorld(new LandHeightTable(new float[LandHeightTable.Count])));
        SpherePath path = t.SpherePath;
        path.InitSphere(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) }, 1f);
        path.LocalSpacePos = new Position(0x80800001u, Vector3.Zero);
        path.CheckPos = new Position(0x80800001u, new Vector3(0.5f, 0.5f, -0.3f));
        path.CacheGlobalSphere();
        // The sphere moves from centre z = 2 down to z = 0.2 (movement -1.8), into the square's face.
        path.LocalSpaceSphere[0] = new Sphere(new Vector3(0.5f, 0.5f, 0.2f), 0.5f);
        path.LocalSpaceCurrCenter[0] = new Vector3(0.5f, 0.5f, 2f);

        // PATH_CLIPPED without PERFECT_CLIP: collide with the polygon's normal.
        t.ObjectInfo.State = ObjectInfoState.PathClipped;
        Assert.Equal(TransitionState.Collided, tree.FindCollisions(t, 1f));
        Assert.Equal(new Vector3(0f, 0f, 1f), t.CollisionInfo.CollisionNormal);

        // With PERFECT_CLIP: adjust_sphere_to_poly gives t = (0.5 - 2) / -1.8 = 0.8333 (centre z 0.5, touching, no hit:
        // the lower bound); the bisection only narrows the upper bound (0.9167, 0.875, 0.854, 0.84375: all hit) until the
        // bracket is under 0.02, and the sphere ends at the lower bound: z 0.5. The check position moves by 0.5 - 0.2 = 0.3.
        t.ObjectInfo.State = ObjectInfoState.PathClipped | ObjectInfoState.PerfectClip;
        Assert.Equal(TransitionState.Adjusted, tree.FindCollisions(t, 1f));
        Assert.Equal(0f, path.CheckPos.Frame.Origin.Z, 5);
        Assert.Equal(new Vector3(0f, 0f, 1f), t.CollisionInfo.CollisionNormal);
    }

    // A retail-shaped solid tree: the split plane z = 0 (the square's plane), the square listed in both leaves, the
    // negative (below-floor) leaf solid, as a physics BSP of a slab would be.
    private static BspTree SolidFloor()
    {
        Polygon sq = Square();
        var bound = new Sphere(new Vector3(0.5f, 0.5f, 0f), 0.71f);
        var nodes = new[]
        {
            BspNode.Split(BspNodeType.SplitBothChildren, sq.Plane, new Sphere(new Vector3(0.5f, 0.5f, 0f), 50f), 1, 2),
            BspNode.MakeLeaf(0, bound, 0, 1, false),
            BspNode.MakeLeaf(1, new Sphere(new Vector3(0.5f, 0.5f, 0f), 50f), 1, 1, true),
        };
        return new BspTree(nodes, new[] { sq }, new[] { 0, 0 });
    }

    [Fact]
    public void SolidLeaf_CatchesACentreInsideOnlyWithTheCentreCheck()
    {
        BspTree tree = SolidFloor();
        // 2 m below the floor, r 0.5: touches no polygon; the centre is in the solid leaf.
        var s = new Sphere(new Vector3(0.5f, 0.5f, -2f), 0.5f);
        Assert.True(tree.SphereIntersectsSolid(s, true));
        Assert.False(tree.SphereIntersectsSolid(s, false));
        bool centerSolid = false;
        Polygon? hit = null;
        Assert.True(tree.SphereIntersectsSolidPoly(s, 0.5f, ref centerSolid, ref hit, true));
        Assert.True(centerSolid);
        Assert.Null(hit);
        // BSPLEAF::point_intersects_solid (acclient.c:364085) answers num_polys != 0, not the solid flag: both leaves list
        // the square, so a point above the floor "intersects solid" too (retail quirk, kept).
        Assert.True(tree.PointIntersectsSolid(new Vector3(0.5f, 0.5f, -2f)));
        Assert.True(tree.PointIntersectsSolid(new Vector3(0.5f, 0.5f, 2f)));
    }

    [Fact]
    public void PlacementInsert_PushesACentreInTheSolidOutThroughTheFace_AndGivesUpWhenBuriedTooDeep()
    {
        BspTree tree = SolidFloor();
        var t = new Transition(new TerrainWorld(new LandHeightTable(new float[LandHeightTable.Count])));
        SpherePath path = t.SpherePath;
        path.InitSphere(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) }, 1f);
        path.LocalSpacePos = new Position(0x80800001u, Vector3.Zero);
        path.CheckPos = new Position(0x80800001u, new Vector3(0.5f, 0.5f, -0.8f));
        path.CacheGlobalSphere();
        // Centre 0.3 below the face: round 0 finds the square with the centre solid: move = (r, negated for the solid
        // centre, negated again for dist <= 0) - dist = 0.5 + 0.3 = 0.8 up; round 1 is free: Adjusted, offset 0.8.
        path.LocalSpaceSphere[0] = new Sphere(new Vector3(0.5f, 0.5f, -0.3f), 0.5f);
        Assert.Equal(TransitionState.Adjusted, tree.PlacementInsert(t));
        Assert.Equal(0f, path.CheckPos.Frame.Origin.Z, 5);

        // Centre 2 m down: solid but no polygon within reach of the 0.5 m sphere; the test radius doubles each round and
        // 20 rounds pass without a polygon to push out of: Collided.
        path.LocalSpaceSphere[0] = new Sphere(new Vector3(0.5f, 0.5f, -2f), 0.5f);
        Assert.Equal(TransitionState.Collided, tree.PlacementInsert(t));
    }
}
