// PhysicsObj — remote objects: newer_event, MoveOrTeleport, teleport_hook, HandleReceivedPosition, stick_to_object; smoothing.
using System;
using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Objects;

// The remote-object update path and the sticky/target entry points of the position managers.
public sealed partial class PhysicsObj
{
    private UpdateTimeStamps _updateTimes;

    /// <summary>Last accepted 16-bit timestamp of <paramref name="stamp"/> (retail <c>update_times</c>).</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="stamp"/> is not a defined stamp.</exception>
    public ushort GetUpdateTime(PhysicsTimeStamp stamp) => _updateTimes[StampIndex(stamp)];

    private int StampIndex(PhysicsTimeStamp stamp) =>
        (uint)stamp < (uint)UpdateTimeStamps.Count ? (int)stamp : throw new ArgumentOutOfRangeException(nameof(stamp));

    /// <summary>
    /// True when <paramref name="newTime"/> is newer than the stored stamp in 16-bit wrap-around order (a difference above
    /// 0x7FFF means the counter wrapped); a newer stamp is stored.
    /// </summary>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::newer_event (acclient.c:143014)
    public bool NewerEvent(PhysicsTimeStamp stamp, ushort newTime)
    {
        ThrowIfRemoved();
        ushort old = _updateTimes[StampIndex(stamp)];
        bool newer = Math.Abs(newTime - old) > 0x7FFF ? newTime < old : old < newTime;
        if (newer)
        {
            _updateTimes[(int)stamp] = newTime;
        }

        return newer;
    }

    /// <summary>
    /// Applies a server position: a stale teleport stamp is ignored; a newer teleport (or an object with no cell) teleports;
    /// otherwise, only with contact, an object at least 96 m from the player snaps there and a nearer one interpolates.
    /// </summary>
    /// <returns>True when the position was used.</returns>
    /// <param name="p">The reported position: the position domain of <see cref="StorePosition"/> (unit quaternion; origin
    /// within ±65,536 m, outdoor x, y in [−192, 384]).</param>
    /// <param name="teleportTimestamp">The report's 16-bit teleport timestamp (any value; wrap-around order).</param>
    /// <param name="contact">The report says the object is on the ground.</param>
    /// <exception cref="ArgumentException">The position is outside that domain; state unchanged.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::MoveOrTeleport (acclient.c:323450)
    public bool MoveOrTeleport(in Position p, ushort teleportTimestamp, bool contact)
    {
        ThrowIfRemoved();
        return MoveOrTeleportResult(p, teleportTimestamp, contact) >= ReceivedPositionResult.Interpolating;
    }

    // retail: CPhysicsObj::MoveOrTeleport (acclient.c:323450), answering which branch it took
    private ReceivedPositionResult MoveOrTeleportResult(in Position p, ushort teleportTimestamp, bool contact)
    {
        InputLimits.ThrowIfOutside(p, nameof(p));
        Touch();

        ushort stored = _updateTimes[(int)PhysicsTimeStamp.Teleport];
        bool older = Math.Abs(stored - teleportTimestamp) > 0x7FFF ? stored < teleportTimestamp : teleportTimestamp < stored;
        if (older)
        {
            return ReceivedPositionResult.StaleTeleport;
        }

        if (NewerEvent(PhysicsTimeStamp.Teleport, teleportTimestamp) || CellId == 0)
        {
            bool loaded = World.Sweep.FindsCell(this, p);
            TeleportHook();
            return Placement(loaded, SetPosition(p, SetPositionFlags.Teleport | SetPositionFlags.Slide | SetPositionFlags.SendPositionEvent));
        }

        if (!contact)
        {
            return ReceivedPositionResult.NoContact;
        }

        bool cellLoaded = World.Sweep.FindsCell(this, p);
        if (PlayerDistance >= PhysicsGlobals.PlayerActivityDistance)
        {
            PositionManager?.StopInterpolating();
            return Placement(cellLoaded, SetPositionSimple(p, true));
        }

        // non-retail: fidelity switch PhysicsProfile.RemoteSmoothing; the retail profile runs InterpolateTo(p, IsMovingTo())
        if (FollowRemoteReport(p, out SetPositionError placed))
        {
            return cellLoaded ? ReceivedPositionResult.Interpolating : ReceivedPositionResult.InterpolatingToUnloadedCell;
        }

        return Placement(cellLoaded, placed);
    }

    private static ReceivedPositionResult Placement(bool cellLoaded, SetPositionError e) =>
        !cellLoaded ? ReceivedPositionResult.LeftWorld
        : e == SetPositionError.Ok ? ReceivedPositionResult.Placed
        : ReceivedPositionResult.PlacementFailed;

