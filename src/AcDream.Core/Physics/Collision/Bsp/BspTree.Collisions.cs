using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision.Bsp;

// The BSP as a collision body of the sweep: the entry points a cell or a physics part calls with the transition's
// spheres already in the tree's local space (the sphere path's CacheLocalSpaceSphere), and their helpers. Results go
// back to landblock space through the sphere path's LocalSpacePos and the owner's scale.
public sealed partial class BspTree
{
    /// <summary>Most rounds of <see cref="PlacementInsert"/>. Retail: 20 (acclient.c:360778).</summary>
    public const int MaxPlacementRounds = 20;

    /// <summary>Most iterations of the sphere's adjustment back to a hit plane (retail <c>BSPTREE::adjust_to_plane</c>). Retail: 15 (acclient.c:360915).</summary>
    public const int MaxAdjustIterations = 15;

    /// <summary>Bisection stops when the time bracket is narrower than this. Retail: 0.02 (acclient.c:360915).</summary>
    public const double AdjustTimeTolerance = 0.02;

    /// <summary>
    /// The tree against the transition's local-space spheres, by the sweep's mode: placement (any touch or solid centre
    /// collides), a walkable probe, a step down (stand on the highest walkable polygon below), a step-up check (the
    /// collide request), or a move — on the ground a hit asks for a step up, in the air it asks for a step-up check
    /// (landing), and a clipped path (missile) stops at the surface.
    /// </summary>
    /// <param name="transition">The transition; its local-space spheres must be cached for this tree's space.</param>
    /// <param name="scale">The scale of the tree's owner (results are scaled back by it).</param>
    /// <returns>The transition state (OK, Collided, Adjusted or Slid).</returns>
    // retail: BSPTREE::find_collisions (acclient.c:361295)
    internal TransitionState FindCollisions(Transition transition, float scale)
    {
        ArgumentNullException.ThrowIfNull(transition);
        SpherePath path = transition.SpherePath;
        CollisionInfo ci = transition.CollisionInfo;
        Sphere s0 = path.LocalSpaceSphere[0];
        Vector3 cc = path.LocalSpaceCurrCenter[0];
        var movement = new Vector3(
            (float)((double)s0.Center.X - cc.X),
            (float)((double)s0.Center.Y - cc.Y),
            (float)((double)s0.Center.Z - cc.Z));

        if (path.InsertType == InsertType.Placement || path.ObstructionEthereal)
        {
            bool centerCheck = !path.BldgCheck || !path.HitsInteriorCell;
            if (SphereIntersectsSolid(s0, centerCheck)
                || (path.NumSphere > 1 && SphereIntersectsSolid(path.LocalSpaceSphere[1], centerCheck)))
            {
                return TransitionState.Collided;
            }

            return TransitionState.Ok;
        }

        if (path.CheckWalkable)
        {
            return CheckWalkable(path, s0, scale);
        }

        if (path.StepDown)
        {
            return StepSphereDown(path, ci, s0, scale);
        }

        Polygon? hitPoly = null;
        if (path.Collide)
        {
            Sphere valid = s0;
            Polygon? walkable = null;
            bool changed = false;
            FindWalkable(path, ref valid, ref walkable, movement, path.LocalSpaceZ, ref changed);
            if (changed && walkable is not null)
            {
                Vector3 off = ScaledLocalToGlobal(path, valid.Center, s0.Center, scale);
                path.AddOffsetToCheckPos(off);
                CollisionPlane plane = PlaneSpace.LocalToGlobal(path.CheckPos, path.LocalSpacePos, walkable.Plane);
                plane.D = (float)(plane.D * (double)scale);
                ci.SetContactPlane(plane, false);
                ci.ContactPlaneCellId = path.CheckPos.ObjCellId;
                path.SetWalkable(valid, walkable, path.LocalSpaceZ, path.LocalSpacePos, scale);
                return TransitionState.Adjusted;
            }

            return TransitionState.Ok;
        }

        ObjectInfoState state = transition.ObjectInfo.State;
        if ((state & ObjectInfoState.Contact) != 0)
        {
            if (SphereIntersectsPoly(s0, movement, ref hitPoly, out _))
            {
                return StepSphereUp(transition, hitPoly!.Plane.N);
            }

            if (path.NumSphere > 1)
            {
                Polygon? hit2 = null;
                if (SphereIntersectsPoly(path.LocalSpaceSphere[1], movement, ref hit2, out _))
                {
                    return SlideSphere(path, ci, hit2!.Plane.N);
                }

                if (hit2 is not null)
                {
                    path.SetNegPolyHit(false, path.LocalSpacePos.LocalToGlobalVec(hit2.Plane.N));
                    return TransitionState.Ok;
                }

                if (hitPoly is not null)
                {
                    path.SetNegPolyHit(true, path.LocalSpacePos.LocalToGlobalVec(hitPoly.Plane.N));
                    return TransitionState.Ok;
                }
            }

            return TransitionState.Ok;
        }

        if ((state & ObjectInfoState.PathClipped) == 0)
        {
            if (SphereIntersectsPoly(s0, movement, ref hitPoly, out _) || hitPoly is not null)
            {
                path.SetCollide(path.LocalSpacePos.LocalToGlobalVec(hitPoly!.Plane.N));
                path.WalkableAllowance = PhysicsGlobals.LandingZ;
                return TransitionState.Adjusted;
            }

            if (path.NumSphere > 1
                && (SphereIntersectsPoly(path.LocalSpaceSphere[1], movement, ref hitPoly, out _) || hitPoly is not null))
            {
                ci.SetCollisionNormal(path.LocalSpacePos.LocalToGlobalVec(hitPoly!.Plane.N));
                return TransitionState.Collided;
            }

            return TransitionState.Ok;
        }

        if (SphereIntersectsPoly(s0, movement, ref hitPoly, out Vector3 contact) || hitPoly is not null)
        {
            return CollideWithPt(transition.ObjectInfo, path, ci, s0, cc, hitPoly!, contact, scale);
        }

        return TransitionState.Ok;
    }

