using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Collision;

/// <summary>
/// The moving object as the sweep sees it: its state bits, scale and step heights. Retail: <c>OBJECTINFO</c>
/// (acclient.h:52284, PORTAL/cphysics/CObjectInfo.c).
/// </summary>
internal sealed partial class ObjectInfo
{
    /// <summary>The object being moved (null for a bare sweep). Retail: <c>object</c>.</summary>
    public PhysicsObj? Object;

    /// <summary>The sweep's view of the object. Retail: <c>state</c>.</summary>
    public ObjectInfoState State;

    /// <summary>The object's scale. Retail: <c>scale</c>.</summary>
    public float Scale;

    /// <summary>Highest ledge the object steps up, in metres. Retail: <c>step_up_height</c>.</summary>
    public float StepUpHeight;

    /// <summary>Deepest drop the object follows down while walking, in metres. Retail: <c>step_down_height</c>.</summary>
    public float StepDownHeight;

    /// <summary>The object is ethereal. Retail: <c>ethereal</c>.</summary>
    public bool Ethereal;

    /// <summary>The object follows the ground down (not a missile). Retail: <c>step_down</c>.</summary>
    public bool StepDown;

    /// <summary>The object a missile is aimed at. Retail: <c>targetID</c>.</summary>
    public uint TargetId;

    /// <summary>Clears the object and state. Part of retail's <c>CTransition::init</c> (acclient.c:311595).</summary>
    public void Clear()
    {
        Object = null;
        State = ObjectInfoState.None;
        TargetId = 0;
    }

    /// <summary>Loads the object's scale, step heights and flags.</summary>
    // retail: OBJECTINFO::init (acclient.c:314117) — CTransition::init_object is COMDAT-folded into it
    public void Init(PhysicsObj obj, ObjectInfoState state)
    {
        Object = obj;
        State = state;
        Scale = obj.Scale;
        StepUpHeight = obj.StepUpHeight;
        StepDownHeight = obj.StepDownHeight;
        Ethereal = (obj.State & PhysicsState.Ethereal) != 0;
        StepDown = (obj.State & PhysicsState.Missile) == 0;
        AddWeenieState(obj.Weenie);
    }

    /// <summary>True when <paramref name="normal"/> is steep enough to stand on (N.z &gt;= floor_z).</summary>
    // retail: OBJECTINFO::is_valid_walkable (acclient.c:314099) -> CPhysicsObj::is_valid_walkable (acclient.c:316499)
    public static bool IsValidWalkable(Vector3 normal) => normal.Z >= (double)PhysicsGlobals.FloorZ;

    /// <summary>The walkable threshold, <see cref="PhysicsGlobals.FloorZ"/>.</summary>
    // retail: OBJECTINFO::get_walkable_z (acclient.c:314108) -> CPhysicsObj::get_walkable_z (acclient.c:316506)
    public static float GetWalkableZ() => PhysicsGlobals.FloorZ;

    /// <summary>Stops the object.</summary>
    // retail: OBJECTINFO::kill_velocity (acclient.c:314147)
    public void KillVelocity() => Object?.SetVelocity(Vector3.Zero);

    /// <summary>
    /// Tests the sphere <paramref name="checkPos"/> (local to <paramref name="landCellId"/>'s landblock) against a terrain
    /// (or other walkable) plane: pushes it up out of the surface, records the contact plane when the surface may be stood
    /// on, and refuses the position during a walkable probe or an over-long step down.
    /// </summary>
    /// <param name="checkPos">The first check sphere, in the plane's landblock.</param>
    /// <param name="contactPlane">The surface plane.</param>
    /// <param name="isWater">The cell is (partly) water.</param>
    /// <param name="waterDepth">How deep the sphere sinks below the surface, in metres.</param>
    /// <param name="path">The sphere path (check position moved on <see cref="TransitionState.Adjusted"/>).</param>
    /// <param name="collisions">Receives the contact plane and environment collision.</param>
    /// <param name="landCellId">The cell the plane belongs to.</param>
    // retail: OBJECTINFO::validate_walkable (acclient.c:314160)
    public TransitionState ValidateWalkable(in Sphere checkPos, in CollisionPlane contactPlane, bool isWater, float waterDepth,
        SpherePath path, CollisionInfo collisions, uint landCellId)
    {
        Vector3 n = contactPlane.N;
        Vector3 c = checkPos.Center;
        if ((State & ObjectInfoState.IsViewer) != 0)
        {
            double distD = (double)n.X * c.X + (double)n.Y * c.Y + (double)c.Z * n.Z + contactPlane.D - checkPos.Radius;
            float dist = (float)distD;
            if (distD > -(double)PhysicsGlobals.Epsilon)
            {
                return TransitionState.Ok;
            }

            Vector3 curr = path.GlobalCurrCenter[0];
            float ox = c.X - curr.X;
            float oy = c.Y - curr.Y;
            double oz = (double)c.Z - curr.Z;
            double t = dist / (oz * n.Z + (double)ox * n.X + (double)oy * n.Y);
            if ((t <= 0.0 || t > 1.0) && path.HasBeginPos && (path.BeginPos.ObjCellId & 0xFFFF) >= LandDefs.FirstEnvCell)
            {
                return TransitionState.Ok;
            }

            double back = -t;
            var offset = new Vector3((float)(ox * back), (float)(oy * back), (float)(oz * back));
            path.AddOffsetToCheckPos(offset);
            collisions.SetCollisionNormal(n);
            collisions.CollidedWithEnvironment = true;
            return TransitionState.Adjusted;
        }

        TransitionState ts = TransitionState.Ok;
        double depth = (double)c.Y * n.Y + ((double)c.Z - checkPos.Radius) * n.Z + (double)c.X * n.X + contactPlane.D + waterDepth;
        bool onContact = (State & ObjectInfoState.Contact) != 0;
        bool walking = (State & ObjectInfoState.OnWalkable) != 0;
        if (depth >= -(double)PhysicsGlobals.Epsilon)
        {
            if (depth > PhysicsGlobals.Epsilon)
            {
                return TransitionState.Ok;
            }

            if (path.StepDown || !walking || IsValidWalkable(n))
            {
                collisions.SetContactPlane(contactPlane, isWater);
                collisions.ContactPlaneCellId = landCellId;
            }

            if (!onContact && !path.StepDown)
            {
                collisions.SetCollisionNormal(n);
                collisions.CollidedWithEnvironment = true;
            }

            return TransitionState.Ok;
        }

        if (path.CheckWalkable)
        {
            return TransitionState.Collided;
        }

        float dz = (float)(depth / n.Z);
        if (path.StepDown || !walking || IsValidWalkable(n))
        {
            collisions.SetContactPlane(contactPlane, isWater);
            collisions.ContactPlaneCellId = landCellId;
            if (path.StepDown)
            {
                double interp = (1.0 - -1.0 / ((double)path.StepDownAmt * path.WalkInterp) * dz) * path.WalkInterp;
                if (interp >= path.WalkInterp || interp < -0.1)
                {
                    return TransitionState.Collided;
                }

                path.WalkInterp = (float)interp;
            }

            path.AddOffsetToCheckPos(new Vector3(0f, 0f, -dz));
            ts = TransitionState.Adjusted;
        }

        if (!onContact && !path.StepDown)
        {
            collisions.SetCollisionNormal(n);
            collisions.CollidedWithEnvironment = true;
        }

        return ts;
    }
}