    /// <summary>Drops every move-to, stickiness, interpolation, constraint and target before a teleport.</summary>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::teleport_hook (acclient.c:322236)
    public void TeleportHook()
    {
        ThrowIfRemoved();
        Touch();
        Movement?.CancelMoveTo(MotionError.ITeleported);
        PositionManager?.StopSticking();
        PositionManager?.StopInterpolating();
        PositionManager?.StopConstraining();
        if (TargetManager is { } tm)
        {
            tm.ClearTarget();
            tm.NotifyVoyeurOfEvent(Managers.TargetStatus.Teleported);
        }
        World.Sweep.ReportCollisionEnd(this, true);
    }

    // The remote-object update path and the sticky/target entry points of the position managers.

    /// <summary>
    /// Applies a server position report for an object the client does not control (the remote branch of retail's
    /// <c>SmartBox::HandleReceivedPosition</c>): a report whose position timestamp is not newer is dropped; one whose teleport
    /// timestamp is older is dropped and the position stamp restored; otherwise <see cref="MoveOrTeleport"/> runs and, when it
    /// used the report, the constraint is re-armed at the object's current position with
    /// <see cref="StartConstraintDistance"/> / <see cref="MaxConstraintDistance"/> (the dead-reckoning leash).
    /// </summary>
    /// <remarks><para>SmartBox's parent and placement-frame handling (unset_parent, SetPlacementFrame) and its error counter are
    /// the client's concern and not ported here.</para>
    /// <para>Before the first report the network layer gives the object a part array from its Setup, a motion table and
    /// a weenie, and its first position (<see cref="EnterWorld"/>); between reports the server's MovementEvents drive its motion
    /// (<see cref="Motion.Wire.MovementEvent.ApplyInterpretedMotion"/>; docs/interpolation.md, "What a network layer sets first").</para></remarks>
    /// <param name="p">The reported position: the cell id and the frame local to that cell's landblock, as the server's
    /// position update carries them; unit quaternion, origin within ±<see cref="InputLimits.MaxCoordinate"/>, outdoor x, y in
    /// [−192, 384] (<see cref="InputLimits.OutdoorMargin"/>).</param>
    /// <param name="positionTimestamp">The update's 16-bit position sequence (retail POSITION_TS), compared with wrap-around: a
    /// report whose sequence is not newer than the last one applied is dropped.</param>
    /// <param name="teleportTimestamp">The update's 16-bit teleport sequence (retail TELEPORT_TS): older than the object's is a
    /// stale report (dropped); newer means the server moved the object discontinuously, so it is placed (teleported) at
    /// <paramref name="p"/> instead of interpolated. Pass the last value received while no teleport happened (0 from the
    /// start).</param>
    /// <param name="hasContact">The update's contact flag: the object stands on the ground. Without contact a nearby object is
    /// not interpolated (its own physics carries it, e.g. through a jump) unless the report teleports it.</param>
    /// <returns>What happened: <see cref="ReceivedPositionResult.Stale"/>, <see cref="ReceivedPositionResult.StaleTeleport"/>
    /// or <see cref="ReceivedPositionResult.NoContact"/> when the report was not used;
    /// <see cref="ReceivedPositionResult.Interpolating"/> (or <see cref="ReceivedPositionResult.InterpolatingToUnloadedCell"/>)
    /// when it was queued; <see cref="ReceivedPositionResult.Placed"/> when the object was placed there; and
    /// <see cref="ReceivedPositionResult.LeftWorld"/> when the report's cell is not loaded and the object was sent out of the
    /// world (cell 0), as retail does. The leash is re-armed for the last four.</returns>
    /// <exception cref="ArgumentException"><paramref name="p"/> is outside the position domain of <see cref="StorePosition"/>
    /// (invalid rotation; origin not finite, beyond ±65,536 m, or outdoor x, y outside [−192, 384]); nothing changes.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: SmartBox::HandleReceivedPosition (acclient.c:145124)
    public ReceivedPositionResult HandleReceivedPosition(in Position p, ushort positionTimestamp, ushort teleportTimestamp, bool hasContact)
    {
        ThrowIfRemoved();
        if (!InputLimits.IsPositionInDomain(p))
        {
            throw new ArgumentException("Position must have a finite origin and a valid rotation.", nameof(p));
        }

        ushort previousPositionTime = GetUpdateTime(PhysicsTimeStamp.Position);
        if (!NewerEvent(PhysicsTimeStamp.Position, positionTimestamp))
        {
            return ReceivedPositionResult.Stale;
        }

        ushort teleportTime = GetUpdateTime(PhysicsTimeStamp.Teleport);
        bool staleTeleport = Math.Abs(teleportTime - teleportTimestamp) > 0x7FFF
            ? teleportTime < teleportTimestamp
            : teleportTimestamp < teleportTime;
        if (staleTeleport)
        {
            _updateTimes[(int)PhysicsTimeStamp.Position] = previousPositionTime;
            return ReceivedPositionResult.StaleTeleport;
        }

        ReceivedPositionResult result = MoveOrTeleportResult(p, teleportTimestamp, hasContact);
        if (result < ReceivedPositionResult.Interpolating)
        {
            return result;
        }

        // acclient.c:145227: re-arm the leash at the object's own position.
        // non-retail: an own position outside the input domain (retail's zeroed quaternion, a free-space drift beyond
        // ±65,536 m) skips the re-arm instead of refusing after the move
        if (InputLimits.IsPositionInDomain(_position))
        {
            ConstrainTo(_position, (float)StartConstraintDistance, (float)MaxConstraintDistance);
        }

        return result;
    }

