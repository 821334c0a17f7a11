// PhysicsObj — placement and commit: set_frame, store_position, SetPosition, enter_world, SetPositionInternal(CTransition*).
using System;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Objects;

public sealed partial class PhysicsObj
{
    /// <summary>
    /// Stores <paramref name="frame"/> as the object's frame without any collision test, places the parts and moves the
    /// attached children.
    /// </summary>
    /// <param name="frame">The new frame, local to the object's landblock: a unit quaternion (|q|² within 5 × EPSILON of 1; not
    /// <c>default(Frame)</c>) and an origin within the position domain of the object's cell
    /// (<see cref="InputLimits.MaxCoordinate"/>; outdoor: x, y in [−192, 384], see <see cref="InputLimits.OutdoorMargin"/>).</param>
    /// <exception cref="ArgumentException">The frame is outside that domain (state unchanged; retail would store it, and would
    /// zero a NaN quaternion whose origin is valid: that repair is kept for the engine's own steps).</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::set_frame (acclient.c:321327)
    public void SetFrame(in Frame frame)
    {
        ThrowIfRemoved();
        // non-retail: the frame's domain is checked before anything changes (retail stores any frame)
        InputLimits.ThrowIfOutside(_position.ObjCellId, frame, nameof(frame));
        Touch();
        CutPose();
        SetFrameInternal(frame);
    }

    /// <summary>The engine's <c>set_frame</c> (no domain check): a frame whose origin is finite but whose quaternion has a NaN
    /// gets an all-zero quaternion, as retail.</summary>
    // retail: CPhysicsObj::set_frame (acclient.c:321327)
    internal void SetFrameInternal(in Frame frame)
    {
        Touch();
        Frame f = frame;
        if (!f.IsValid() && f.IsValidExceptForHeading())
        {
            f.SetQuaternionRaw(0f, 0f, 0f, 0f);
        }

        _position.Frame = f;
        SyncObstacleSummary();
        if ((_state & PhysicsState.ParticleEmitter) == 0)
        {
            PartArray?.SetFrame(_position.Frame);
        }

        UpdateChildrenInternal();
    }

    /// <summary>Stores a frame with no validity repair (retail <c>set_initial_frame</c>).</summary>
    /// <param name="frame">The frame: the domain of <see cref="SetFrame"/> (unit quaternion, origin in the cell's domain).</param>
    /// <exception cref="ArgumentException">The frame is outside that domain (state unchanged; retail would store it).</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::set_initial_frame (acclient.c:321355)
    public void SetInitialFrame(in Frame frame)
    {
        ThrowIfRemoved();
        // non-retail: the frame's domain is checked before anything changes
        InputLimits.ThrowIfOutside(_position.ObjCellId, frame, nameof(frame));
        Touch();
        CutPose();
        _position.Frame = frame;
        SyncObstacleSummary();
        if ((_state & PhysicsState.ParticleEmitter) == 0)
        {
            PartArray?.SetFrame(_position.Frame);
        }

        UpdateChildrenInternal();
    }

    /// <summary>Turns the object to face <paramref name="degrees"/> (clockwise from north), keeping its origin.</summary>
    /// <param name="degrees">Compass heading, degrees (the type of <see cref="Position.Heading"/>): any value whose float
    /// rounding is finite (wrapped; rounded to float first, as retail's <c>set_heading(float)</c>).</param>
    /// <exception cref="ArgumentException">The heading is NaN or infinite (also when its float rounding is).</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::set_heading (acclient.c:321376)
    public void SetHeading(double degrees)
    {
        ThrowIfRemoved();
        if (!float.IsFinite((float)degrees))
        {
            throw new ArgumentException("Heading must be finite.", nameof(degrees));
        }

        Touch();
        CutPose();
        Frame f = _position.Frame;
        f.SetHeading(degrees);
        SetFrameInternal(f);
    }

    /// <summary>Writes a position without a cell change or collision test (outdoor ids are re-homed to the cell under the
    /// origin first).</summary>
    /// <param name="p">The position: a unit quaternion and an origin in the position domain of its cell id
    /// (<see cref="InputLimits"/>: every component within ±65,536 m; outdoor: x, y in [−192, 384]).</param>
    /// <exception cref="ArgumentException">The position is outside that domain (state unchanged).</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::store_position (acclient.c:321388)
    public void StorePosition(in Position p)
    {
        ThrowIfRemoved();
        // non-retail: the position's domain is checked before anything changes (retail stores any position)
        InputLimits.ThrowIfOutside(p, nameof(p));
        Touch();
        CutPose();
        StorePositionInternal(p);
    }

