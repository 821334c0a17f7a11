using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision.Primitives;

// The sphere-against-polygon tests of the BSP queries (retail CPolygon, PORTAL/cgeometry/CPolygon.c). Every edge loop
// runs from the last vertex round to the first (edge v[i-1] → v[i], starting with v[n-1] → v[0]); a point is inside an
// edge when disp · (N × edge) ≥ 0, i.e. to the left of the edge seen from the front of a counter-clockwise polygon.
// Retail ambiguity BSP-B1 (docs/divergences.md): after "outside this edge" the decompiler shows a flags-only compare
// (C0|C2) whose operands were lost. It is read as "outside this edge by more than the radius", i.e. cross² &gt; radsq ·
// |edge|² (the distance from the edge line is cross / |edge| for a unit normal) → miss. This is the only reading that
// gives both this function and polygon_hits_sphere_slow_but_sure (which has no inside flag to test) a meaning; an
// outside point within the radius then goes on to the edge-segment and vertex tests.
public sealed partial class Polygon
{
    /// <summary>
    /// True when the sphere touches the polygon: its centre lies within <c>radius - EPSILON</c> of the plane and its
    /// projection is inside the outline, within the radius of an edge, or within the radius of a vertex.
    /// <paramref name="contactPoint"/> receives the projection of the centre onto the plane.
    /// </summary>
    // retail: CPolygon::polygon_hits_sphere (acclient.c:359915)
    public bool PolygonHitsSphere(in Sphere sphere, out Vector3 contactPoint)
    {
        double dist = Plane.N.Y * (double)sphere.Center.Y + Plane.N.Z * (double)sphere.Center.Z + Plane.N.X * (double)sphere.Center.X + Plane.D;
        double r = sphere.Radius - (double)PhysicsGlobals.Epsilon;
        if (r < Math.Abs(dist))
        {
            contactPoint = default;
            return false;
        }

        contactPoint = Project(sphere.Center, dist);
        float radsq = (float)(r * r - dist * dist);
        return DiscTouches(contactPoint, radsq);
    }

    /// <summary>
    /// Like <see cref="PolygonHitsSphere"/>, but first tests whether the projected centre lies inside every edge, and
    /// only then walks the edges for edge and vertex contacts (no inside flag).
    /// </summary>
    // retail: CPolygon::polygon_hits_sphere_slow_but_sure (acclient.c:360006)
    public bool PolygonHitsSphereSlowButSure(in Sphere sphere, out Vector3 contactPoint)
    {
        double dist = Plane.N.Y * (double)sphere.Center.Y + Plane.N.Z * (double)sphere.Center.Z + sphere.Center.X * (double)Plane.N.X + Plane.D;
        double r = sphere.Radius - (double)PhysicsGlobals.Epsilon;
        if (!(r >= Math.Abs(dist)))
        {
            contactPoint = default;
            return false;
        }

        contactPoint = Project(sphere.Center, dist);
        float radsq = (float)(r * r - dist * dist);
        if (PointInPolygon(contactPoint))
        {
            return true;
        }

        Vector3[] v = _vertices;
        Vector3 prev = v[v.Length - 1];
        for (int i = 0; i < v.Length; i++)
        {
            Vector3 cur = v[i];
            EdgeTest t = TestEdge(prev, cur, contactPoint, radsq);
            if (t == EdgeTest.Miss)
            {
                return false;
            }

            if (t == EdgeTest.Hit || VertexWithin(prev, contactPoint, radsq))
            {
                return true;
            }

            prev = cur;
        }

        return false;
    }

    /// <summary>
    /// The moving sphere hits the polygon's front: <see cref="PolygonHitsSphereSlowButSure"/> and the movement goes into
    /// the face (<c>N · movement &lt; 0</c>). On any touch, <paramref name="struckPoly"/> is set to this polygon even when the
    /// movement leaves the face (that is retail's negative-side hit, see <see cref="Bsp.BspTree.FindCollisions"/>).
    /// </summary>
    // retail: CPolygon::pos_hits_sphere (acclient.c:360493)
    public bool PosHitsSphere(in Sphere sphere, Vector3 movement, out Vector3 contactPoint, ref Polygon? struckPoly)
    {
        bool hit = PolygonHitsSphereSlowButSure(sphere, out contactPoint);
        if (hit)
        {
            struckPoly = this;
        }

        if ((double)Plane.N.Z * movement.Z + (double)Plane.N.Y * movement.Y + (double)Plane.N.X * movement.X >= 0.0)
        {
            return false;
        }

        return hit;
    }

    /// <summary>True when the (static) sphere touches the polygon.</summary>
    // retail: CPolygon::hits_sphere (acclient.c:360510)
    public bool HitsSphere(in Sphere sphere) => PolygonHitsSphereSlowButSure(sphere, out _);

