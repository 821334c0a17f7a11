using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision.Bsp;

// The recursive sphere queries of the BSP (retail's virtual BSPNODE / BSPLEAF pairs). A split node first rejects
// spheres that miss its bounding sphere, then descends into the positive child when the centre is at least radius -
// EPSILON in front of the plane, the negative child when at least that far behind, and both otherwise (retail's order).
// A missing child (index -1) behaves as an empty leaf.
public sealed partial class BspTree
{
    /// <summary>
    /// True when the moving sphere hits the front of a polygon while moving into it. <paramref name="hitPoly"/> receives
    /// the last polygon touched, including one the movement leaves (a negative-side hit, for which the query returns
    /// false); <paramref name="contactPoint"/> the centre's projection on the hit polygon's plane.
    /// </summary>
    // retail: BSPTREE root -> BSPNODE::sphere_intersects_poly (acclient.c:363521) / BSPLEAF::sphere_intersects_poly (acclient.c:364199)
    public bool SphereIntersectsPoly(in Sphere checkPos, Vector3 movement, ref Polygon? hitPoly, out Vector3 contactPoint)
    {
        contactPoint = default;
        return SphereIntersectsPoly(Root, checkPos, movement, ref hitPoly, ref contactPoint);
    }

    /// <summary>True when the sphere touches a polygon of a leaf, or (with <paramref name="centerCheck"/>) lies in a solid leaf.</summary>
    // retail: BSPNODE::sphere_intersects_solid (acclient.c:363573) / BSPLEAF::sphere_intersects_solid (acclient.c:364235)
    public bool SphereIntersectsSolid(in Sphere checkPos, bool centerCheck) => SphereIntersectsSolid(Root, checkPos, centerCheck);

    /// <summary>
    /// Like <see cref="SphereIntersectsSolid(in Sphere, bool)"/> for placement, using <paramref name="radius"/> for the plane tests:
    /// <paramref name="hitPoly"/> receives the first polygon touched and <paramref name="centerSolid"/> is set when the centre
    /// lies in a solid leaf (with <paramref name="centerCheck"/>).
    /// </summary>
    // retail: BSPNODE::sphere_intersects_solid_poly (acclient.c:363713) / BSPLEAF::sphere_intersects_solid_poly (acclient.c:364344)
    public bool SphereIntersectsSolidPoly(in Sphere checkPos, float radius, ref bool centerSolid, ref Polygon? hitPoly, bool centerCheck) =>
        SphereIntersectsSolidPoly(Root, checkPos, radius, ref centerSolid, ref hitPoly, centerCheck);

    /// <summary>True when the sphere touches a polygon it can stand on (steep enough for the path's walkable allowance, and
    /// standing on it within half the radius).</summary>
    // retail: BSPNODE::hits_walkable (acclient.c:363614) / BSPLEAF::hits_walkable (acclient.c:364274)
    internal bool HitsWalkable(SpherePath path, in Sphere validPos, Vector3 up) => HitsWalkable(Root, path, validPos, up);

    /// <summary>
    /// Every walkable polygon the sphere touches moves it back along <paramref name="movement"/> onto its plane
    /// (<see cref="Polygon.AdjustSphereToPlane"/>); <paramref name="polygon"/> receives the last one that did, and
    /// <paramref name="changed"/> is set.
    /// </summary>
    // retail: BSPNODE::find_walkable (acclient.c:363662) / BSPLEAF::find_walkable (acclient.c:364310)
    internal void FindWalkable(SpherePath path, ref Sphere validPos, ref Polygon? polygon, Vector3 movement, Vector3 up, ref bool changed) =>
        FindWalkable(Root, path, ref validPos, ref polygon, movement, up, ref changed);

    /// <summary>True when the point is in a solid leaf (negative side: plane distance &lt; 0).</summary>
    // retail: BSPNODE::point_intersects_solid (acclient.c:363025) / BSPLEAF::point_intersects_solid (acclient.c:364085)
    public bool PointIntersectsSolid(Vector3 point)
    {
        int i = Root;
        while (i >= 0)
        {
            ref readonly BspNode n = ref _nodes[i];
            if (n.IsLeaf)
            {
                return n.NumPolys != 0;
            }

            i = n.SplittingPlane.DotProduct(point) < 0.0 ? n.NegNode : n.PosNode;
        }

        return false;
    }