    /// <summary>
    /// Initial placement against the tree: while a local-space sphere touches a polygon (or sits in a solid leaf), push
    /// both spheres out along that polygon's normal; a solid centre without a polygon doubles the test radius. Up to
    /// <see cref="MaxPlacementRounds"/> rounds; the accumulated push moves the check position.
    /// </summary>
    /// <returns>OK when nothing was touched, Adjusted after a push that freed the spheres, Collided when no free place
    /// was found.</returns>
    // retail: BSPTREE::placement_insert (acclient.c:360778)
    internal TransitionState PlacementInsert(Transition transition)
    {
        ArgumentNullException.ThrowIfNull(transition);
        SpherePath path = transition.SpherePath;
        Sphere valid = path.LocalSpaceSphere[0];
        Sphere valid2 = path.NumSphere > 1 ? path.LocalSpaceSphere[1] : default;
        float radius = valid.Radius;
        bool centerCheck = !path.BldgCheck || !path.HitsInteriorCell;
        Polygon? hitPoly = null;
        for (int i = 0; i < MaxPlacementRounds; i++)
        {
            bool centerSolid = false;
            if (SphereIntersectsSolidPoly(valid, radius, ref centerSolid, ref hitPoly, centerCheck))
            {
                if (hitPoly is null)
                {
                    radius = radius + radius;
                    continue;
                }

                hitPoly.AdjustToPlacementPoly(ref valid, ref valid2, radius, centerSolid, centerCheck);
                hitPoly = null;
                radius = valid.Radius;
                continue;
            }

            if (path.NumSphere <= 1)
            {
                return PlacementResult(path, i, valid);
            }

            if (!SphereIntersectsSolidPoly(valid2, radius, ref centerSolid, ref hitPoly, centerCheck))
            {
                return PlacementResult(path, i, valid);
            }

            if (hitPoly is null)
            {
                radius = radius + radius;
                continue;
            }

            hitPoly.AdjustToPlacementPoly(ref valid2, ref valid, radius, centerSolid, centerCheck);
            hitPoly = null;
            radius = valid.Radius;
        }

        return TransitionState.Collided;
    }

