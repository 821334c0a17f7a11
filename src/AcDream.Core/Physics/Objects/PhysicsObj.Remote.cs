using System;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Math;

namespace AcDream.Core.Physics.Objects;

// The remote-object update path and the sticky/target entry points of the position managers.
public sealed partial class PhysicsObj
{
    /// <summary>
    /// Applies a server position report for an object the client does not control (the remote branch of retail's
    /// <c>SmartBox::HandleReceivedPosition</c>): a report whose position timestamp is not newer is dropped; one whose teleport
    /// timestamp is older is dropped and the position stamp restored; otherwise <see cref="MoveOrTeleport"/> runs and, when it
    /// used the report, the constraint is re-armed at the object's current position with
    /// <see cref="GetStartConstraintDistance"/> / <see cref="GetMaxConstraintDistance"/> (the dead-reckoning leash).
    /// </summary>
    /// <remarks>SmartBox's parent and placement-frame handling (unset_parent, SetPlacementFrame) and its error counter are
    /// the client's concern and not ported here.</remarks>
    /// <param name="p">Reported position: unit quaternion; origin within ±<see cref="InputLimits.MaxCoordinate"/>, outdoor x, y
    /// in [−192, 384] (<see cref="InputLimits.OutdoorMargin"/>).</param>
    /// <param name="positionTimestamp">The report's 16-bit position timestamp (POSITION_TS).</param>
    /// <param name="teleportTimestamp">The report's 16-bit teleport timestamp (TELEPORT_TS).</param>
    /// <param name="hasContact">The report says the object is on the ground.</param>
    /// <returns>True when the report moved, queued or placed the object.</returns>
    /// <exception cref="ArgumentException"><paramref name="p"/> is outside the position domain of <see cref="StorePosition"/>
    /// (invalid rotation; origin not finite, beyond ±65,536 m, or outdoor x, y outside [−192, 384]); nothing changes.</exception>
    // retail: SmartBox::HandleReceivedPosition (acclient.c:145124)
    public bool HandleReceivedPosition(in Position p, ushort positionTimestamp, ushort teleportTimestamp, bool hasContact)
    {
        if (!ManagerMath.IsUsable(p))
        {
            throw new ArgumentException("Position must have a finite origin and a valid rotation.", nameof(p));
        }

        ushort previousPositionTime = GetUpdateTime(PhysicsTimeStamp.Position);
        if (!NewerEvent(PhysicsTimeStamp.Position, positionTimestamp))
        {
            return false;
        }

        ushort teleportTime = GetUpdateTime(PhysicsTimeStamp.Teleport);
        bool staleTeleport = System.Math.Abs(teleportTime - teleportTimestamp) > 0x7FFF
            ? teleportTime < teleportTimestamp
            : teleportTimestamp < teleportTime;
        if (staleTeleport)
        {
            _updateTimes[(int)PhysicsTimeStamp.Position] = previousPositionTime;
            return false;
        }

        if (!MoveOrTeleport(p, teleportTimestamp, hasContact))
        {
            return false;
        }

        // acclient.c:145227: re-arm the leash at the object's own position.
        // non-retail: an own position outside the input domain (retail's zeroed quaternion, a free-space drift beyond
        // ±65,536 m) skips the re-arm instead of refusing after the move
        if (InputLimits.IsPositionInDomain(_position))
        {
            ConstrainTo(_position, (float)GetStartConstraintDistance(), (float)GetMaxConstraintDistance());
        }
        return true;
    }

    /// <summary>Passes a target-tracking report (context 0 only) to the position manager.</summary>
    /// <param name="info">The report.</param>
    /// <remarks>Retail also forwards it to the movement manager, whose seam here has no such entry.</remarks>
    // retail: CPhysicsObj::HandleUpdateTarget (acclient.c:319966)
    public void HandleUpdateTarget(in TargetInfo info)
    {
        Touch();
        if (info.ContextId != 0)
        {
            return;
        }

        PositionManager?.HandleUpdateTarget(info);
    }

    /// <summary>
    /// Sticks to object <paramref name="objectId"/> (its top-level parent when attached), with that object's radius. As
    /// retail, the position manager is created (and the object activated) first, also when the world has no such object;
    /// then nothing else happens.
    /// </summary>
    /// <param name="objectId">Target id: any value (an id the world does not hold sticks to nothing).</param>
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
}
