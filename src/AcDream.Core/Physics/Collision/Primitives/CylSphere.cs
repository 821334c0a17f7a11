using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Collision.Primitives;

/// <summary>
/// A vertical cylinder with a flat top and bottom, the usual collision shape of creatures and many objects: the centre
/// of its bottom, its height and its radius. Retail: <c>CCylSphere</c> (acclient.h, PORTAL/cgeometry/CCylSphere.c).
/// </summary>
/// <remarks>
/// A setup's cylinder spheres are object-local and unscaled (<see cref="Objects.Parts.IPartCollision.CylSpheres"/>);
/// <see cref="IntersectsSphere(in Position, float, Transition)"/> scales and places one in the check position's
/// landblock before testing. Arithmetic follows the decompilation (x87 temporaries in double).
/// </remarks>
public partial struct CylSphere : IEquatable<CylSphere>
{
    // EPSILON as the x87 code loads it (the float 0.0002f widened).
    private const double EpsD = PhysicsGlobals.Epsilon;

    /// <summary>Centre of the bottom disc. Retail: <c>low_pt</c>.</summary>
    public Vector3 LowPt;

    /// <summary>Height, metres. Retail: <c>height</c>.</summary>
    public float Height;

    /// <summary>Radius, metres. Retail: <c>radius</c>.</summary>
    public float Radius;

    /// <summary>Creates a cylinder sphere.</summary>
    public CylSphere(Vector3 lowPt, float radius, float height)
    {
        LowPt = lowPt;
        Radius = radius;
        Height = height;
    }

    /// <summary>Retail <c>CCylSphere::UnPack</c> (acclient.c:361547): low point x, y, z, radius, then height (finite).</summary>
    // retail: CCylSphere::UnPack (acclient.c:361547)
    internal static CylSphere UnPack(ref RetailDataReader reader, string what)
    {
        Vector3 low = reader.ReadFiniteVector3(what);
        float radius = reader.ReadFiniteSingle(what);
        float height = reader.ReadFiniteSingle(what);
        return new CylSphere(low, radius, height);
    }

    /// <summary>True when this is a cylinder sphere the sweep can handle: finite low point, positive radius and height,
    /// |low point| + radius + height &lt;= <see cref="InputLimits.MaxShapeReach"/> (computed in double).</summary>
    internal readonly bool IsInDomain =>
        VectorMath.IsFinite(LowPt) && Radius > 0f && Height > 0f
        && VectorMath.Magnitude(LowPt) + Radius + (double)Height <= InputLimits.MaxShapeReach; // also NaN and ∞ sizes

    /// <summary>Throws when a cylinder sphere of <paramref name="cylSpheres"/> is outside <see cref="IsInDomain"/>.</summary>
    /// <exception cref="ArgumentException">A cylinder sphere is outside the domain (the message names its index).</exception>
    internal static void ThrowIfAnyOutside(ReadOnlySpan<CylSphere> cylSpheres, string paramName)
    {
        for (int i = 0; i < cylSpheres.Length; i++)
        {
            if (!cylSpheres[i].IsInDomain)
            {
                throw new ArgumentException(string.Create(System.Globalization.CultureInfo.InvariantCulture,
                    $"Cylinder sphere {i} needs a finite low point, a positive radius and height, and |low point| + radius + height at most 192 m (InputLimits.MaxShapeReach)."),
                    paramName);
            }
        }
    }

    /// <summary>
    /// True when the sphere <paramref name="checkPos"/>, whose centre is <paramref name="disp"/> from the bottom centre,
    /// overlaps the cylinder: within <paramref name="radsum"/> horizontally, and within half the height plus its radius
    /// (less EPSILON) of the cylinder's mid-height.
    /// </summary>
    // retail: CCylSphere::collides_with_sphere (acclient.c:361501)
    public readonly bool CollidesWithSphere(in Sphere checkPos, Vector3 disp, float radsum) =>
        (double)radsum * radsum >= (double)disp.X * disp.X + (double)disp.Y * disp.Y
        && checkPos.Radius - EpsD + Height * 0.5 >= Math.Abs(Height * 0.5 - disp.Z);

