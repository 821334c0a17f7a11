// PhysicsObj — the object as an obstacle: FindObjCollisions, check_collision, ethereal_check_for_collisions.
using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;

namespace AcDream.Core.Physics.Objects;

// The object as an obstacle: how a transition of another object collides with it.
public sealed partial class PhysicsObj
{
    /// <summary>The game object's answers (creature, player, PK...), or null for a plain physics object. Retail:
    /// <c>weenie_obj</c>.</summary>
    /// <exception cref="System.InvalidOperationException">Set on an object removed from its world.</exception>
    public IWeenieObject? Weenie
    {
        get => _weenie;
        set
        {
            ThrowIfRemoved();
            _weenie = value;
        }
    }

    private IWeenieObject? _weenie;

    /// <summary>
    /// Tests this object, as an obstacle, against <paramref name="transition"/> (another object's sweep), with retail's
    /// rules: an ethereal object that ignores collisions is skipped; a viewer passes creatures; an ethereal obstacle (or
    /// an ethereal mover against a non-static one) only blocks placements and is recorded without stopping the mover;
    /// players pass through each other unless impenetrable or both PK / both PK-lite; missiles skip missiles and, aimed at
    /// a target, ethereal objects and other creatures; a mover with IGNORE_CREATURES passes creatures (and missiles).
    /// The geometry tested is the part BSPs (HAS_PHYSICS_BSP), else the cylinder spheres, else the spheres. A hit is
    /// recorded in the transition's collision info (a static obstacle counts as the environment instead).
    /// </summary>
    /// <returns>The state of the first shape that did not answer OK, or OK.</returns>
    // retail: CPhysicsObj::FindObjCollisions (acclient.c:316158)
    internal TransitionState FindObjCollisions(Transition transition)
    {
        ArgumentNullException.ThrowIfNull(transition);
        ObjectInfo oi = transition.ObjectInfo;
        SpherePath path = transition.SpherePath;
        if ((_state & PhysicsState.Ethereal) != 0 && (_state & PhysicsState.IgnoreCollisions) != 0)
        {
            return TransitionState.Ok;
        }

        IWeenieObject? weenie = Weenie;
        if (weenie is not null && (oi.State & ObjectInfoState.IsViewer) != 0 && weenie.IsCreature)
        {
            return TransitionState.Ok;
        }

        bool ethereal;
        if ((_state & PhysicsState.Ethereal) != 0 || (oi.Ethereal && (_state & PhysicsState.Static) == 0))
        {
            ethereal = true;
            if (path.StepDown)
            {
                return TransitionState.Ok;
            }
        }
        else
        {
            ethereal = false;
        }

        path.ObstructionEthereal = ethereal;
        bool playersPass = PlayersPassThrough(weenie, oi.State);
        bool isCreature = (_state & PhysicsState.Missile) != 0 || (weenie is not null && weenie.IsCreature);
        TransitionState result = TransitionState.Ok;
        bool hit = false;
        if ((_state & PhysicsState.HasPhysicsBsp) == 0 || playersPass || oi.MissileIgnore(this))
        {
            IPartCollision? parts = PartArray as IPartCollision;
            int numCyl = parts is null ? 0 : parts.CylSpheres.Length;
            if (numCyl != 0 && !playersPass && !oi.MissileIgnore(this))
            {
                ReadOnlySpan<CylSphere> cyl = parts!.CylSpheres;
                for (int i = 0; i < cyl.Length; i++)
                {
                    result = cyl[i].IntersectsSphere(_position, Scale, transition);
                    if (result != TransitionState.Ok)
                    {
                        hit = true;
                        break;
                    }
                }
            }
            else if (numCyl == 0 && PartArray is not null && PartArray.NumSpheres != 0 && !playersPass && !oi.MissileIgnore(this))
            {
                ReadOnlySpan<Sphere> spheres = PartArray.Spheres;
                for (int i = 0; i < spheres.Length; i++)
                {
                    result = spheres[i].IntersectsSphere(_position, Scale, transition, isCreature);
                    if (result != TransitionState.Ok)
                    {
                        hit = true;
                        break;
                    }
                }
            }
        }
        else if (PartArray is IPartCollision bspParts)
        {
            result = FindPartObjCollisions(bspParts, transition);
            hit = result != TransitionState.Ok;
        }

        if (hit && !path.StepDown)
        {
            CollisionInfo ci = transition.CollisionInfo;
            if ((_state & PhysicsState.Static) != 0)
            {
                if ((oi.State & ObjectInfoState.Contact) == 0)
                {
                    ci.CollidedWithEnvironment = true;
                }
            }
            else if (ethereal || (isCreature && (oi.State & ObjectInfoState.IgnoreCreatures) != 0))
            {
                result = TransitionState.Ok;
                ci.CollisionNormalValid = false;
                ci.AddObject(this, TransitionState.Ok);
            }
            else
            {
                ci.AddObject(this, result);
            }
        }

        path.ObstructionEthereal = false;
        return result;
    }