    // retail: CPhysicsObj::store_position (acclient.c:321388), for a position already in the domain
    private void StorePositionInternal(in Position p)
    {
        Position np = p;
        if ((np.ObjCellId & 0xFFFFu) < 0x100u)
        {
            LandDefs.AdjustToOutside(ref np.ObjCellId, ref np.Frame.Origin);
        }

        // The obstacle summary follows in SetFrameInternal.
        _position.ObjCellId = np.ObjCellId;
        if ((_state & PhysicsState.ParticleEmitter) == 0)
        {
            PartArray?.SetCellId(np.ObjCellId);
        }

        SetFrameInternal(np.Frame);
    }

    /// <summary>
    /// Places the object at <paramref name="p"/> through the world's <see cref="CollisionSweep"/> with the flags retail uses for a
    /// simple move: PLACEMENT-free teleport with a position event, plus SLIDE when <paramref name="sliding"/>.
    /// </summary>
    /// <param name="p">The position: the domain of <see cref="StorePosition"/>.</param>
    /// <param name="sliding">True to let the placement slide.</param>
    /// <exception cref="ArgumentException">The position is outside that domain (NaN, non-unit quaternion, origin out of
    /// range); state unchanged.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::SetPositionSimple (acclient.c:323420)
    public SetPositionError SetPositionSimple(in Position p, bool sliding)
    {
        ThrowIfRemoved();
        InputLimits.ThrowIfOutside(p, nameof(p));
        Touch();
        SetPositionFlags flags = SetPositionFlags.Teleport | SetPositionFlags.SendPositionEvent;
        if (sliding)
        {
            flags |= SetPositionFlags.Slide;
        }

        return SetPosition(p, flags);
    }

    /// <summary>Places the object at <paramref name="p"/> through the world's <see cref="CollisionSweep"/>.</summary>
    /// <param name="p">The position: the domain of <see cref="StorePosition"/>.</param>
    /// <param name="flags">The placement flags.</param>
    /// <exception cref="ArgumentException">The position is outside that domain (NaN, non-unit quaternion, origin out of
    /// range); state unchanged.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::SetPosition (acclient.c:323289)
    public SetPositionError SetPosition(in Position p, SetPositionFlags flags)
    {
        ThrowIfRemoved();
        InputLimits.ThrowIfOutside(p, nameof(p));
        Touch();
        CutPose();
        return World.Sweep.SetPosition(this, p, flags);
    }

    /// <summary>
    /// Enters the world at <paramref name="p"/>: stores the position, restarts the clock, places the object with SLIDE and,
    /// on success, activates it and tells the part array and movement manager.
    /// </summary>
    /// <returns>True when the object was placed in a cell and activated. False, with nothing changed, when the object has no
    /// <see cref="PartArray"/> (retail's <c>enter_cell</c> puts no such object in a cell: it would be in none) or when the
    /// position's cell does not exist or is not loaded (an outdoor cell whose landblock the sweep's cells do not hold, an indoor
    /// cell not loaded, an invalid cell id): the object stays where it was, out of the world if it was. False when the object
    /// has a parent (the position is stored, as retail, and the object stays attached) or the placement failed
    /// (<see cref="SetPositionError"/> other than Ok).</returns>
    /// <param name="p">The position: the domain of <see cref="StorePosition"/>.</param>
    /// <exception cref="ArgumentException">The position is outside that domain; state unchanged.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::enter_world(Position*) (acclient.c:323440) -> enter_world(slide) (acclient.c:323345)
    public bool EnterWorld(in Position p)
    {
        ThrowIfRemoved();
        InputLimits.ThrowIfOutside(p, nameof(p));
        // non-retail: without a part array retail "enters" no cell and answers true; a client is told instead
        // non-retail: retail stores the position and sends the object to the lost cell; a client is told instead
        if (_partArray is null || !World.Sweep.FindsCell(this, p))
        {
            return false;
        }

        Touch();
        CutPose();
        StorePositionInternal(p);
        if (Parent is not null)
        {
            return false;
        }

        UpdateTime = World.CurrentTime;
        if (World.Sweep.SetPosition(this, _position, SetPositionFlags.Placement | SetPositionFlags.Slide) != SetPositionError.Ok)
        {
            return false;
        }

        if ((_state & PhysicsState.Static) == 0)
        {
            if ((_transientState & TransientState.Active) == 0)
            {
                UpdateTime = World.CurrentTime;
            }

            _transientState |= TransientState.Active;
        }

        PartArray?.HandleEnterWorld();
        Movement?.HandleEnterWorld();
        return true;
    }

