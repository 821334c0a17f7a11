using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision.Primitives;

// Another object's collision sphere against the moving spheres of a transition: overlap tests, landing on it, stepping
// up onto it, stepping down onto it, sliding along it, and the path-clipped missile's time of impact. Retail: CSphere
// (PORTAL/cgeometry/CSphere.c), the object-collision half. Coordinates: this is the obstacle sphere already placed in
// the landblock of the transition's check position (see IntersectsSphere(in Position, float, Transition, bool)).
// Arithmetic follows the decompilation: x87 temporaries in double, values stored to float locals or fields rounded at
// that point.
public partial struct Sphere
{
    // EPSILON as the x87 code loads it (the float 0.0002f widened: the decompilation prints 0.00019999999).
    private const double EpsD = PhysicsGlobals.Epsilon;

    /// <summary>
    /// The fraction of <paramref name="movement"/> at which a sphere starting at <paramref name="disp"/> from this one
    /// first touches it at distance <paramref name="radsum"/>; -1 when it starts inside (or within EPSILON of touching),
    /// does not move, or never touches.
    /// </summary>
    // retail: CSphere::find_time_of_collision (acclient.c:358480)
    public static double FindTimeOfCollision(Vector3 movement, Vector3 disp, float radsum)
    {
        double a = (double)movement.X * movement.X + (double)movement.Y * movement.Y + (double)movement.Z * movement.Z;
        double b = -((double)disp.Z * movement.Z + (double)disp.Y * movement.Y + (double)movement.X * disp.X);
        double c = (double)disp.X * disp.X + (double)disp.Y * disp.Y + (double)disp.Z * disp.Z - (double)radsum * radsum;
        if (c < EpsD)
        {
            return -1.0;
        }

        double disc = b * b - c * a;
        if (a < EpsD || disc < 0.0)
        {
            return -1.0;
        }

        double s = Math.Sqrt(disc);
        if (b - s < 0.0)
        {
            return (s - ((double)disp.Z * movement.Z + (double)disp.Y * movement.Y + (double)movement.X * disp.X)) / a;
        }

        return (b - s) / a;
    }

    /// <summary>True when a sphere centre at <paramref name="disp"/> from this sphere's centre lies within
    /// <paramref name="radsum"/> (touching counts).</summary>
    /// <remarks>The decompilation lost the comparison (x87 flags only); the inline copy of the same test in
    /// <c>CSphere::intersects_sphere</c> reads <c>radsum² &gt;= |disp|²</c>, which this follows (divergences.md, O1).</remarks>
    // retail: CSphere::collides_with_sphere (acclient.c:358508)
    public static bool CollidesWithSphere(Vector3 disp, float radsum) =>
        (double)radsum * radsum >= (double)disp.Y * disp.Y + (double)disp.X * disp.X + (double)disp.Z * disp.Z;

    /// <summary>
    /// This sphere (local to the object at <paramref name="p"/>, scaled by <paramref name="scale"/>) against the
    /// transition's check spheres.
    /// </summary>
    /// <param name="p">The position of the object that owns the sphere.</param>
    /// <param name="scale">That object's scale.</param>
    /// <param name="transition">The transition being tested.</param>
    /// <param name="isCreature">The owner is a creature (or a missile): a step down or landing ignores it.</param>
    // retail: CSphere::intersects_sphere(Position*, float, CTransition*, int) (acclient.c:359389)
    internal readonly TransitionState IntersectsSphere(in Position p, float scale, Transition transition, bool isCreature)
    {
        var local = new Vector3(scale * Center.X, scale * Center.Y, scale * Center.Z);
        var global = new Sphere(transition.SpherePath.CheckPos.LocalToGlobal(p, local), scale * Radius);
        return global.IntersectsSphere(transition, isCreature);
    }