    /// <summary>
    /// True when this object, as an obstacle where it stands, cannot reach the check spheres boxed by
    /// <paramref name="reach"/>: it has no physics BSP, the built-in part array without cylinder spheres, and its spheres
    /// (all within |scale| · <see cref="SimplePartArray.ObstacleReach"/> of its origin, whatever its orientation) lie
    /// outside the box. <see cref="FindObjCollisions"/> then answers OK without touching anything but the obstruction
    /// flag; the cell's object loop calls <see cref="SkipOutOfReach"/> instead. The loop first passes over, from its cell's
    /// <see cref="ObstacleTable"/>, the obstacles that a packed copy of these inputs (<see cref="ObstacleSummary"/>, with the
    /// reach rounded up) already shows out of reach, without reading them; it asks this of the others, and
    /// <see cref="ObstacleSummary.Verify"/> checks each one passed over against it.
    /// </summary>
    // non-retail: the exact early-out of ObjectReach (retail tests every sphere)
    [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
    internal bool IsOutOfReach(in ObjectReach reach)
    {
        if (!TryGetSphereReach(out float bound))
        {
            return false;
        }

        // GetBlockOffset's own first test, done here so that an obstacle of the same landblock costs no call.
        Vector3 b = (reach.CellId >> 16) == (_position.ObjCellId >> 16) ? Vector3.Zero : LandDefs.GetBlockOffset(reach.CellId, _position.ObjCellId);
        Vector3 o = _position.Frame.Origin;
        return reach.Excludes((double)b.X + o.X, (double)b.Y + o.Y, (double)b.Z + o.Z, Math.Abs((double)Scale) * bound);
    }

    /// <summary>The object's <see cref="SimplePartArray.ObstacleReach"/> (at scale 1) when its shapes are spheres alone: no
    /// physics BSP, the built-in part array, no cylinder spheres; false otherwise (the object is then tested in full).</summary>
    [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
    internal bool TryGetSphereReach(out float bound)
    {
        bound = 0f;
        if ((_state & PhysicsState.HasPhysicsBsp) != 0 || _partArray is not SimplePartArray parts)
        {
            return false;
        }

        bound = parts.ObstacleReach;
        return bound >= 0f;
    }

    /// <summary>
    /// What <see cref="FindObjCollisions"/> does for an obstacle that is <see cref="IsOutOfReach"/>: it answers OK, and
    /// clears the transition's obstruction flag unless one of its early exits (ethereal and ignoring collisions, a creature
    /// seen by a viewer, an ethereal obstruction during a step down) comes first.
    /// </summary>
    // non-retail: the effect of CPhysicsObj::FindObjCollisions (acclient.c:316158) when no shape is reached
    internal void SkipOutOfReach(Transition transition)
    {
        ObjectInfo oi = transition.ObjectInfo;
        SpherePath path = transition.SpherePath;
        if ((_state & PhysicsState.Ethereal) != 0 && (_state & PhysicsState.IgnoreCollisions) != 0)
        {
            return;
        }

        IWeenieObject? weenie = Weenie;
        if (weenie is not null && (oi.State & ObjectInfoState.IsViewer) != 0 && weenie.IsCreature)
        {
            return;
        }

        if (((_state & PhysicsState.Ethereal) != 0 || (oi.Ethereal && (_state & PhysicsState.Static) == 0)) && path.StepDown)
        {
            return;
        }

        path.ObstructionEthereal = false;
    }

    // retail: CPartArray::FindObjCollisions (acclient.c:325463)
    private static TransitionState FindPartObjCollisions(IPartCollision parts, Transition transition)
    {
        TransitionState result = TransitionState.Ok;
        int n = parts.NumCollisionParts;
        for (int i = 0; i < n; i++)
        {
            result = parts.FindPartObjCollisions(i, transition);
            if (result != TransitionState.Ok)
            {
                break;
            }
        }

        return result;
    }

    // retail: CPhysicsObj::FindObjCollisions (acclient.c:316158), the player rule: two players pass through each other
    // unless the mover is impenetrable, this one is, or both are PK, or both PK-lite.
    private static bool PlayersPassThrough(IWeenieObject? weenie, ObjectInfoState mover)
    {
        if (weenie is null || !weenie.IsPlayer || (mover & ObjectInfoState.IsPlayer) == 0)
        {
            return false;
        }

        if ((mover & ObjectInfoState.IsImpenetrable) != 0 || weenie.IsImpenetrable)
        {
            return false;
        }

        if ((mover & ObjectInfoState.IsPK) != 0 && weenie.IsPK)
        {
            return false;
        }

        return !((mover & ObjectInfoState.IsPKLite) != 0 && weenie.IsPKLite);
    }

    /// <summary>
    /// True when <paramref name="mover"/>, standing where it is, overlaps this object (a placement test with the mover's
    /// spheres). A static object never reports; false when no transition is free or the world has no retail sweep.
    /// </summary>
    // retail: CPhysicsObj::check_collision (acclient.c:320127)
    internal bool CheckCollision(PhysicsObj mover)
    {
        ArgumentNullException.ThrowIfNull(mover);
        if ((_state & PhysicsState.Static) != 0 || World.Sweep is not RetailSweep retail)
        {
            return false;
        }

        return CheckCollision(retail, mover);
    }

    /// <summary>
    /// True when <paramref name="mover"/>, where it stands, overlaps this object: a placement test of the mover's shapes
    /// against this object's spheres at rest, in a transition from <paramref name="sweep"/>'s pool. False when no
    /// transition is free.
    /// </summary>
    // retail: CPhysicsObj::check_collision (acclient.c:320127) -> CTransition::check_collisions (acclient.c:312174)
    internal bool CheckCollision(RetailSweep sweep, PhysicsObj mover)
    {
        Transition? t = sweep.Pool.Make();
        if (t is null)
        {
            return false;
        }

        try
        {
            t.InitObject(this, GetObjectInfo(t, false));
            InitSpheres(t);
            Position pos = Position;
            t.InitPath(sweep.Cells.GetVisible(CellId), pos, pos);
            SpherePath path = t.SpherePath;
            path.InsertType = InsertType.Placement;
            path.CheckPos = path.CurrPos;
            path.CheckCell = path.CurrCell;
            path.CellArrayValid = false;
            path.CacheGlobalSphere();
            return mover.FindObjCollisions(t) != TransitionState.Ok;
        }
        finally
        {
            sweep.Pool.Cleanup();
        }
    }

    /// <summary>True when this object, where it stands, overlaps an object shadowed in any cell it overlaps.</summary>
    // retail: CPhysicsObj::ethereal_check_for_collisions (acclient.c:317831)
    internal bool EtherealCheckForCollisions()
    {
        for (int i = 0; i < NumShadowObjects; i++)
        {
            ObjCell? cell = _shadowObjects[i].Cell;
            if (cell is not null && cell.CheckCollisions(this))
            {
                return true;
            }
        }

        return false;
    }
}
