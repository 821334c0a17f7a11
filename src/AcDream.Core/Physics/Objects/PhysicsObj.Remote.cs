using System;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Objects;

// The remote-object update path and the sticky/target entry points of the position managers.
public sealed partial class PhysicsObj
{
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
}