    /// <summary>
    /// This sphere (in the check position's landblock) against the transition's check spheres: during a placement or
    /// past an ethereal obstruction only an overlap test; during a step down a landing on top; during a walkable probe an
    /// overlap test; otherwise a step up (walkers), a point collision (path-clipped missiles) or a landing (fallers);
    /// and once a landing was requested, the contact plane on top of the sphere.
    /// </summary>
    // retail: CSphere::intersects_sphere(CTransition*, int) (acclient.c:359156)
    internal readonly TransitionState IntersectsSphere(Transition transition, bool isCreature)
    {
        SpherePath path = transition.SpherePath;
        Sphere gs0 = path.GlobalSphere[0];
        var disp = new Vector3(gs0.Center.X - Center.X, gs0.Center.Y - Center.Y, gs0.Center.Z - Center.Z);
        float radsum = (float)((double)Radius + gs0.Radius - EpsD);
        if (path.ObstructionEthereal || path.InsertType == InsertType.Placement)
        {
            if ((double)radsum * radsum >= (double)disp.Y * disp.Y + (double)disp.X * disp.X + (double)disp.Z * disp.Z)
            {
                return TransitionState.Collided;
            }

            return path.NumSphere > 1 && CollidesWithSphere(Disp(path.GlobalSphere[1]), radsum)
                ? TransitionState.Collided
                : TransitionState.Ok;
        }

        if (path.StepDown)
        {
            return isCreature ? TransitionState.Ok : StepSphereDown(path, transition.CollisionInfo, disp, radsum);
        }

        if (path.CheckWalkable)
        {
            if (CollidesWithSphere(disp, radsum))
            {
                return TransitionState.Collided;
            }

            return path.NumSphere > 1 && CollidesWithSphere(Disp(path.GlobalSphere[1]), radsum)
                ? TransitionState.Collided
                : TransitionState.Ok;
        }

        if (!path.Collide)
        {
            ObjectInfoState state = transition.ObjectInfo.State;
            if ((state & (ObjectInfoState.Contact | ObjectInfoState.OnWalkable)) != 0)
            {
                if (CollidesWithSphere(disp, radsum))
                {
                    return StepSphereUp(transition, disp, radsum);
                }

                if (path.NumSphere > 1)
                {
                    Vector3 disp2 = Disp(path.GlobalSphere[1]);
                    if (CollidesWithSphere(disp2, radsum))
                    {
                        return SlideSphereAway(path, transition.CollisionInfo, 1);
                    }
                }
            }
            else if ((state & ObjectInfoState.PathClipped) != 0)
            {
                if (CollidesWithSphere(disp, radsum))
                {
                    return CollideWithPoint(transition.ObjectInfo, path, transition.CollisionInfo, gs0, radsum, 0);
                }
            }
            else
            {
                if (CollidesWithSphere(disp, radsum))
                {
                    return LandOnSphere(path);
                }

                if (path.NumSphere > 1)
                {
                    Sphere gs1 = path.GlobalSphere[1];
                    if (CollidesWithSphere(Disp(gs1), radsum))
                    {
                        return CollideWithPoint(transition.ObjectInfo, path, transition.CollisionInfo, gs1, radsum, 1);
                    }
                }
            }

            return TransitionState.Ok;
        }

        if (isCreature)
        {
            return TransitionState.Ok;
        }

        if (!CollidesWithSphere(disp, radsum) && !(path.NumSphere > 1 && CollidesWithSphere(Disp(path.GlobalSphere[1]), radsum)))
        {
            return TransitionState.Ok;
        }

        return LandOnTop(path, transition.CollisionInfo, gs0, disp, radsum);
    }

    private readonly Vector3 Disp(in Sphere s) => new(s.Center.X - Center.X, s.Center.Y - Center.Y, s.Center.Z - Center.Z);

