using System;
using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Motion.Wire;

// VectorUpdate, SetState, ParentEvent, PickupEvent, DeleteObject and the MovementEvent's SmartBox side.
public sealed partial class ServerMessageHandler
{
    /// <summary>Applies a VectorUpdate (0xF74E): after the instance gate, a vector stamp not newer is dropped; otherwise
    /// the object takes the velocity and omega (a remote's jump), except the player while its client is in control
    /// (<see cref="ServerMessageResult.PlayerOwnEcho"/>, the stamp taken).</summary>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    /// <exception cref="ArgumentException">A velocity or omega component is NaN or infinite (nothing changes).</exception>
    // retail: SmartBox::HandleVectorUpdate (acclient.c:144433)
    public ServerMessageResult HandleVectorUpdate(VectorUpdateMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        if (!VectorMath.IsFinite(message.Velocity) || !VectorMath.IsFinite(message.Omega))
        {
            throw new ArgumentException("The velocity and omega must be finite.", nameof(message));
        }

        ServerMessageResult gate = InstanceGate(message.ObjectId, message.InstanceTimestamp, out PhysicsObj obj);
        return gate != ServerMessageResult.Applied
            ? gate
            : DoVectorUpdate(obj, message.Velocity, message.Omega, message.VectorTimestamp);
    }

    // retail: SmartBox::DoVectorUpdate (acclient.c:143458)
    private ServerMessageResult DoVectorUpdate(PhysicsObj obj, Vector3 velocity, Vector3 omega, ushort vectorTime)
    {
        if (!obj.NewerEvent(PhysicsTimeStamp.Vector, vectorTime))
        {
            return ServerMessageResult.Stale;
        }

        if (obj == Player && !UsePositionFromServer)
        {
            return ServerMessageResult.PlayerOwnEcho;
        }

        obj.SetVelocity(velocity);
        obj.SetOmega(omega);
        return ServerMessageResult.Applied;
    }

    /// <summary>Applies a SetState (0xF74B): after the instance gate, a state stamp not newer is dropped; otherwise the
    /// object takes the state bits, and the player waiting for a teleport stops waiting once it is no longer hidden.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    // retail: SmartBox::HandleSetState (acclient.c:144394)
    public ServerMessageResult HandleSetState(SetStateMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        ServerMessageResult gate = InstanceGate(message.ObjectId, message.InstanceTimestamp, out PhysicsObj obj);
        return gate != ServerMessageResult.Applied ? gate : DoSetState(obj, message.State, message.StateTimestamp);
    }

    // retail: SmartBox::DoSetState (acclient.c:143395)
    private ServerMessageResult DoSetState(PhysicsObj obj, PhysicsState state, ushort stateTime)
    {
        if (!obj.NewerEvent(PhysicsTimeStamp.State, stateTime))
        {
            return ServerMessageResult.Stale;
        }

        obj.SetState(state);
        if (obj == Player && WaitingForTeleport && (obj.State & PhysicsState.Hidden) == 0)
        {
            WaitingForTeleport = false;
        }

        return ServerMessageResult.Applied;
    }

    /// <summary>Applies a ParentEvent (0xF749): the parent's instance gate (an unknown parent or child is waited for), then
    /// a child position stamp not newer is dropped; otherwise the child is attached to the parent at the holding location
    /// (<see cref="HoldingLocations"/>; <see cref="ServerMessageResult.NotApplicable"/> when the parent has no such
    /// location, the stamp taken, as retail).</summary>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    /// <exception cref="ArgumentException">The child is the parent or one of its ancestors (a parent cycle; nothing
    /// changes).</exception>
    // retail: SmartBox::HandleParentEvent (acclient.c:144511)
    public ServerMessageResult HandleParentEvent(ParentEventMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        ServerMessageResult gate = InstanceGate(message.ParentId, message.ParentInstanceTimestamp, out PhysicsObj parent);
        if (gate == ServerMessageResult.UnknownObject)
        {
            return gate;
        }

        PhysicsObj? child = World.GetObjectById(message.ChildId);
        if (child is null)
        {
            _queueFor = message.ChildId;
            return ServerMessageResult.UnknownObject;
        }

        if (gate != ServerMessageResult.Applied)
        {
            return gate;
        }

        ThrowIfCycle(child, parent);
        return DoParentEvent(child, parent, message.Location, message.ChildPositionTimestamp);
    }

    private static void ThrowIfCycle(PhysicsObj child, PhysicsObj parent)
    {
        for (PhysicsObj? p = parent; p is not null; p = p.Parent)
        {
            if (p == child)
            {
                throw new ArgumentException("The child is the parent or one of its ancestors (a parent cycle).", "message");
            }
        }
    }

