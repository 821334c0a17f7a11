// PhysicsObj — the object's retail sweep and placement: transition, SetPosition's placement, AdjustPosition, CheckPositionInternal.
using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects.Parts;

namespace AcDream.Core.Physics.Objects;

// The object's retail sweep and placement: the pooled transition that moves it, and the placement that sets it down.
public sealed partial class PhysicsObj
{
    /// <summary>
    /// Sweeps the object from <paramref name="oldPos"/> to <paramref name="newPos"/> in a transition from
    /// <paramref name="sweep"/>'s pool. Returns the transition (already given back to the pool, readable until the pool's next
    /// <see cref="TransitionPool.Make"/>) or null when the sweep failed or all ten transitions were in use.
    /// </summary>
    /// <exception cref="ArgumentException">A position is outside the position domain (origin not finite, beyond ±65,536 m, or
    /// outdoor x, y outside [−192, 384]; rotation not a unit quaternion); nothing is changed. The engine's own steps always
    /// sweep inside it (a step moves an object at most 30 m from a re-homed origin, with a renormalised rotation); or the sweep
    /// is longer than <see cref="InputLimits.MaxSweepDistance"/> (192 m). A position whose cell id is no world cell (0,
    /// 0xFFFFFFFF, a landblock outside the world) makes the sweep fail (null).</exception>
    // retail: CPhysicsObj::transition (acclient.c:320060)
    internal Transition? RunTransition(RetailSweep sweep, in Position oldPos, in Position newPos, bool adminMove)
    {
        Transition? t = SweepHoldingTransition(sweep, oldPos, newPos, adminMove);
        if (t is not null)
        {
            sweep.Pool.Cleanup();
        }

        return t;
    }

    /// <summary>
    /// <see cref="RunTransition"/> that keeps the pool slot of a successful sweep: the caller commits the transition and then
    /// gives it back (<see cref="TransitionPool.Cleanup"/>). A failed sweep gives its slot back here (null).
    /// </summary>
    /// <exception cref="ArgumentException">As <see cref="RunTransition"/>.</exception>
    // retail: CPhysicsObj::transition (acclient.c:320060), without its cleanupTransition on success
    internal Transition? SweepHoldingTransition(RetailSweep sweep, in Position oldPos, in Position newPos, bool adminMove)
    {
        // non-retail: the position domain (a sweep towards 1e30 m took seconds and ended in an unloaded block's cell; an
        // invalid rotation never ended)
        if (!InputLimits.IsPositionInDomain(oldPos) || !InputLimits.IsPositionInDomain(newPos))
        {
            throw new ArgumentException("Sweep positions must lie in the position domain (InputLimits).", nameof(newPos));
        }

        // non-retail: a sweep between cells that are no world cells fails at once, and one longer than MaxSweepDistance is
        // refused (a sweep to the landblock 0xFF, outside the world, ran tens of thousands of steps); the engine's own steps
        // move at most 30 m inside the world
        if (!LandDefs.InboundValidCellId(oldPos.ObjCellId) || !LandDefs.InboundValidCellId(newPos.ObjCellId))
        {
            return null;
        }

        Vector3 d = oldPos.GetOffset(newPos);
        if ((double)d.X * d.X + (double)d.Y * d.Y + (double)d.Z * d.Z
            > (double)InputLimits.MaxSweepDistance * InputLimits.MaxSweepDistance)
        {
            throw new ArgumentException("A sweep must not be longer than 192 m.", nameof(newPos));
        }

        Transition? t = sweep.Pool.Make();
        if (t is null)
        {
            return null;
        }

        bool ok = false;
        try
        {
            ObjectInfoState state = GetObjectInfo(t, adminMove);
            t.InitObject(this, state);
            InitSpheres(t);
            t.InitPath(sweep.Cells.GetVisible(CellId), oldPos, newPos);
            TransientState ts = TransientState;
            if ((ts & TransientState.StationaryStuck) != 0)
            {
                t.CollisionInfo.FramesStationaryFall = Transition.StationaryFallFrames;
            }
            else if ((ts & TransientState.StationaryStop) != 0)
            {
                t.CollisionInfo.FramesStationaryFall = 2;
            }
            else if ((ts & TransientState.StationaryFall) != 0)
            {
                t.CollisionInfo.FramesStationaryFall = 1;
            }

            ok = t.FindValidPosition();
        }
        finally
        {
            if (!ok)
            {
                sweep.Pool.Cleanup();
            }
        }

        return ok ? t : null;
    }