    // retail: CSphere::intersects_sphere (acclient.c:359156), the path.collide branch: after land_on_sphere asked for it,
    // move the check sphere back along the step to where it rests on this sphere and record that contact plane.
    private readonly TransitionState LandOnTop(SpherePath path, CollisionInfo collisions, in Sphere gs0, Vector3 disp, float radsum)
    {
        Vector3 block = path.GetCurrPosCheckPosBlockOffset();
        Vector3 gcc = path.GlobalCurrCenter[0];
        var back = new Vector3(gcc.X - gs0.Center.X, gcc.Y - gs0.Center.Y, gcc.Z - gs0.Center.Z);
        var movement = new Vector3(back.X - block.X, back.Y - block.Y, back.Z - block.Z);
        float r = (float)(radsum + EpsD);
        double a = (double)movement.Z * movement.Z + (double)movement.Y * movement.Y + (double)movement.X * movement.X;
        double b = -((double)movement.Y * disp.Y + (double)movement.X * disp.X + (double)movement.Z * disp.Z);
        if (Math.Abs(a) < EpsD)
        {
            return TransitionState.Collided;
        }

        double d2 = (double)disp.Y * disp.Y + (double)disp.X * disp.X + (double)disp.Z * disp.Z - (double)r * r;
        double num = Math.Sqrt(b * b - d2 * a)
                     - ((double)movement.Y * disp.Y + (double)movement.X * disp.X + (double)movement.Z * disp.Z);
        if (num > 1.0)
        {
            // Retail compares the numerator (not the time) with 1 and then takes the other root.
            num = b + b - num;
        }

        double t = num / a;
        double interp = (1.0 - t) * path.WalkInterp;
        if (!(interp < path.WalkInterp && interp >= -0.1))
        {
            return TransitionState.Collided;
        }

        movement = new Vector3((float)(movement.X * t), (float)(movement.Y * t), (float)(movement.Z * t));
        var n = new Vector3(movement.X + disp.X, movement.Y + disp.Y, movement.Z + disp.Z);
        n = DivideByFloat(n, r);
        if (!path.IsWalkableAllowable(n.Z))
        {
            return TransitionState.Ok;
        }

        var point = new Vector3(gs0.Center.X - gs0.Radius * n.X, gs0.Center.Y - gs0.Radius * n.Y, gs0.Center.Z - gs0.Radius * n.Z);
        collisions.SetContactPlane(PlaneThrough(n, point), true);
        collisions.ContactPlaneCellId = path.CheckPos.ObjCellId;
        path.WalkInterp = (float)interp;
        path.AddOffsetToCheckPos(movement);
        return TransitionState.Adjusted;
    }

    // retail: Vector3::operator/= (acclient.c:146865 family): the double reciprocal for x, its float rounding for y and z.
    internal static Vector3 DivideByFloat(Vector3 v, float d)
    {
        double inv = 1.0 / d;
        float invf = (float)inv;
        return new Vector3((float)(v.X * inv), v.Y * invf, v.Z * invf);
    }

    /// <summary>The plane with normal <paramref name="n"/> through <paramref name="point"/>.</summary>
    // retail: Plane::Plane(Vector3*, Vector3*) (acclient.c:358518)
    internal static CollisionPlane PlaneThrough(Vector3 n, Vector3 point) =>
        new(n, (float)-((double)point.Z * n.Z + (double)point.Y * n.Y + (double)point.X * n.X));

    /// <summary>During a step down: lifts the check sphere onto the top of this one (limited by what is left of the step
    /// down) and records the contact plane there, when that surface is walkable enough.</summary>
    // retail: CSphere::step_sphere_down (acclient.c:358615)
    private readonly TransitionState StepSphereDown(SpherePath path, CollisionInfo collisions, Vector3 disp, float radsum)
    {
        float ty = disp.Y * disp.Y;
        float tx = disp.X * disp.X;
        if ((double)radsum * radsum < (double)disp.Z * disp.Z + tx + ty)
        {
            if (path.NumSphere <= 1 || !CollidesWithSphere(Disp(path.GlobalSphere[1]), radsum))
            {
                return TransitionState.Ok;
            }
        }

        float amt = (float)((double)path.StepDownAmt * path.WalkInterp);
        if (Math.Abs(amt) < EpsD)
        {
            return TransitionState.Collided;
        }

        float r = (float)(radsum + EpsD);
        double t = (Math.Sqrt((double)r * r - ((double)tx + ty)) - disp.Z) / amt;
        double interp = (1.0 - t) * path.WalkInterp;
        if (interp >= path.WalkInterp || interp < -0.1)
        {
            return TransitionState.Collided;
        }

        float lift = (float)(amt * t);
        double inv = 1.0 / r;
        double nz = ((double)lift + disp.Z) * inv;
        var n = new Vector3((float)(inv * disp.X), (float)(inv * disp.Y), (float)nz);
        if (nz <= path.WalkableAllowance)
        {
            return TransitionState.Ok;
        }

        var point = new Vector3(Center.X + Radius * n.X, Center.Y + Radius * n.Y, Center.Z + Radius * n.Z);
        collisions.SetContactPlane(PlaneThrough(n, point), true);
        collisions.ContactPlaneCellId = path.CheckPos.ObjCellId;
        path.WalkInterp = (float)interp;
        path.AddOffsetToCheckPos(new Vector3(0f, 0f, lift));
        return TransitionState.Adjusted;
    }