    /// <summary>
    /// Commits the result of a client's own sweep or placement: cell, frame, contact plane, CONTACT / WATER_CONTACT /
    /// ON_WALKABLE / SLIDING and acceleration. A result with no cell sends the object to the lost cell. A result carries no
    /// collisions: nothing is reported and the velocity is not bounced (a client sweep reports its own collisions). In a
    /// world that sweeps with a <see cref="RetailSweep"/> the object's shadows then follow it: it is re-shadowed where it
    /// stands (retail <c>CPhysicsObj::calc_cross_cells</c>).
    /// </summary>
    /// <param name="t">The result: <see cref="TransitionResult.CurrentPosition"/> in the domain of <see cref="StorePosition"/>,
    /// finite contact-plane and sliding normals, of unit length (|n|² within 5 × EPSILON of 1) when flagged valid, and a finite
    /// contact-plane distance.</param>
    /// <exception cref="ArgumentException">The result is outside that domain (state unchanged; retail stores it).</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::SetPositionInternal(CTransition*) (acclient.c:322503)
    public void CommitTransition(in TransitionResult t)
    {
        ThrowIfRemoved();
        // non-retail: a client sweep's result is checked before anything changes
        InputLimits.ThrowIfOutside(t.CurrentPosition, nameof(t));
        if (!InputLimits.IsNormalInDomain(t.ContactPlaneNormal, t.ContactPlaneValid)
            || !InputLimits.IsNormalInDomain(t.SlidingNormal, t.SlidingNormalValid) || !float.IsFinite(t.ContactPlaneD))
        {
            throw new ArgumentException(
                "Contact-plane and sliding normals must be finite (unit length when flagged valid) and the plane distance finite.",
                nameof(t));
        }

        CutPose();
        CommitTransitionInternal(t);
    }

    /// <summary>
    /// The engine's commit (no domain check) of <paramref name="t"/>, a result without a transition (a client's sweep, a
    /// free-space step): nothing to respond to; the world's sweep re-shadows the object where it stands
    /// (<see cref="CollisionSweep.ShadowInPlace"/>). See <see cref="CommitTransition"/>.
    /// </summary>
    // retail part: CPhysicsObj::SetPositionInternal(CTransition*) over a result in place of the transition (acclient.c line
    // 322503): the same cell, frame, contact-plane and sliding steps as the transition's commit below, no collisions
    internal void CommitTransitionInternal(in TransitionResult t)
    {
        Touch();
        if (!CommitCellAndFrame(t.CurrentPosition, t.CurrentCellId))
        {
            return;
        }

        CommitContactPlane(t.ContactPlaneValid, t.ContactPlaneNormal, t.ContactPlaneD, t.ContactPlaneCellId, t.ContactPlaneIsWater);
        CommitSlidingNormal(t.SlidingNormalValid, t.SlidingNormal);
        // non-retail: a result without a transition has no collisions to respond to and no cells of its own: the object is
        // shadowed where it stands (by a world that sweeps with a RetailSweep)
        if (CellId != 0 && !RemovedFromWorld)
        {
            World.Sweep.ShadowInPlace(this);
        }
    }

    /// <summary>
    /// The engine's commit of <paramref name="transit"/>, a transition of <paramref name="sweep"/>'s pool, read where it ended
    /// (its sphere path's current position and cell, its collision info): the object takes its cell, frame, contact plane and
    /// sliding normal, the transition's collisions are reported and its cells take the shadows.
    /// </summary>
    // retail: CPhysicsObj::SetPositionInternal(CTransition*) (acclient.c:322503)
    internal void CommitTransitionInternal(RetailSweep sweep, Transition transit)
    {
        Touch();
        bool prevOnWalkable = (_transientState & TransientState.OnWalkable) != 0;
        bool prevContact = (_transientState & TransientState.Contact) != 0;
        SpherePath path = transit.SpherePath;
        CollisionInfo ci = transit.CollisionInfo;
        if (!CommitCellAndFrame(path.CurrPos, path.CurrCell?.Id ?? 0))
        {
            return;
        }

        CommitContactPlane(ci.ContactPlaneValid, ci.ContactPlane.N, ci.ContactPlane.D, ci.ContactPlaneCellId, ci.ContactPlaneIsWater);
        CommitSlidingNormal(ci.SlidingNormalValid, ci.SlidingNormal);
        HandleAllCollisions(sweep, ci, prevContact, prevOnWalkable);
        // non-retail: a collision listener may have removed the object from its world: it casts no shadow any more
        if (CellId != 0 && !RemovedFromWorld)
        {
            UpdateCellShadows(sweep, transit);
        }
    }