    /// <summary>
    /// Moves the sphere back along its movement from <paramref name="currPos"/> until it just touches
    /// <paramref name="hitPoly"/> (following further polygons it then hits), then bisects the time to within
    /// <see cref="AdjustTimeTolerance"/>; <paramref name="checkPos"/> ends at the last free time. False after
    /// <see cref="MaxAdjustIterations"/> hits without a free time.
    /// </summary>
    /// <remarks>Retail ambiguity BSP-B3: the loop's exit test is flags-only (C3|C2) on the time returned by
    /// <see cref="Polygon.AdjustSphereToPoly"/>, read as "time == 0" (the movement runs along the plane: no touching
    /// time, go straight to the bisection).</remarks>
    // retail: BSPTREE::adjust_to_plane (acclient.c:360915)
    internal bool AdjustToPlane(ref Sphere checkPos, Vector3 currPos, Polygon hitPoly, ref Vector3 contactPoint)
    {
        ArgumentNullException.ThrowIfNull(hitPoly);
        double utime = 1.0;
        double ltime = 0.0;
        var movement = new Vector3(checkPos.Center.X - currPos.X, checkPos.Center.Y - currPos.Y, checkPos.Center.Z - currPos.Z);
        int n = 0;
        Polygon? poly = hitPoly;
        while (true)
        {
            double t = poly!.AdjustSphereToPoly(checkPos, currPos, movement);
            if (t == 0.0 || double.IsNaN(t))
            {
                break;
            }

            checkPos.Center = At(currPos, movement, t);
            if (!SphereIntersectsPoly(checkPos, movement, ref poly, out Vector3 cp))
            {
                ltime = t;
                break;
            }

            contactPoint = cp;
            n++;
            utime = t;
            if (n >= MaxAdjustIterations)
            {
                return false;
            }
        }

        while (n < MaxAdjustIterations)
        {
            double mid = (ltime + utime) * 0.5;
            checkPos.Center = At(currPos, movement, mid);
            if (SphereIntersectsPoly(checkPos, movement, ref poly, out Vector3 cp))
            {
                contactPoint = cp;
                utime = mid;
            }
            else
            {
                ltime = mid;
            }

            if (utime - ltime < AdjustTimeTolerance)
            {
                break;
            }

            n++;
        }

        checkPos.Center = At(currPos, movement, ltime);
        return true;
    }

    /// <summary>
    /// A clipped path (missile) hit <paramref name="hitPoly"/>: without PERFECT_CLIP it just collides with the polygon's
    /// normal; with it, the sphere is moved back to where it touches (<see cref="AdjustToPlane"/>).
    /// </summary>
    // retail: BSPTREE::collide_with_pt (acclient.c:361123)
    internal TransitionState CollideWithPt(ObjectInfo obj, SpherePath path, CollisionInfo collisions, in Sphere checkPos, Vector3 currPos,
        Polygon hitPoly, Vector3 contactPoint, float scale)
    {
        ArgumentNullException.ThrowIfNull(obj);
        ArgumentNullException.ThrowIfNull(path);
        ArgumentNullException.ThrowIfNull(collisions);
        ArgumentNullException.ThrowIfNull(hitPoly);
        if ((obj.State & ObjectInfoState.PerfectClip) == 0)
        {
            ref readonly Frame f = ref path.LocalSpacePos.Frame;
            Vector3 n = hitPoly.Plane.N;
            var g = new Vector3(
                (float)((double)f.M11 * n.X + (double)f.M21 * n.Y + (double)f.M31 * n.Z),
                (float)((double)f.M12 * n.X + (double)f.M22 * n.Y + (double)f.M32 * n.Z),
                (float)((double)f.M13 * n.X + (double)f.M23 * n.Y + (double)f.M33 * n.Z));
            collisions.SetCollisionNormal(g);
            return TransitionState.Collided;
        }

        Sphere valid = checkPos;
        if (!AdjustToPlane(ref valid, currPos, hitPoly, ref contactPoint))
        {
            return TransitionState.Collided;
        }

        collisions.SetCollisionNormal(path.LocalSpacePos.LocalToGlobalVec(hitPoly.Plane.N));
        path.AddOffsetToCheckPos(ScaledLocalToGlobal(path, valid.Center, checkPos.Center, scale));
        return TransitionState.Adjusted;
    }

    /// <summary>
    /// The step-down probe: the sphere is moved down by the remaining step (<c>step_down_amt · walk_interp</c> along the
    /// local up axis, divided by the scale) onto the walkable polygons it meets; on success the check position follows,
    /// the contact plane becomes that polygon's plane and the polygon is remembered as the walkable.
    /// </summary>
    // retail: BSPTREE::step_sphere_down (acclient.c:361176)
    internal TransitionState StepSphereDown(SpherePath path, CollisionInfo collisions, in Sphere checkPos, float scale)
    {
        ArgumentNullException.ThrowIfNull(path);
        ArgumentNullException.ThrowIfNull(collisions);
        double down = -((double)path.StepDownAmt * path.WalkInterp);
        Vector3 z = path.LocalSpaceZ;
        float tx = (float)(down * z.X);
        float ty = (float)(down * z.Y);
        double tz = down * z.Z;
        double inv = 1.0 / scale;
        float invF = (float)inv;
        var trans = new Vector3((float)(inv * tx), (float)((double)ty * invF), (float)(tz * invF));
        Sphere valid = checkPos;
        Polygon? walkable = null;
        bool changed = false;
        FindWalkable(path, ref valid, ref walkable, trans, z, ref changed);
        if (!changed || walkable is null)
        {
            return TransitionState.Ok;
        }

        Vector3 off = ScaledLocalToGlobal(path, valid.Center, checkPos.Center, scale);
        path.CellArrayValid = false;
        Vector3 o = path.CheckPos.Frame.Origin;
        path.CheckPos.Frame.Origin = new Vector3(off.X + o.X, off.Y + o.Y, off.Z + o.Z);
        path.CacheGlobalSphere(off);
        CollisionPlane plane = PlaneSpace.LocalToGlobal(path.CheckPos, path.LocalSpacePos, walkable.Plane);
        plane.D = (float)(plane.D * (double)scale);
        collisions.ContactPlaneValid = true;
        collisions.ContactPlane = plane;
        collisions.ContactPlaneIsWater = false;
        collisions.ContactPlaneCellId = path.CheckPos.ObjCellId;
        path.SetWalkable(valid, walkable, z, path.LocalSpacePos, scale);
        return TransitionState.Adjusted;
    }