    /// <summary>A walker runs into this sphere: climbs onto it when its top is within the step-up height, otherwise
    /// slides along it.</summary>
    // retail: CSphere::step_sphere_up (acclient.c:359071)
    private readonly TransitionState StepSphereUp(Transition transition, Vector3 disp, float radsum)
    {
        double r = radsum + EpsD;
        if (transition.ObjectInfo.StepUpHeight < r - disp.Z)
        {
            return SlideSphereBy(transition.SpherePath, transition.CollisionInfo, disp, 0);
        }

        Vector3 gcc = transition.SpherePath.GlobalCurrCenter[0];
        var normal = new Vector3(gcc.X - Center.X, gcc.Y - Center.Y, gcc.Z - Center.Z);
        if (transition.StepUp(normal))
        {
            return TransitionState.Ok;
        }

        return transition.SpherePath.StepUpSlide(transition.CollisionInfo);
    }

    /// <summary>A falling sphere touches this one: asks the transition to come back with the landing test
    /// (<see cref="SpherePath.SetCollide"/>) at the landing threshold.</summary>
    // retail: CSphere::land_on_sphere (acclient.c:359114)
    private readonly TransitionState LandOnSphere(SpherePath path)
    {
        Vector3 gcc = path.GlobalCurrCenter[0];
        var n = new Vector3(gcc.X - Center.X, gcc.Y - Center.Y, gcc.Z - Center.Z);
        if (VectorMath.NormalizeCheckSmall(ref n))
        {
            return TransitionState.Collided;
        }

        path.SetCollide(n);
        path.WalkableAllowance = PhysicsGlobals.LandingZ;
        return TransitionState.Adjusted;
    }

    /// <summary>Slides check sphere <paramref name="sphereNum"/> along this sphere's surface (the general sphere slide
    /// with the normal from this centre to the sphere's current centre).</summary>
    // retail: CSphere::slide_sphere(OBJECTINFO*, SPHEREPATH*, COLLISIONINFO*, CSphere*, Vector3*, float*, int) (acclient.c:359138)
    private readonly TransitionState SlideSphereAway(SpherePath path, CollisionInfo collisions, int sphereNum)
    {
        Vector3 curr = path.GlobalCurrCenter[sphereNum];
        var n = new Vector3(curr.X - Center.X, curr.Y - Center.Y, curr.Z - Center.Z);
        if (VectorMath.NormalizeCheckSmall(ref n))
        {
            return TransitionState.Collided;
        }

        return path.GlobalSphere[sphereNum].SlideSphere(path, collisions, ref n, curr);
    }