    /// <summary>The commit's cell and frame: a position in no cell (<paramref name="cellId"/> 0) sends the object to the lost
    /// cell (false); otherwise it takes the cell (changing cells when it is another) and the frame.</summary>
    // retail part: the cell and frame lines of CPhysicsObj::SetPositionInternal(CTransition*) (acclient.c line 322503)
    private bool CommitCellAndFrame(in Position pos, uint cellId)
    {
        if (cellId == 0)
        {
            GoToLostCellInternal(pos);
            return false;
        }

        if (CellId == cellId)
        {
            uint id = pos.ObjCellId;
            // The obstacle summary follows in SetFrameInternal, below.
            _position.ObjCellId = id;
            if ((_state & PhysicsState.ParticleEmitter) == 0)
            {
                PartArray?.SetCellId(id);
            }

            SetChildrenCellId(id);
        }
        else
        {
            ChangeCell(cellId);
        }

        SetFrameInternal(pos.Frame);
        return true;
    }

    /// <summary>The commit's contact plane: the plane stored, CONTACT, WATER_CONTACT and ON_WALKABLE set from it, the
    /// acceleration recomputed (leaving the ground tells the movement manager).</summary>
    // retail part: the contact-plane lines of CPhysicsObj::SetPositionInternal(CTransition*) (acclient.c line 322503)
    private void CommitContactPlane(bool valid, Vector3 normal, float d, uint cellId, bool isWater)
    {
        ContactPlaneCellId = cellId;
        ContactPlaneNormal = normal;
        ContactPlaneD = d;
        if (valid)
        {
            _transientState |= TransientState.Contact;
        }
        else
        {
            _transientState &= ~TransientState.Contact;
        }

        CalcAcceleration();
        if (isWater)
        {
            _transientState |= TransientState.WaterContact;
        }
        else
        {
            _transientState &= ~TransientState.WaterContact;
        }

        if ((_transientState & TransientState.Contact) != 0)
        {
            SetOnWalkableInternal(!(ContactPlaneNormal.Z < PhysicsGlobals.FloorZ));
        }
        else
        {
            bool wasOnWalkable = (_transientState & TransientState.OnWalkable) != 0;
            _transientState &= ~TransientState.OnWalkable;
            if (wasOnWalkable)
            {
                Movement?.LeaveGround();
            }

            CalcAcceleration();
        }
    }

    /// <summary>The commit's sliding normal and SLIDING.</summary>
    // retail part: the sliding lines of CPhysicsObj::SetPositionInternal(CTransition*) (acclient.c line 322503)
    private void CommitSlidingNormal(bool valid, Vector3 normal)
    {
        SlidingNormal = normal;
        if (valid)
        {
            _transientState |= TransientState.Sliding;
        }
        else
        {
            _transientState &= ~TransientState.Sliding;
        }
    }

    /// <summary>
    /// Sends the object out of every cell (retail's lost cell): leaves its cell, stores <paramref name="p"/> and deactivates it.
    /// </summary>
    /// <param name="p">The position: the domain of <see cref="StorePosition"/>.</param>
    /// <exception cref="ArgumentException">The position is outside that domain; checked before the object leaves its cell
    /// (state unchanged).</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: the lost-cell branch of CPhysicsObj::SetPositionInternal (acclient.c:322503, 323034)
    public void GoToLostCell(in Position p)
    {
        ThrowIfRemoved();
        InputLimits.ThrowIfOutside(p, nameof(p));
        GoToLostCellInternal(p);
    }

    // retail: the lost-cell branch of CPhysicsObj::SetPositionInternal (acclient.c:322503, 323034)
    internal void GoToLostCellInternal(in Position p)
    {
        Touch();
        CutPose();
        // retail: CPhysicsObj::prepare_to_leave_visibility (acclient.c:319195), its cell and lost-cell lines
        RemoveShadowsFromCells();
        World.RemoveFromLostCell(this);
        LeaveCell();
        // The engine's own lost positions can be outside the domain (a sweep past the world edge): stored unchecked.
        StorePositionInternal(p);
        World.GotoLostCell(this, _position.ObjCellId);
        _transientState &= ~TransientState.Active;
    }

    /// <summary>The object's lost cell was loaded: it is placed again at its stored position, sliding, its clock restarted.
    /// True when that placement failed.</summary>
    // retail: CPhysicsObj::reenter_visibility (acclient.c:323395), with prepare_to_enter_world (acclient.c:319217)
    internal bool ReenterVisibility()
    {
        Touch();
        UpdateTime = World.CurrentTime;
        World.RemoveFromLostCell(this);
        return World.Sweep.SetPosition(this, _position, SetPositionFlags.Placement | SetPositionFlags.Slide) != SetPositionError.Ok;
    }

    /// <summary>The object leaves visibility (its cell is released): it leaves its cell and shadows, keeps its position and
    /// waits in the lost cell of its position's cell until that cell is loaded again.</summary>
    // retail: CPhysicsObj::leave_visibility (acclient.c:321417)
    internal void LeaveVisibility() => GoToLostCellInternal(_position);
}