    private bool SphereIntersectsPoly(int i, in Sphere checkPos, Vector3 movement, ref Polygon? hitPoly, ref Vector3 contactPoint)
    {
        if (i < 0)
        {
            return false;
        }

        ref readonly BspNode n = ref _nodes[i];
        if (n.IsLeaf)
        {
            if (n.NumPolys == 0 || !n.Sphere.Intersects(checkPos))
            {
                return false;
            }

            for (int p = 0; p < n.NumPolys; p++)
            {
                if (Poly(n, p).PosHitsSphere(checkPos, movement, out Vector3 cp, ref hitPoly))
                {
                    contactPoint = cp;
                    return true;
                }
            }

            return false;
        }

        switch (Descend(n, checkPos, checkPos.Radius, out _))
        {
            case Side.Miss:
                return false;
            case Side.Pos:
                return SphereIntersectsPoly(n.PosNode, checkPos, movement, ref hitPoly, ref contactPoint);
            case Side.Neg:
                return SphereIntersectsPoly(n.NegNode, checkPos, movement, ref hitPoly, ref contactPoint);
        }

        return SphereIntersectsPoly(n.PosNode, checkPos, movement, ref hitPoly, ref contactPoint)
               || SphereIntersectsPoly(n.NegNode, checkPos, movement, ref hitPoly, ref contactPoint);
    }

    private bool SphereIntersectsSolid(int i, in Sphere checkPos, bool centerCheck)
    {
        if (i < 0)
        {
            return false;
        }

        ref readonly BspNode n = ref _nodes[i];
        if (n.IsLeaf)
        {
            if (n.NumPolys == 0)
            {
                return false;
            }

            if (centerCheck && n.Solid)
            {
                return true;
            }

            if (!n.Sphere.Intersects(checkPos))
            {
                return false;
            }

            for (int p = 0; p < n.NumPolys; p++)
            {
                if (Poly(n, p).HitsSphere(checkPos))
                {
                    return true;
                }
            }

            return false;
        }

        switch (Descend(n, checkPos, checkPos.Radius, out double dist))
        {
            case Side.Miss:
                return false;
            case Side.Pos:
                return SphereIntersectsSolid(n.PosNode, checkPos, centerCheck);
            case Side.Neg:
                return SphereIntersectsSolid(n.NegNode, checkPos, centerCheck);
        }

        // Straddling: the centre test applies only on the side the centre is on.
        if (dist < 0.0)
        {
            return SphereIntersectsSolid(n.PosNode, checkPos, false) || SphereIntersectsSolid(n.NegNode, checkPos, centerCheck);
        }

        return SphereIntersectsSolid(n.PosNode, checkPos, centerCheck) || SphereIntersectsSolid(n.NegNode, checkPos, false);
    }

    private bool SphereIntersectsSolidPoly(int i, in Sphere checkPos, float radius, ref bool centerSolid, ref Polygon? hitPoly, bool centerCheck)
    {
        if (i < 0)
        {
            return false;
        }

        ref readonly BspNode n = ref _nodes[i];
        if (n.IsLeaf)
        {
            if (n.NumPolys == 0)
            {
                return false;
            }

            if (centerCheck && n.Solid)
            {
                centerSolid = true;
            }

            if (n.Sphere.Intersects(checkPos))
            {
                for (int p = 0; p < n.NumPolys; p++)
                {
                    Polygon poly = Poly(n, p);
                    if (poly.HitsSphere(checkPos))
                    {
                        hitPoly = poly;
                        return true;
                    }
                }
            }

            return centerSolid;
        }

        switch (Descend(n, checkPos, radius, out double dist))
        {
            case Side.Miss:
                return false;
            case Side.Pos:
                return SphereIntersectsSolidPoly(n.PosNode, checkPos, radius, ref centerSolid, ref hitPoly, centerCheck);
            case Side.Neg:
                return SphereIntersectsSolidPoly(n.NegNode, checkPos, radius, ref centerSolid, ref hitPoly, centerCheck);
        }

        if (dist < 0.0)
        {
            SphereIntersectsSolidPoly(n.NegNode, checkPos, radius, ref centerSolid, ref hitPoly, centerCheck);
            if (hitPoly is null)
            {
                return SphereIntersectsSolidPoly(n.PosNode, checkPos, radius, ref centerSolid, ref hitPoly, false);
            }
        }
        else
        {
            SphereIntersectsSolidPoly(n.PosNode, checkPos, radius, ref centerSolid, ref hitPoly, centerCheck);
            if (hitPoly is null)
            {
                return SphereIntersectsSolidPoly(n.NegNode, checkPos, radius, ref centerSolid, ref hitPoly, false);
            }
        }

        return centerSolid;
    }