    /// <summary>
    /// True when the polygon is steep enough to stand on for this step (<c>N · up &gt; walkable_allowance</c>) and the
    /// sphere touches it.
    /// </summary>
    /// <remarks>Retail calls both sphere tests and, when they disagree, calls them again (a debugging hook with no
    /// effect); the slow-but-sure answer is returned.</remarks>
    // retail: CPolygon::walkable_hits_sphere (acclient.c:360518)
    internal bool WalkableHitsSphere(SpherePath path, in Sphere sphere, Vector3 up)
    {
        if (!((double)Plane.N.Z * up.Z + (double)Plane.N.Y * up.Y + (double)up.X * Plane.N.X > path.WalkableAllowance))
        {
            return false;
        }

        return PolygonHitsSphereSlowButSure(sphere, out _);
    }

    /// <summary>
    /// True when the sphere's centre, dropped along <paramref name="up"/> onto the plane, stands on the polygon: inside
    /// the outline, within half the radius of an edge, or within half the radius of a vertex.
    /// </summary>
    // retail: CPolygon::check_small_walkable (acclient.c:360311)
    public bool CheckSmallWalkable(in Sphere sphere, Vector3 up)
    {
        if (!DropOntoPlane(sphere.Center, up, out Vector3 center))
        {
            return false;
        }

        float inside = (float)((double)sphere.Radius * sphere.Radius * 0.25);
        return DiscTouches(center, inside);
    }

    /// <summary>True when <paramref name="point"/> (in the plane) is inside every edge.</summary>
    // retail: CPolygon::point_in_polygon (acclient.c:360176)
    public bool PointInPolygon(Vector3 point)
    {
        Vector3[] v = _vertices;
        Vector3 prev = v[v.Length - 1];
        for (int i = 0; i < v.Length; i++)
        {
            Vector3 cur = v[i];
            double ex = (double)cur.X - prev.X;
            double ey = (double)cur.Y - prev.Y;
            double ez = (double)cur.Z - prev.Z;
            float normX = (float)(ez * Plane.N.Y - ey * Plane.N.Z);
            float normY = (float)(ex * Plane.N.Z - ez * Plane.N.X);
            double cross = ((double)point.Z - prev.Z) * (ey * Plane.N.X - ex * Plane.N.Y)
                           + ((double)point.Y - prev.Y) * normY
                           + ((double)point.X - prev.X) * normX;
            if (cross < 0.0)
            {
                return false;
            }

            prev = cur;
        }

        return true;
    }

    /// <summary>
    /// Moves <paramref name="validPos"/> back along <paramref name="movement"/> until it rests on the plane (touching
    /// it from the side it came from), and spends that fraction of the path's remaining step (<c>walk_interp</c>).
    /// False (nothing moved) when the movement runs along the plane or the fraction is out of range.
    /// </summary>
    // retail: CPolygon::adjust_sphere_to_plane (acclient.c:359533)
    internal bool AdjustSphereToPlane(SpherePath path, ref Sphere validPos, Vector3 movement)
    {
        double dist = Plane.N.Y * (double)validPos.Center.Y + Plane.N.Z * (double)validPos.Center.Z + validPos.Center.X * (double)Plane.N.X + Plane.D;
        double dp = Plane.N.Z * (double)movement.Z + Plane.N.Y * (double)movement.Y + Plane.N.X * (double)movement.X;
        double num;
        if (dp <= PhysicsGlobals.Epsilon)
        {
            if (dp >= -PhysicsGlobals.Epsilon)
            {
                return false;
            }

            num = dist - validPos.Radius;
        }
        else
        {
            num = -(double)validPos.Radius - dist;
        }

        double t = num / dp;
        double interp = (1.0 - t) * path.WalkInterp;
        float interpF = (float)interp;
        if (interp >= path.WalkInterp || interpF < -0.5)
        {
            return false;
        }

        float my = (float)(t * movement.Y);
        float mz = (float)(t * movement.Z);
        validPos.Center = new Vector3((float)(validPos.Center.X - t * movement.X), validPos.Center.Y - my, validPos.Center.Z - mz);
        path.WalkInterp = interpF;
        return true;
    }

    /// <summary>
    /// The fraction of <paramref name="movement"/> (from <paramref name="currPos"/>) at which a sphere of the check
    /// sphere's radius touches the plane from the side <paramref name="currPos"/> is on: 1 when it already overlaps the
    /// plane at <paramref name="currPos"/>, 0 when the movement runs along the plane.
    /// </summary>
    /// <remarks>The side test is a flags-only compare in the decompile (C0|C3 on the current distance), read as
    /// "distance ≤ 0": the radius is negated for a centre behind the plane.</remarks>
    // retail: CPolygon::adjust_sphere_to_poly (acclient.c:359497)
    internal double AdjustSphereToPoly(in Sphere checkPos, Vector3 currPos, Vector3 movement)
    {
        float dist = (float)((double)Plane.N.Z * currPos.Z + (double)Plane.N.Y * currPos.Y + currPos.X * (double)Plane.N.X + Plane.D);
        if (!(checkPos.Radius <= Math.Abs(dist)))
        {
            return 1.0;
        }

        double dp = (double)Plane.N.Z * movement.Z + (double)Plane.N.Y * movement.Y + movement.X * (double)Plane.N.X;
        if (!(Math.Abs(dp) >= PhysicsGlobals.Epsilon))
        {
            return 0.0;
        }

        double r = checkPos.Radius;
        if (dist <= 0f)
        {
            r = -r;
        }

        return (r - dist) / dp;
    }