    /// <summary>
    /// Places the object at <paramref name="pos"/> with a transition from <paramref name="sweep"/>'s pool: adjusts the
    /// position to its cell, places the spheres there and commits the outcome (or sends the object to the lost cell).
    /// </summary>
    /// <remarks>Scatter placement (SCATTER / RANDOMSCATTER) and the weenie's forced cells are not ported.</remarks>
    // retail: CPhysicsObj::SetPosition (acclient.c:323289) -> SetPositionInternal(sps) (acclient.c:323166)
    //         -> SetPositionInternal(p, sps, transit) (acclient.c:323034)
    internal SetPositionError SetPositionInternal(RetailSweep sweep, in Position pos, SetPositionFlags flags)
    {
        Transition? t = sweep.Pool.Make();
        if (t is null)
        {
            return SetPositionError.GeneralFailure;
        }

        try
        {
            // retail: SetPositionInternal (acclient.c:323034) calls prepare_to_enter_world for an object in no cell; its
            // lost-cell line
            if (_cell is null)
            {
                World.RemoveFromLostCell(this);
            }

            t.InitObject(this, ObjectInfoState.None);
            InitSpheres(t);
            Position p = pos;
            ObjCell? cell = AdjustPosition(sweep, ref p, t.SpherePath.LocalSphere[0].Center);
            if (cell is null)
            {
                GoToLostCellInternal(p);
                return SetPositionError.Ok;
            }

            if ((flags & SetPositionFlags.DoNotCreateCells) != 0)
            {
                t.CellArray.DoNotLoadCells = true;
            }

            if (!CheckPositionInternal(cell, ref p, t, flags))
            {
                return HandleAllCollisions(sweep, t.CollisionInfo, false, false) ? SetPositionError.Collided : SetPositionError.NoValidPosition;
            }

            if (t.SpherePath.CurrCell is null)
            {
                return SetPositionError.NoCell;
            }

            CommitTransitionInternal(sweep, t);
            return SetPositionError.Ok;
        }
        finally
        {
            sweep.Pool.Cleanup();
        }
    }

    // retail: the sphere choice shared by transition (acclient.c:320060), check_collision and SetPosition
    private void InitSpheres(Transition t)
    {
        IPartArray? parts = PartArray;
        if (parts is not null && parts.NumSpheres != 0)
        {
            t.InitSphere(parts.Spheres, Scale);
        }
        else
        {
            Span<Sphere> dummy = stackalloc Sphere[1];
            dummy[0] = Sphere.Dummy;
            t.InitSphere(dummy, 1.0f);
        }
    }

    /// <summary>True when a placement of the object at <paramref name="pos"/> through <paramref name="sweep"/> finds a loaded cell
    /// (the cell <see cref="SetPositionInternal"/> would start from); false when it would send the object to the lost cell.</summary>
    // non-retail: EnterWorld's check before it changes anything (retail's enter_world stores the position and goes to the lost cell)
    internal bool FindsPlacementCell(RetailSweep sweep, in Position pos)
    {
        IPartArray? parts = PartArray;
        Vector3 spherePoint = Sphere.Dummy.Center;
        if (parts is not null && parts.NumSpheres != 0)
        {
            // SPHEREPATH::init_sphere's scaled first centre, as SetPositionInternal hands it to AdjustPosition.
            Vector3 c = parts.Spheres[0].Center;
            float s = Scale;
            spherePoint = new Vector3(s * c.X, s * c.Y, s * c.Z);
        }

        Position p = pos;
        return AdjustPosition(sweep, ref p, spherePoint) is not null;
    }

    // retail: CPhysicsObj::AdjustPosition (acclient.c:319116); indoor branch without the outdoor fallback
    private static ObjCell? AdjustPosition(RetailSweep sweep, ref Position p, Vector3 spherePoint)
    {
        uint low = p.ObjCellId & 0xFFFF;
        if (!((low >= 1 && low <= 0x40) || (low >= 0x100 && low <= 0xFFFD) || low == 0xFFFF))
        {
            return null;
        }

        if (low >= LandDefs.FirstEnvCell)
        {
            // Indoor: the cell itself or a neighbour that contains the first sphere's centre. Retail (bSearchCells = 1)
            // searches the cell's stab list of visible cells; we search its portal neighbours, and retail's fallback to
            // the outdoors for cells seen from outside is not ported (docs/divergences.md, "Indoor SetPosition").
            if (sweep.Cells.GetVisible(p.ObjCellId) is not EnvCell env)
            {
                return null;
            }

            EnvCell? child = env.FindVisibleChildCell(sweep.Cells, p.LocalToGlobal(p, spherePoint));
            if (child is not null)
            {
                p.ObjCellId = child.CellId;
            }

            return child;
        }

        LandDefs.AdjustToOutside(ref p.ObjCellId, ref p.Frame.Origin);
        return p.ObjCellId != 0 ? sweep.Cells.GetVisible(p.ObjCellId) : null;
    }

    /// <summary>
    /// Places the transition's spheres at <paramref name="p"/>: without SLIDE the placement must end within 5 cm (in x and y,
    /// signed as retail compares) of the request and in the same cell, and then takes the placed origin.
    /// </summary>
    // retail: CPhysicsObj::CheckPositionInternal (acclient.c:319172)
    private static bool CheckPositionInternal(ObjCell cell, ref Position p, Transition t, SetPositionFlags flags)
    {
        t.InitPlacementPath(cell, p);
        bool slide = (flags & SetPositionFlags.Slide) != 0;
        if (!slide)
        {
            t.SpherePath.PlacementAllowsSliding = false;
        }

        if (!t.FindValidPosition())
        {
            return false;
        }

        if (slide)
        {
            return true;
        }

        Position curr = t.SpherePath.CurrPos;
        if (curr.Frame.Origin.X - p.Frame.Origin.X < RetailSweep.PlacementTolerance
            && curr.Frame.Origin.Y - p.Frame.Origin.Y < RetailSweep.PlacementTolerance
            && curr.ObjCellId == cell.Id)
        {
            p.Frame.Origin = curr.Frame.Origin;
            return true;
        }

        return false;
    }
}
