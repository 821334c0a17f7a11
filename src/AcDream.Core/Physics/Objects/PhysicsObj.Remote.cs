using System;

namespace AcDream.Core.Physics;

/// <summary>The remote-object update path and the sticky/target entry points of the position managers (issue 4).</summary>
public sealed partial class PhysicsObj
{
    /// <summary>
    /// Applies a server position report for an object the client does not control: the remote branch of
    /// <c>SmartBox::HandleReceivedPosition</c> through <c>CPhysicsObj::MoveOrTeleport</c>. A teleport (or an object not yet in
    /// a cell) is placed at once after the teleport hook; an update without ground contact is ignored; an object 96 m or
    /// more from the player snaps (interpolation stopped); anything else is interpolated, keeping the heading while a
    /// move-to runs. When the report was used, the constraint is re-armed at the object's current position with
    /// <see cref="GetStartConstraintDistance"/> / <see cref="GetMaxConstraintDistance"/>.
    /// </summary>
    /// <remarks>Retail's timestamp tests (a stale teleport stamp drops the report; a newer one means teleport) belong to
    /// the caller, which passes the outcome in <paramref name="isNewTeleport"/>.</remarks>
    /// <param name="p">Reported position.</param>
    /// <param name="isNewTeleport">The report carries a newer teleport timestamp.</param>
    /// <param name="hasContact">The report says the object is on the ground.</param>
    /// <returns>True when the report moved, queued or placed the object (retail MoveOrTeleport's result).</returns>
    /// <exception cref="ArgumentException"><paramref name="p"/> has a non-finite origin or an invalid rotation; nothing changes.</exception>
    // retail: CPhysicsObj::MoveOrTeleport (acclient.c:323450); SmartBox::HandleReceivedPosition (acclient.c:145124)
    public bool ReceiveRemotePosition(in Position p, bool isNewTeleport, bool hasContact)
    {
        if (!ManagerMath.IsUsable(p))
        {
            throw new ArgumentException("Position must have a finite origin and a valid rotation.", nameof(p));
        }

        if (isNewTeleport || CellId == 0)
        {
            TeleportHookForPositionManager();
            SetPosition(p, SetPositionFlags.Teleport | SetPositionFlags.Slide | SetPositionFlags.SendPositionEvent);
        }
        else
        {
            if (!hasContact)
            {
                return false;
            }

            if (PlayerDistance >= PhysicsGlobals.PlayerActivityDistance)
            {
                PositionManager?.StopInterpolating();
                SetPositionSimple(p, true);
            }
            else
            {
                FollowRemoteReport(p); // retail profile: InterpolateTo(p, IsMovingTo())
            }
        }

        // SmartBox::HandleReceivedPosition (acclient.c:145227): re-arm the leash at the object's own position.
        ConstrainTo(_position, (float)GetStartConstraintDistance(), (float)GetMaxConstraintDistance());
        return true;
    }

    /// <summary>Passes a target-tracking report (context 0 only) to the position manager.</summary>
    /// <param name="info">The report.</param>
    /// <remarks>Retail also forwards it to the movement manager, whose seam here has no such entry.</remarks>
    // retail: CPhysicsObj::HandleUpdateTarget (acclient.c:319966)
    public void HandleUpdateTarget(in TargetInfo info)
    {
        if (info.ContextId != 0)
        {
            return;
        }

        PositionManager?.HandleUpdateTarget(info);
    }

    /// <summary>
    /// Sticks to object <paramref name="objectId"/> (its top-level parent when attached), with that object's radius; does
    /// nothing when the world has no such object.
    /// </summary>
    /// <param name="objectId">Target id.</param>
    // retail: CPhysicsObj::stick_to_object (acclient.c:319724)
    public void StickToObject(uint objectId)
    {
        PositionManager pm = MakePositionManager();
        PhysicsObj? found = World.GetObjectById(objectId);
        if (found is null)
        {
            return;
        }

        PhysicsObj target = found.Parent ?? found;
        float height = (float)target.GetHeight();
        float radius = (float)target.GetRadius();
        pm.StickTo(target.Id, radius, height);
    }

    // The position-manager part of retail's CPhysicsObj::teleport_hook (acclient.c:322236): UnStick, StopInterpolating,
    // UnConstrain. (The move-to cancel and the target notifications belong to seams this port does not have.)
    private void TeleportHookForPositionManager()
    {
        PositionManager? pm = PositionManager;
        if (pm is null)
        {
            return;
        }

        pm.UnStick();
        pm.StopInterpolating();
        pm.UnConstrain();
    }
}