    /// <summary>
    /// Pushes a placed sphere (and its companion) out of the polygon along the normal: to the radius in front of it, or,
    /// for a solid test, to the radius on the side the centre is on (the far side when the centre is in a solid leaf).
    /// </summary>
    // retail: CPolygon::adjust_to_placement_poly (acclient.c:360136)
    internal void AdjustToPlacementPoly(ref Sphere struckSphere, ref Sphere otherSphere, float radius, bool centerSolid, bool solidCheck)
    {
        double dist = Plane.N.Y * (double)struckSphere.Center.Y + Plane.N.Z * (double)struckSphere.Center.Z + struckSphere.Center.X * (double)Plane.N.X + Plane.D;
        double move;
        if (solidCheck)
        {
            double r = radius;
            if (centerSolid)
            {
                r *= -1.0;
            }

            if (dist <= 0.0)
            {
                r = -r;
            }

            move = r - dist;
        }
        else
        {
            move = radius - dist;
        }

        float my = (float)(move * Plane.N.Y);
        double mx = move * Plane.N.X;
        float mz = (float)(move * Plane.N.Z);
        struckSphere.Center = new Vector3((float)(mx + struckSphere.Center.X), my + struckSphere.Center.Y, mz + struckSphere.Center.Z);
        otherSphere.Center = new Vector3((float)(mx + otherSphere.Center.X), my + otherSphere.Center.Y, mz + otherSphere.Center.Z);
    }

    private enum EdgeTest
    {
        Inside,
        OutsideNear,
        Hit,
        Miss,
    }

    private Vector3 Project(Vector3 c, double dist)
    {
        float pz = (float)(dist * Plane.N.Z);
        float x = (float)(c.X - dist * Plane.N.X);
        float y = (float)(c.Y - dist * Plane.N.Y);
        float z = (float)(c.Z - (double)pz);
        return new Vector3(x, y, z);
    }

    // The edge walk shared by polygon_hits_sphere, check_walkable and check_small_walkable (the three print the same loop,
    // acclient.c:359915, 360226, 360311): a disc of squared radius radsq around a point in the
    // polygon's plane touches the polygon when it is inside every edge, or reaches an edge segment or a vertex; an edge it is
    // outside of by more than the radius ends the walk with a miss.
    private bool DiscTouches(Vector3 point, float radsq)
    {
        bool inside = true;
        Vector3[] v = _vertices;
        Vector3 prev = v[v.Length - 1];
        for (int i = 0; i < v.Length; i++)
        {
            Vector3 cur = v[i];
            EdgeTest t = TestEdge(prev, cur, point, radsq);
            if (t == EdgeTest.Miss)
            {
                return false;
            }

            if (t == EdgeTest.Hit || VertexWithin(prev, point, radsq))
            {
                return true;
            }

            if (t == EdgeTest.OutsideNear)
            {
                inside = false;
            }

            prev = cur;
        }

        return inside;
    }

    // One edge of the polygon_hits_sphere family: Inside (cross >= 0), Miss (outside by more than the radius, BSP-B1),
    // Hit (outside within the radius and the point projects onto the edge segment), OutsideNear (otherwise).
    private EdgeTest TestEdge(Vector3 prev, Vector3 cur, Vector3 point, float radsq)
    {
        float ex = cur.X - prev.X;
        float ey = cur.Y - prev.Y;
        double ezd = (double)cur.Z - prev.Z;
        float ez = (float)ezd;
        float dx = point.X - prev.X;
        float dy = point.Y - prev.Y;
        double dzd = (double)point.Z - prev.Z;
        float dz = (float)dzd;
        Vector3 n = Plane.N;
        double cross = dzd * ((double)ey * n.X - (double)ex * n.Y)
                       + (double)dy * ((double)ex * n.Z - (double)ez * n.X)
                       + (double)dx * (ezd * n.Y - (double)ey * n.Z);
        if (cross >= 0.0)
        {
            return EdgeTest.Inside;
        }

        double edgeSq = (double)ez * ez + (double)ey * ey + (double)ex * ex;
        if (cross * cross > radsq * edgeSq)
        {
            return EdgeTest.Miss;
        }

        double along = (double)dz * ez + (double)dy * ey + (double)dx * ex;
        if (along >= 0.0 && along <= edgeSq)
        {
            return EdgeTest.Hit;
        }

        return EdgeTest.OutsideNear;
    }

    private static bool VertexWithin(Vector3 vertex, Vector3 point, float radsq)
    {
        float dx = point.X - vertex.X;
        float dy = point.Y - vertex.Y;
        float dz = point.Z - vertex.Z;
        return (double)dz * dz + (double)dy * dy + (double)dx * dx <= radsq;
    }
}