    /// <summary>A grounded sphere hit a polygon: try to step up onto it (normal lifted to landblock space); else slide along it.</summary>
    // retail: BSPTREE::step_sphere_up (acclient.c:361071)
    internal static TransitionState StepSphereUp(Transition transition, Vector3 collisionNormal)
    {
        ArgumentNullException.ThrowIfNull(transition);
        Vector3 n = LocalNormalToGlobal(transition.SpherePath, collisionNormal);
        if (transition.StepUp(n))
        {
            return TransitionState.Ok;
        }

        return transition.SpherePath.StepUpSlide(transition.CollisionInfo);
    }

    /// <summary>Slides the first global sphere along a local-space normal lifted to landblock space.</summary>
    // retail: BSPTREE::slide_sphere (acclient.c:361030)
    internal static TransitionState SlideSphere(SpherePath path, CollisionInfo collisions, Vector3 collisionNormal)
    {
        ArgumentNullException.ThrowIfNull(path);
        ArgumentNullException.ThrowIfNull(collisions);
        Vector3 n = LocalNormalToGlobal(path, collisionNormal);
        return path.GlobalSphere[0].SlideSphere(path, collisions, ref n, path.GlobalCurrCenter[0]);
    }

    /// <summary>The walkable probe: Collided when the sphere stands on a walkable polygon of the tree, OK otherwise.</summary>
    // retail: BSPTREE::check_walkable (acclient.c:361051)
    internal TransitionState CheckWalkable(SpherePath path, in Sphere checkPos, float scale)
    {
        ArgumentNullException.ThrowIfNull(path);
        Sphere valid = checkPos;
        return HitsWalkable(path, valid, path.LocalSpaceZ) ? TransitionState.Collided : TransitionState.Ok;
    }

    private static TransitionState PlacementResult(SpherePath path, int round, in Sphere valid)
    {
        if (round == 0)
        {
            return TransitionState.Ok;
        }

        // Both exits of retail's loop add the local push lifted to landblock space (no scale: placement runs unscaled).
        Vector3 s0 = path.LocalSpaceSphere[0].Center;
        var local = new Vector3(
            (float)((double)valid.Center.X - s0.X),
            (float)((double)valid.Center.Y - s0.Y),
            (float)((double)valid.Center.Z - s0.Z));
        path.AddOffsetToCheckPos(path.LocalSpacePos.LocalToGlobalVec(local));
        return TransitionState.Adjusted;
    }

    private static Vector3 LocalNormalToGlobal(SpherePath path, Vector3 n)
    {
        ref readonly Frame f = ref path.LocalSpacePos.Frame;
        return new Vector3(
            (float)((double)f.M31 * n.Z + (double)f.M11 * n.X + (double)f.M21 * n.Y),
            (float)((double)f.M32 * n.Z + (double)f.M12 * n.X + (double)f.M22 * n.Y),
            (float)((double)f.M33 * n.Z + (double)f.M13 * n.X + (double)f.M23 * n.Y));
    }

    private static Vector3 ScaledLocalToGlobal(SpherePath path, Vector3 to, Vector3 from, float scale)
    {
        var local = new Vector3(to.X - from.X, to.Y - from.Y, to.Z - from.Z);
        Vector3 g = path.LocalSpacePos.LocalToGlobalVec(local);
        return new Vector3(g.X * scale, g.Y * scale, g.Z * scale);
    }

    private static Vector3 At(Vector3 start, Vector3 movement, double t)
    {
        float x = (float)(movement.X * t);
        float y = (float)(movement.Y * t);
        return new Vector3(x + start.X, (float)((double)y + start.Y), (float)(t * movement.Z + start.Z));
    }
}