    /// <summary>
    /// This cylinder (local to the object at <paramref name="p"/>, scaled by <paramref name="scale"/>) against the
    /// transition's check spheres. Caches the spheres in the object's local space first (a step up reads it).
    /// </summary>
    // retail: CCylSphere::intersects_sphere(Position*, float, CTransition*) (acclient.c:362243)
    internal readonly TransitionState IntersectsSphere(in Position p, float scale, Transition transition)
    {
        ArgumentNullException.ThrowIfNull(transition);
        SpherePath path = transition.SpherePath;
        path.CacheLocalSpaceSphere(p, 1.0f);
        var low = new Vector3(scale * LowPt.X, scale * LowPt.Y, scale * LowPt.Z);
        var global = new CylSphere(path.CheckPos.LocalToGlobal(p, low), scale * Radius, scale * Height);
        return global.IntersectsSphere(transition);
    }

    /// <summary>
    /// This cylinder (in the check position's landblock) against the transition's check spheres: an overlap test during
    /// a placement or past an ethereal obstruction; a landing on top during a step down; an overlap test during a
    /// walkable probe; otherwise a step up (walkers), a point collision (path-clipped missiles) or a landing (fallers);
    /// once a landing was requested, the flat contact plane on top.
    /// </summary>
    // retail: CCylSphere::intersects_sphere(CTransition*) (acclient.c:362034)
    internal readonly TransitionState IntersectsSphere(Transition transition)
    {
        ArgumentNullException.ThrowIfNull(transition);
        SpherePath path = transition.SpherePath;
        CollisionInfo ci = transition.CollisionInfo;
        Sphere gs0 = path.GlobalSphere[0];
        Vector3 disp = Disp(gs0);
        float radsum = (float)(Radius - EpsD + gs0.Radius);
        if (path.InsertType == InsertType.Placement || path.ObstructionEthereal)
        {
            if (CollidesWithSphere(gs0, disp, radsum))
            {
                return TransitionState.Collided;
            }

            return path.NumSphere > 1 && CollidesWithSphere(path.GlobalSphere[1], Disp(path.GlobalSphere[1]), radsum)
                ? TransitionState.Collided
                : TransitionState.Ok;
        }

        if (path.StepDown)
        {
            return StepSphereDown(path, ci, gs0, disp, radsum);
        }

        if (path.CheckWalkable)
        {
            if (CollidesWithSphere(gs0, disp, radsum))
            {
                return TransitionState.Collided;
            }

            return path.NumSphere > 1 && CollidesWithSphere(path.GlobalSphere[1], Disp(path.GlobalSphere[1]), radsum)
                ? TransitionState.Collided
                : TransitionState.Ok;
        }

        if (!path.Collide)
        {
            ObjectInfoState state = transition.ObjectInfo.State;
            if ((state & (ObjectInfoState.Contact | ObjectInfoState.OnWalkable)) != 0)
            {
                if (CollidesWithSphere(gs0, disp, radsum))
                {
                    return StepSphereUp(transition, gs0, disp, radsum);
                }

                if (path.NumSphere > 1)
                {
                    Sphere gs1 = path.GlobalSphere[1];
                    Vector3 disp2 = Disp(gs1);
                    if (CollidesWithSphere(gs1, disp2, radsum))
                    {
                        return SlideSphere(path, ci, gs1, disp2, radsum, 1);
                    }
                }
            }
            else if ((state & ObjectInfoState.PathClipped) != 0)
            {
                if (CollidesWithSphere(gs0, disp, radsum))
                {
                    return CollideWithPoint(transition.ObjectInfo, path, ci, gs0, disp, radsum, 0);
                }
            }
            else
            {
                if (CollidesWithSphere(gs0, disp, radsum))
                {
                    return LandOnCylinder(path, gs0, disp, radsum);
                }

                if (path.NumSphere > 1)
                {
                    Sphere gs1 = path.GlobalSphere[1];
                    Vector3 disp2 = Disp(gs1);
                    if (CollidesWithSphere(gs1, disp2, radsum))
                    {
                        return CollideWithPoint(transition.ObjectInfo, path, ci, gs1, disp2, radsum, 1);
                    }
                }
            }

            return TransitionState.Ok;
        }

        if (!CollidesWithSphere(gs0, disp, radsum)
            && !(path.NumSphere > 1 && CollidesWithSphere(path.GlobalSphere[1], Disp(path.GlobalSphere[1]), radsum)))
        {
            return TransitionState.Ok;
        }

        return LandOnTop(path, ci, gs0, disp, radsum);
    }