    private bool HitsWalkable(int i, SpherePath path, in Sphere validPos, Vector3 up)
    {
        if (i < 0)
        {
            return false;
        }

        ref readonly BspNode n = ref _nodes[i];
        if (n.IsLeaf)
        {
            if (n.NumPolys == 0 || !n.Sphere.Intersects(validPos))
            {
                return false;
            }

            for (int p = 0; p < n.NumPolys; p++)
            {
                Polygon poly = Poly(n, p);
                if (poly.WalkableHitsSphere(path, validPos, up) && poly.CheckSmallWalkable(validPos, up))
                {
                    return true;
                }
            }

            return false;
        }

        switch (Descend(n, validPos, validPos.Radius, out _))
        {
            case Side.Miss:
                return false;
            case Side.Pos:
                return HitsWalkable(n.PosNode, path, validPos, up);
            case Side.Neg:
                return HitsWalkable(n.NegNode, path, validPos, up);
        }

        return HitsWalkable(n.PosNode, path, validPos, up) || HitsWalkable(n.NegNode, path, validPos, up);
    }

    private void FindWalkable(int i, SpherePath path, ref Sphere validPos, ref Polygon? polygon, Vector3 movement, Vector3 up, ref bool changed)
    {
        if (i < 0)
        {
            return;
        }

        ref readonly BspNode n = ref _nodes[i];
        if (n.IsLeaf)
        {
            if (n.NumPolys == 0 || !n.Sphere.Intersects(validPos))
            {
                return;
            }

            for (int p = 0; p < n.NumPolys; p++)
            {
                Polygon poly = Poly(n, p);
                if (poly.WalkableHitsSphere(path, validPos, up) && poly.AdjustSphereToPlane(path, ref validPos, movement))
                {
                    changed = true;
                    polygon = poly;
                }
            }

            return;
        }

        switch (Descend(n, validPos, validPos.Radius, out _))
        {
            case Side.Miss:
                return;
            case Side.Pos:
                FindWalkable(n.PosNode, path, ref validPos, ref polygon, movement, up, ref changed);
                return;
            case Side.Neg:
                FindWalkable(n.NegNode, path, ref validPos, ref polygon, movement, up, ref changed);
                return;
        }

        FindWalkable(n.PosNode, path, ref validPos, ref polygon, movement, up, ref changed);
        FindWalkable(n.NegNode, path, ref validPos, ref polygon, movement, up, ref changed);
    }

    private enum Side : byte
    {
        Miss,
        Pos,
        Neg,
        Both,
    }

    // The split node's step shared by the sphere queries: a sphere missing the node's bounding sphere goes nowhere; otherwise
    // the positive child when the centre is at least radius - EPSILON in front of the plane, the negative child when that far
    // behind, both otherwise. dist receives the centre's plane distance (0 on a miss).
    private static Side Descend(in BspNode n, in Sphere sphere, float radius, out double dist)
    {
        dist = 0.0;
        if (!n.Sphere.Intersects(sphere))
        {
            return Side.Miss;
        }

        dist = n.SplittingPlane.DotProduct(sphere.Center);
        double r = radius - (double)PhysicsGlobals.Epsilon;
        if (dist >= r)
        {
            return Side.Pos;
        }

        return dist <= -r ? Side.Neg : Side.Both;
    }
}