    /// <summary>
    /// Slides check sphere <paramref name="sphereNum"/> along this sphere: keeps the part of the step along the crease
    /// between this sphere and the contact plane, or, without a crease, the part of the step tangent to this sphere.
    /// </summary>
    // retail: CSphere::slide_sphere(OBJECTINFO*, SPHEREPATH*, COLLISIONINFO*, Vector3*, float, int) (acclient.c:358708)
    private readonly TransitionState SlideSphereBy(SpherePath path, CollisionInfo collisions, Vector3 disp, int sphereNum)
    {
        Sphere gs = path.GlobalSphere[sphereNum];
        Vector3 gcc = path.GlobalCurrCenter[sphereNum];
        var cn = new Vector3(gcc.X - Center.X, gcc.Y - Center.Y, gcc.Z - Center.Z);
        if (VectorMath.NormalizeCheckSmall(ref cn))
        {
            return TransitionState.Collided;
        }

        collisions.SetCollisionNormal(cn);
        Vector3 pn = collisions.ContactPlaneValid ? collisions.ContactPlane.N : collisions.LastKnownContactPlane.N;
        var dir = new Vector3(
            (float)((double)pn.Z * cn.Y - (double)pn.Y * cn.Z),
            (float)((double)cn.Z * pn.X - (double)pn.Z * cn.X),
            (float)((double)pn.Y * cn.X - (double)cn.Y * pn.X));
        Vector3 block = LandDefs.GetBlockOffset(path.CurrPos.ObjCellId, path.CheckPos.ObjCellId);
        double ddx = (double)gs.Center.X - gcc.X;
        double ddy = (double)gs.Center.Y - gcc.Y;
        float ddz = gs.Center.Z - gcc.Z;
        var m = new Vector3((float)(block.X + ddx), (float)(block.Y + ddy), block.Z + ddz);
        double l2 = (double)dir.Z * dir.Z + (double)dir.Y * dir.Y + (double)dir.X * dir.X;
        Vector3 offset;
        if (l2 >= EpsD)
        {
            double along = (double)m.Z * dir.Z + (double)m.Y * dir.Y + (double)m.X * dir.X;
            double inv = 1.0 / l2;
            var skid = new Vector3((float)((float)(dir.X * along) * inv), (float)((float)(dir.Y * along) * inv),
                (float)((float)(dir.Z * along) * inv));
            // The decompilation lost this compare (x87 flags); read as the other slide's |skid|² < EPSILON test (O2).
            if ((double)skid.X * skid.X + (double)skid.Y * skid.Y + (double)skid.Z * skid.Z < EpsD)
            {
                return TransitionState.Collided;
            }

            offset = new Vector3(skid.X - m.X, skid.Y - m.Y, skid.Z - m.Z);
        }
        else
        {
            if ((double)pn.Z * disp.Z + (double)pn.Y * disp.Y + (double)pn.X * disp.X < 0.0)
            {
                return TransitionState.Collided;
            }

            float into = (float)((double)m.Z * cn.Z + (double)m.Y * cn.Y + (double)m.X * cn.X);
            offset = new Vector3(-cn.X * into, -cn.Y * into, -cn.Z * into);
        }

        path.AddOffsetToCheckPos(offset);
        return TransitionState.Slid;
    }

    /// <summary>
    /// A path-clipped missile's sphere hits this one. With PERFECT_CLIP the check sphere moves back along the step to
    /// the time of impact and the collision normal is taken there (Adjusted); otherwise only the normal from this
    /// centre to the current centre is recorded (Collided: the sweep stops at the last valid step).
    /// </summary>
    // retail: CSphere::collide_with_point (acclient.c:358807)
    private readonly TransitionState CollideWithPoint(ObjectInfo obj, SpherePath path, CollisionInfo collisions, in Sphere checkPos,
        float radsum, int sphereNum)
    {
        Vector3 gcc = path.GlobalCurrCenter[sphereNum];
        if ((obj.State & ObjectInfoState.PerfectClip) == 0)
        {
            var n = new Vector3(gcc.X - Center.X, gcc.Y - Center.Y, gcc.Z - Center.Z);
            if (!VectorMath.NormalizeCheckSmall(ref n))
            {
                collisions.SetCollisionNormal(n);
            }

            return TransitionState.Collided;
        }

        float r = (float)(radsum + EpsD);
        var oldDisp = new Vector3(gcc.X - Center.X, gcc.Y - Center.Y, gcc.Z - Center.Z);
        Vector3 block = LandDefs.GetBlockOffset(path.CurrPos.ObjCellId, path.CheckPos.ObjCellId);
        double mx = (double)checkPos.Center.X - gcc.X;
        double my = (double)checkPos.Center.Y - gcc.Y;
        float mz = checkPos.Center.Z - gcc.Z;
        var movement = new Vector3((float)(block.X + mx), (float)(block.Y + my), block.Z + mz);
        double t = FindTimeOfCollision(movement, oldDisp, r);
        if (t < EpsD || t > 1.0)
        {
            return TransitionState.Collided;
        }

        float oy = (float)(movement.Y * t);
        float oz = (float)(movement.Z * t);
        double bx = movement.X * t - movement.X;
        double bz = (double)oz - movement.Z;
        double by = (double)oy - movement.Y;
        var offset = new Vector3((float)bx, (float)by, (float)bz);
        float hx = (float)(bx + checkPos.Center.X);
        hx -= Center.X;
        float hy = (float)(by + checkPos.Center.Y - Center.Y);
        double hz = (double)offset.Z + checkPos.Center.Z - Center.Z;
        double inv = 1.0 / r;
        collisions.SetCollisionNormal(new Vector3((float)(hx * inv), (float)(hy * inv), (float)(hz * inv)));
        path.AddOffsetToCheckPos(offset);
        return TransitionState.Adjusted;
    }
}