    private readonly Vector3 Disp(in Sphere s) => new(s.Center.X - LowPt.X, s.Center.Y - LowPt.Y, s.Center.Z - LowPt.Z);

    // retail: CCylSphere::intersects_sphere (acclient.c:362034), the path.collide branch: move the check sphere back along
    // the step to where it rests on the top disc, and record the flat contact plane there.
    private readonly TransitionState LandOnTop(SpherePath path, CollisionInfo collisions, in Sphere gs0, Vector3 disp, float radsum)
    {
        Vector3 block = path.GetCurrPosCheckPosBlockOffset();
        Vector3 gcc = path.GlobalCurrCenter[0];
        var movement = new Vector3(gcc.X - gs0.Center.X - block.X, gcc.Y - gs0.Center.Y - block.Y, gcc.Z - gs0.Center.Z - block.Z);
        if (Math.Abs(movement.Z) < EpsD)
        {
            return TransitionState.Collided;
        }

        double t = ((double)Height + gs0.Radius - disp.Z) / movement.Z;
        float tf = (float)t;
        var offset = new Vector3(movement.X * tf, movement.Y * tf, movement.Z * tf);
        double ox = (double)offset.X + disp.X;
        double oy = (double)offset.Y + disp.Y;
        if ((double)radsum * radsum < oy * oy + ox * ox)
        {
            return TransitionState.Ok;
        }

        double interp = (1.0 - t) * path.WalkInterp;
        if (!(interp < path.WalkInterp && interp >= -0.1))
        {
            return TransitionState.Collided;
        }

        var point = new Vector3(gs0.Center.X + offset.X, gs0.Center.Y + offset.Y, (float)((double)gs0.Center.Z + offset.Z - gs0.Radius));
        collisions.SetContactPlane(Sphere.PlaneThrough(new Vector3(0f, 0f, 1f), point), true);
        collisions.ContactPlaneCellId = path.CheckPos.ObjCellId;
        path.WalkInterp = (float)interp;
        path.AddOffsetToCheckPos(offset);
        return TransitionState.Adjusted;
    }

    /// <summary>During a step down: lifts the check sphere onto the top disc when that is within what is left of the
    /// step, and records the flat contact plane there.</summary>
    // retail: CCylSphere::step_sphere_down (acclient.c:361573)
    private readonly TransitionState StepSphereDown(SpherePath path, CollisionInfo collisions, in Sphere checkPos, Vector3 disp, float radsum)
    {
        if (!CollidesWithSphere(checkPos, disp, radsum)
            && !(path.NumSphere > 1 && CollidesWithSphere(path.GlobalSphere[1], Disp(path.GlobalSphere[1]), radsum)))
        {
            return TransitionState.Ok;
        }

        double amt = (double)path.StepDownAmt * path.WalkInterp;
        if (Math.Abs(amt) < EpsD)
        {
            return TransitionState.Collided;
        }

        double lift = (double)Height + checkPos.Radius - disp.Z;
        double interp = (1.0 - lift / amt) * path.WalkInterp;
        if (interp >= path.WalkInterp || interp < -0.1)
        {
            return TransitionState.Collided;
        }

        float liftf = (float)lift;
        var point = new Vector3(checkPos.Center.X, checkPos.Center.Y, (float)((double)liftf - checkPos.Radius + checkPos.Center.Z));
        collisions.SetContactPlane(Sphere.PlaneThrough(new Vector3(0f, 0f, 1f), point), true);
        collisions.ContactPlaneCellId = path.CheckPos.ObjCellId;
        path.WalkInterp = (float)interp;
        path.AddOffsetToCheckPos(new Vector3(0f, 0f, liftf));
        return TransitionState.Adjusted;
    }