    /// <summary>Passes a target-tracking report (context 0 only) to the movement manager (a move-to or turn-to the target)
    /// and the position manager (a stick). The object's <see cref="TargetManager"/> does this for the reports it receives;
    /// a client may pass its own.</summary>
    /// <param name="info">The report.</param>
    /// <exception cref="ArgumentException">An Ok report (context 0) whose target or interpolated position is outside the
    /// position domain; nothing changes.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::HandleUpdateTarget (acclient.c:319966)
    public void HandleUpdateTarget(in TargetInfo info)
    {
        ThrowIfRemoved();
        // non-retail: an Ok report's positions must be usable before any manager acts on it (the move-to plans from both)
        if (info.Status == TargetStatus.Ok && info.ContextId == 0
            && (!InputLimits.IsPositionInDomain(info.TargetPosition) || !InputLimits.IsPositionInDomain(info.InterpolatedPosition)))
        {
            throw new ArgumentException("An Ok report's target and interpolated positions must be in the position domain.",
                nameof(info));
        }

        HandleUpdateTargetInternal(info);
    }

    /// <summary>
    /// Sticks to object <paramref name="objectId"/> (its top-level parent when attached), with that object's radius. As
    /// retail, the position manager is created (and the object activated) first, also when the world has no such object;
    /// then nothing else happens.
    /// </summary>
    /// <param name="objectId">Target id: any value (an id the world does not hold sticks to nothing).</param>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::stick_to_object (acclient.c:319724)
    public void StickToObject(uint objectId)
    {
        ThrowIfRemoved();
        PositionManager pm = MakePositionManager();
        PhysicsObj? found = World.GetObjectById(objectId);
        if (found is null)
        {
            return;
        }

        PhysicsObj target = found.Parent ?? found;
        float height = target.Height;
        float radius = target.Radius;
        pm.StickTo(target.Id, radius, height);
    }

    // The non-retail remote-smoothing modes of PhysicsProfile.RemoteSmoothing: snapping to each report and plain linear
    // extrapolation. Under the retail default none of this runs.

    /// <summary>Velocity (world axes, m/s) used by <see cref="RemoteSmoothing.LinearExtrapolation"/> since the last report;
    /// zero otherwise.</summary>
    public Vector3 ExtrapolationVelocity => _rare?.Extrapolation is { Extrapolating: true } e ? e.Velocity : Vector3.Zero;

    // The in-range branch of MoveOrTeleport under the world's profile: retail interpolates (true); the other modes place the
    // body (false, with the placement's result).
    private bool FollowRemoteReport(in Position p, out SetPositionError placed)
    {
        RemoteSmoothing mode = World.Profile.RemoteSmoothing;
        placed = SetPositionError.Ok;
        if (mode == RemoteSmoothing.Retail)
        {
            InterpolateTo(p, IsMovingTo());
            return true;
        }

        PositionManager?.StopInterpolating();
        if (mode == RemoteSmoothing.LinearExtrapolation)
        {
            // Created at the object's first report in this mode (a network event, never inside the object's own update).
            RareComponents rare = Rare(create: true)!;
            Extrapolation e = rare.Extrapolation ??= new Extrapolation();
            double now = World.CurrentTime;
            double span = now - e.LastReportTime;
            if (span > PhysicsGlobals.Epsilon)
            {
                Vector3 d = e.LastReport.GetOffset(p);
                double inv = 1.0 / span;
                e.Velocity = new Vector3((float)(d.X * inv), (float)(d.Y * inv), (float)(d.Z * inv));
                e.Extrapolating = true;
            }

            e.LastReport = p;
            e.LastReportTime = now;
        }

        placed = SetPositionSimple(p, true);
        return false;
    }

    // LinearExtrapolation: replaces the step's offset origin (root motion) by the extrapolation velocity × quantum.
    private void ApplyExtrapolation(ref Frame offset, float quantum)
    {
        Extrapolation? e = _rare?.Extrapolation;
        if (e is null || !e.Extrapolating || World.Profile.RemoteSmoothing != RemoteSmoothing.LinearExtrapolation)
        {
            return;
        }

        Vector3 v = e.Velocity;
        offset.Origin = _position.Frame.GlobalToLocalVec(new Vector3(v.X * quantum, v.Y * quantum, v.Z * quantum));
    }

    // LinearExtrapolation's state: the last report, its time (NaN before the first) and the velocity the last two gave.
    private sealed class Extrapolation
    {
        public Position LastReport;
        public double LastReportTime = double.NaN;
        public Vector3 Velocity;
        public bool Extrapolating;
    }
}