    // retail: SmartBox::DoParentEvent (acclient.c:143503); set_parent(obj, where) (acclient.c:322951) through the
    // holding-location seam. The placement frame (SetPlacementFrame) and the weenie's notice are the client's.
    private ServerMessageResult DoParentEvent(PhysicsObj child, PhysicsObj parent, uint location, ushort positionTime)
    {
        if (!child.NewerEvent(PhysicsTimeStamp.Position, positionTime))
        {
            return ServerMessageResult.Stale;
        }

        return SetParent(child, parent, location) ? ServerMessageResult.Applied : ServerMessageResult.NotApplicable;
    }

    // retail: CPhysicsObj::set_parent (acclient.c:322951): add_child finds the location in the parent's Setup.
    private bool SetParent(PhysicsObj child, PhysicsObj parent, uint location)
    {
        if (HoldingLocations is null || !HoldingLocations(parent, location, out uint part, out Frame frame))
        {
            return false;
        }

        return child.SetParent(parent, part, frame);
    }

    /// <summary>Applies a PickupEvent (0xF74A): after the instance gate, a position stamp not newer is dropped; otherwise
    /// the object leaves its parent and the world (<see cref="PhysicsObj.LeaveWorld"/>).</summary>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    // retail: SmartBox::HandlePickupEvent (acclient.c:144472)
    public ServerMessageResult HandlePickupEvent(PickupEventMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        ServerMessageResult gate = InstanceGate(message.ObjectId, message.InstanceTimestamp, out PhysicsObj obj);
        return gate != ServerMessageResult.Applied ? gate : DoPickupEvent(obj, message.PositionTimestamp);
    }

    // retail: SmartBox::DoPickupEvent (acclient.c:143482)
    private static ServerMessageResult DoPickupEvent(PhysicsObj obj, ushort positionTime)
    {
        if (!obj.NewerEvent(PhysicsTimeStamp.Position, positionTime))
        {
            return ServerMessageResult.Stale;
        }

        obj.UnsetParent();
        obj.LeaveWorld();
        return ServerMessageResult.Applied;
    }

    /// <summary>Applies a DeleteObject (0xF747): never the player (<see cref="ServerMessageResult.NotApplicable"/>); an
    /// unknown object or a newer instance is waited for; an older instance is dropped; the object of that instance is
    /// removed from the world.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    // retail: SmartBox::HandleDeleteObject (acclient.c:143261)
    public ServerMessageResult HandleDeleteObject(DeleteObjectMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        if (message.ObjectId == PlayerId && PlayerId != 0)
        {
            return ServerMessageResult.NotApplicable;
        }

        ServerMessageResult gate = InstanceGate(message.ObjectId, message.InstanceTimestamp, out PhysicsObj obj);
        if (gate != ServerMessageResult.Applied)
        {
            return gate;
        }

        World.RemoveObject(obj);
        return ServerMessageResult.Applied;
    }

    /// <summary>Applies a MovementEvent (0xF74C) as retail's <c>ACSmartBox</c> does: the instance gate, then
    /// <see cref="PhysicsObj.HandleMovementEvent"/> (its stamps, the player's own echo); a movement applied to the player
    /// gives its control to the server (<see cref="IPlayerControl.LoseControlToServer"/>).</summary>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    /// <exception cref="ArgumentException">As <see cref="PhysicsObj.HandleMovementEvent"/> (nothing changes).</exception>
    // retail: ACSmartBox::DispatchSmartBoxEvent, case 0xF74C
    public ServerMessageResult HandleMovementEvent(MovementEventMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        ServerMessageResult gate = InstanceGate(message.ObjectId, message.InstanceTimestamp, out PhysicsObj obj);
        if (gate != ServerMessageResult.Applied)
        {
            return gate;
        }

        return MovementResult(obj, obj.HandleMovementEvent(message));
    }

    private ServerMessageResult MovementResult(PhysicsObj obj, MovementEventResult r)
    {
        switch (r)
        {
            case MovementEventResult.Applied:
                if (obj == Player)
                {
                    PlayerControl?.LoseControlToServer();
                }

                return ServerMessageResult.Applied;
            case MovementEventResult.OwnAutonomousEcho:
                return ServerMessageResult.PlayerOwnEcho;
            case MovementEventResult.Stale:
            case MovementEventResult.StaleServerControl:
                return ServerMessageResult.Stale;
            default:
                return ServerMessageResult.NotApplicable;
        }
    }
}