    /// <summary>
    /// The normal of the cylinder surface that check sphere <paramref name="sphereNum"/> hits: horizontal (from the axis)
    /// when its current centre is outside the radius, else the top (moving down) or the bottom. Returns whether the hit
    /// is definite: a side hit counts only when the current centre is already within the cylinder's height band or the
    /// step is level.
    /// </summary>
    // retail: CCylSphere::normal_of_collision (acclient.c:361651)
    internal readonly bool NormalOfCollision(SpherePath path, in Sphere checkPos, Vector3 disp, float radsum, int sphereNum, out Vector3 normal)
    {
        Vector3 curr = path.GlobalCurrCenter[sphereNum];
        double ox = (double)curr.X - LowPt.X;
        double oy = (double)curr.Y - LowPt.Y;
        float oz = (float)((double)curr.Z - LowPt.Z);
        if ((double)radsum * radsum < oy * oy + ox * ox)
        {
            normal = new Vector3((float)ox, (float)oy, 0f);
            return checkPos.Radius - EpsD + Height * 0.5 >= Math.Abs(Height * 0.5 - oz)
                   || Math.Abs((double)oz - disp.Z) <= EpsD;
        }

        normal = (double)disp.Z - oz <= 0.0 ? new Vector3(0f, 0f, 1f) : new Vector3(0f, 0f, -1f);
        return true;
    }

    /// <summary>Slides the check sphere along the cylinder surface it hit (the general sphere slide).</summary>
    // retail: CCylSphere::slide_sphere (acclient.c:361956)
    private readonly TransitionState SlideSphere(SpherePath path, CollisionInfo collisions, in Sphere checkPos, Vector3 disp, float radsum, int sphereNum)
    {
        NormalOfCollision(path, checkPos, disp, radsum, sphereNum, out Vector3 n);
        if (VectorMath.NormalizeCheckSmall(ref n))
        {
            return TransitionState.Collided;
        }

        return checkPos.SlideSphere(path, collisions, ref n, path.GlobalCurrCenter[sphereNum]);
    }

    /// <summary>A walker runs into the cylinder: climbs onto it when its top is within the step-up height above the
    /// sphere's bottom, otherwise slides along it.</summary>
    // retail: CCylSphere::step_sphere_up (acclient.c:361975)
    private readonly TransitionState StepSphereUp(Transition transition, in Sphere checkPos, Vector3 disp, float radsum)
    {
        SpherePath path = transition.SpherePath;
        if (transition.ObjectInfo.StepUpHeight < (double)checkPos.Radius + Height - disp.Z)
        {
            return SlideSphere(path, transition.CollisionInfo, checkPos, disp, radsum, 0);
        }

        NormalOfCollision(path, checkPos, disp, radsum, 0, out Vector3 n);
        if (VectorMath.NormalizeCheckSmall(ref n))
        {
            return TransitionState.Collided;
        }

        Vector3 up = path.LocalSpacePos.LocalToGlobalVec(n);
        if (transition.StepUp(up))
        {
            return TransitionState.Ok;
        }

        return path.StepUpSlide(transition.CollisionInfo);
    }

    /// <summary>A falling sphere touches the cylinder: asks for the landing test at the landing threshold.</summary>
    // retail: CCylSphere::land_on_cylinder (acclient.c:362014)
    private readonly TransitionState LandOnCylinder(SpherePath path, in Sphere checkPos, Vector3 disp, float radsum)
    {
        NormalOfCollision(path, checkPos, disp, radsum, 0, out Vector3 n);
        if (VectorMath.NormalizeCheckSmall(ref n))
        {
            return TransitionState.Collided;
        }

        path.SetCollide(n);
        path.WalkableAllowance = PhysicsGlobals.LandingZ;
        return TransitionState.Adjusted;
    }

    /// <inheritdoc />
    public readonly bool Equals(CylSphere other) => LowPt.Equals(other.LowPt) && Height.Equals(other.Height) && Radius.Equals(other.Radius);

    /// <inheritdoc />
    public override readonly bool Equals(object? obj) => obj is CylSphere c && Equals(c);

    /// <inheritdoc />
    public override readonly int GetHashCode() => HashCode.Combine(LowPt, Height, Radius);

    /// <summary>Bitwise equality.</summary>
    public static bool operator ==(CylSphere left, CylSphere right) => left.Equals(right);

    /// <summary>Bitwise inequality.</summary>
    public static bool operator !=(CylSphere left, CylSphere right) => !left.Equals(right);
}
