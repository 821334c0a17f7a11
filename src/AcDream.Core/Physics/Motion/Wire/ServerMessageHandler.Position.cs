using System;
using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Motion.Wire;

// UpdatePosition (0xF748) and PlayerTeleport (0xF751): SmartBox::UnpackPositionEvent, HandleReceivedPosition,
// BlipPlayer, TeleportPlayer, PlayerPositionUpdated, HandlePlayerTeleport.
public sealed partial class ServerMessageHandler
{
    /// <summary>
    /// Applies an UpdatePosition (0xF748) as retail's client does. The instance gate first (unknown object or newer
    /// instance: <see cref="ServerMessageResult.UnknownObject"/>; older: <see cref="ServerMessageResult.OldInstance"/>).
    /// For the player, a newer force-position stamp (and a teleport stamp not older than the player's) blips it there with
    /// its own heading. Otherwise a position stamp not newer, or an older teleport stamp, drops the message
    /// (<see cref="ServerMessageResult.Stale"/>); the object leaves its parent; the player is teleported by a newer teleport
    /// stamp, else leashed to the position and, when it follows the server and has contact, interpolated there
    /// (<see cref="ServerMessageResult.PlayerOwnEcho"/> when it does not); any other object goes through
    /// <see cref="PhysicsObj.HandleReceivedPosition"/> (its detail in <see cref="LastReceivedPosition"/>).
    /// </summary>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    /// <exception cref="ArgumentException">The position is outside the position domain (nothing changes).</exception>
    // retail: SmartBox::UnpackPositionEvent (acclient.c:145253)
    public ServerMessageResult HandleUpdatePosition(UpdatePositionMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        InputLimits.ThrowIfOutside(message.Position, nameof(message));
        ServerMessageResult gate = InstanceGate(message.ObjectId, message.InstanceTimestamp, out PhysicsObj obj);
        if (gate != ServerMessageResult.Applied)
        {
            return gate;
        }

        return ReceivedPosition(obj, message.Position, message.HasContact, message.PositionTimestamp,
            message.TeleportTimestamp, message.ForcePositionTimestamp);
    }

    // retail: SmartBox::HandleReceivedPosition (acclient.c:145124). The placement frame (SetPlacementFrame when the object
    // has no animations) and the weenie's unparent notice are the client's; the velocity is not used (retail's pack leaves
    // it unread).
    private ServerMessageResult ReceivedPosition(PhysicsObj obj, Position pos, bool hasContact, ushort positionTime,
                                                 ushort teleportTime, ushort forcePositionTime)
    {
        PhysicsObj? player = Player;
        if (obj == player && obj.NewerEvent(PhysicsTimeStamp.ForcePosition, forcePositionTime)
            && !IsNewer(teleportTime, obj.GetUpdateTime(PhysicsTimeStamp.Teleport)))
        {
            // acclient.c:145244-145251: the server's position with the player's own heading.
            pos.Frame.SetHeading(obj.Position.Frame.Heading);
            BlipPlayer(obj, pos);
            obj.SetUpdateTime(PhysicsTimeStamp.Position, positionTime);
            PlayerControl?.PositionForcedByServer();
            return ServerMessageResult.PlayerBlipped;
        }

        if (obj != player)
        {
            // The remote branch is PhysicsObj.HandleReceivedPosition (the same gates, MoveOrTeleport, the leash); the
            // object leaves its parent between the gates and the move, as here.
            if (IsNewer(obj.GetUpdateTime(PhysicsTimeStamp.Position), positionTime)
                && !IsNewer(teleportTime, obj.GetUpdateTime(PhysicsTimeStamp.Teleport)))
            {
                obj.UnsetParent();
            }

            LastReceivedPosition = obj.HandleReceivedPosition(pos, positionTime, teleportTime, hasContact);
            return LastReceivedPosition <= ReceivedPositionResult.StaleTeleport
                ? ServerMessageResult.Stale
                : ServerMessageResult.Applied;
        }

        ushort previous = obj.GetUpdateTime(PhysicsTimeStamp.Position);
        if (!obj.NewerEvent(PhysicsTimeStamp.Position, positionTime))
        {
            return ServerMessageResult.Stale;
        }

        if (IsNewer(teleportTime, obj.GetUpdateTime(PhysicsTimeStamp.Teleport)))
        {
            obj.SetUpdateTime(PhysicsTimeStamp.Position, previous);
            return ServerMessageResult.Stale;
        }

        obj.UnsetParent();
        if (obj.NewerEvent(PhysicsTimeStamp.Teleport, teleportTime))
        {
            TeleportPlayer(obj, pos);
            obj.ConstrainTo(pos, (float)obj.StartConstraintDistance, (float)obj.MaxConstraintDistance);
            obj.SetVelocity(Vector3.Zero);
            return ServerMessageResult.PlayerTeleported;
        }

        obj.ConstrainTo(pos, (float)obj.StartConstraintDistance, (float)obj.MaxConstraintDistance);
        if (UsePositionFromServer && hasContact)
        {
            // non-retail: retail asks the command interpreter whether to keep the heading (a virtual the decompilation
            // does not name); the object's move-to state answers, as MoveOrTeleport's does for remote objects
            obj.InterpolateTo(pos, obj.IsMovingTo());
            return ServerMessageResult.Applied;
        }

        return ServerMessageResult.PlayerOwnEcho;
    }

    // retail: SmartBox::BlipPlayer (acclient.c:144747)
    private void BlipPlayer(PhysicsObj player, in Position pos) => player.SetPositionSimple(pos, true);

    // retail: SmartBox::TeleportPlayer (acclient.c:144732) and PlayerPositionUpdated's teleport lines (acclient.c:144694)
    private void TeleportPlayer(PhysicsObj player, in Position pos)
    {
        player.SetPositionSimple(pos, true);
        PositionUpdateComplete = false;
        WaitingForTeleport = false;
        HasBeenTeleported = false;
        player.TeleportHook();
        PlayerControl?.PlayerTeleported();
    }

    /// <summary>
    /// Applies a PlayerTeleport (0xF751): unless its stamp is older than the player's teleport stamp, the player is now
    /// waiting for the teleport (<see cref="WaitingForTeleport"/>; <see cref="PositionUpdateComplete"/> and
    /// <see cref="HasBeenTeleported"/> cleared) until a SetState shows it again.
    /// </summary>
    /// <returns><see cref="ServerMessageResult.Applied"/>, <see cref="ServerMessageResult.Stale"/>, or
    /// <see cref="ServerMessageResult.NotApplicable"/> before the player exists.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    // retail: SmartBox::HandlePlayerTeleport (acclient.c:143427)
    public ServerMessageResult HandlePlayerTeleport(PlayerTeleportMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        PhysicsObj? player = Player;
        if (player is null)
        {
            return ServerMessageResult.NotApplicable;
        }

        if (IsNewer(message.TeleportTimestamp, player.GetUpdateTime(PhysicsTimeStamp.Teleport)))
        {
            return ServerMessageResult.Stale;
        }

        PositionUpdateComplete = false;
        HasBeenTeleported = false;
        WaitingForTeleport = true;
        return ServerMessageResult.Applied;
    }
}
