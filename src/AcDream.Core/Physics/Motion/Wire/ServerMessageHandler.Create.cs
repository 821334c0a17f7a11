using System;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Motion.Wire;

// CreateObject (0xF745), its physics part: SmartBox::HandleCreateObject and CPhysicsObj::set_description.
public sealed partial class ServerMessageHandler
{
    /// <summary>
    /// Applies a CreateObject's physics description (0xF745) as retail's <c>SmartBox::HandleCreateObject</c> does. An
    /// unknown parent is waited for. An object this client does not hold (or holds as an older instance) is made by
    /// <see cref="ObjectFactory"/> from its Setup id and takes the description (state, movement buffer through the
    /// movement entry point, scale, friction, elasticity, translucency, velocity, omega, the nine stamps); it is attached
    /// to its parent, or the player is placed (and teleport-hooked) at its position, or another object enters the world
    /// at its position; then the messages kept for it are applied. An object held as this same instance is updated
    /// through the entry points the description's stamps gate: the parent event, the received position (with contact) or
    /// the pickup, the MovementEvent, SetState and VectorUpdate.
    /// </summary>
    /// <returns><see cref="ServerMessageResult.Applied"/>; <see cref="ServerMessageResult.UnknownObject"/> (parent not
    /// created); <see cref="ServerMessageResult.OldInstance"/>; <see cref="ServerMessageResult.NotApplicable"/> when the
    /// factory refused the object.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    /// <exception cref="ArgumentException">The position is outside the position domain, the scale outside
    /// [0.01, 100], or the parent is the object itself (nothing changes).</exception>
    /// <exception cref="Format.RetailDataFormatException">The movement buffer is not a MovementEvent's movement data
    /// (nothing changes).</exception>
    // retail: SmartBox::HandleCreateObject (acclient.c:145880), the physics side
    public ServerMessageResult HandleCreateObject(CreateObjectMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        PhysicsDesc d = message.Physics;
        CheckDescription(message.ObjectId, d);
        if (d.MovementBufferLength != 0)
        {
            MovementEventDecoder.DecodeMovementData(d.MovementBuffer, _createMovement);
        }

        PhysicsObj? parent = null;
        if (d.ParentId != 0)
        {
            parent = World.GetObjectById(d.ParentId);
            if (parent is null)
            {
                _queueFor = d.ParentId;
                return ServerMessageResult.UnknownObject;
            }
        }

        PhysicsObj? obj = World.GetObjectById(message.ObjectId);
        if (obj is not null && !IsNewer(obj.GetUpdateTime(PhysicsTimeStamp.Instance), d.GetTimestamp(PhysicsTimeStamp.Instance)))
        {
            return obj.GetUpdateTime(PhysicsTimeStamp.Instance) == d.GetTimestamp(PhysicsTimeStamp.Instance)
                ? UpdateObject(obj, parent, d)
                : ServerMessageResult.OldInstance;
        }

        // acclient.c:145930-145940: a newer instance replaces the object.
        if (obj is not null)
        {
            World.RemoveObject(obj);
        }

        obj = ObjectFactory is null ? World.CreateObject(message.ObjectId) : ObjectFactory(World, message.ObjectId, d);
        if (obj is null)
        {
            return ServerMessageResult.NotApplicable;
        }

        SetDescription(obj, d);
        if (parent is not null)
        {
            // non-retail: the object maintainer (not decompiled as such) attaches a created child; here as ParentEvent does
            SetParent(obj, parent, d.ParentLocation);
        }
        else if (obj.Id == PlayerId && PlayerId != 0)
        {
            // acclient.c:145957-145975: init_player, store_position, enter_world, PlayerPositionUpdated(teleporting).
            obj.StorePosition(d.Position);
            obj.EnterWorld(d.Position);
            PositionUpdateComplete = false;
            WaitingForTeleport = false;
            HasBeenTeleported = false;
            obj.TeleportHook();
            PlayerControl?.PlayerTeleported();
        }
        else if (d.Position.ObjCellId != 0)
        {
            obj.EnterWorld(d.Position);
        }

        ProcessObjectNetBlobs(obj.Id);
        return ServerMessageResult.Applied;
    }

    private static void CheckDescription(uint objectId, PhysicsDesc d)
    {
        if (d.Position.ObjCellId != 0)
        {
            InputLimits.ThrowIfOutside(d.Position, "message");
        }

        if (!InputLimits.IsScaleInDomain(d.Scale))
        {
            throw new ArgumentException("The description's scale must be in [0.01, 100].", "message");
        }

        if (d.ParentId != 0 && d.ParentId == objectId)
        {
            throw new ArgumentException("An object cannot be its own parent.", "message");
        }
    }

    // acclient.c:145976-146040: an object already held as this instance.
    private ServerMessageResult UpdateObject(PhysicsObj obj, PhysicsObj? parent, PhysicsDesc d)
    {
        ushort positionTime = d.GetTimestamp(PhysicsTimeStamp.Position);
        obj.NewerEvent(PhysicsTimeStamp.ObjDesc, d.GetTimestamp(PhysicsTimeStamp.ObjDesc)); // UpdateVisualDesc's gate
        if (parent is not null)
        {
            ThrowIfCycle(obj, parent);
            DoParentEvent(obj, parent, d.ParentLocation, positionTime);
        }
        else if (d.Position.ObjCellId != 0)
        {
            ReceivedPosition(obj, d.Position, true, positionTime, d.GetTimestamp(PhysicsTimeStamp.Teleport),
                d.GetTimestamp(PhysicsTimeStamp.ForcePosition));
        }
        else
        {
            DoPickupEvent(obj, positionTime);
        }

        if (d.MovementBufferLength != 0)
        {
            // CPhysics::SetObjectMovement with the description's stamps and autonomous flag.
            _createMovement.ObjectId = obj.Id;
            _createMovement.InstanceTimestamp = d.GetTimestamp(PhysicsTimeStamp.Instance);
            _createMovement.MovementTimestamp = d.GetTimestamp(PhysicsTimeStamp.Movement);
            _createMovement.ServerControlTimestamp = d.GetTimestamp(PhysicsTimeStamp.ServerControlledMove);
            _createMovement.Autonomous = d.AutonomousMovement;
            obj.HandleMovementEvent(_createMovement);
        }

        DoSetState(obj, d.State, d.GetTimestamp(PhysicsTimeStamp.State));
        DoVectorUpdate(obj, d.Velocity, d.Omega, d.GetTimestamp(PhysicsTimeStamp.Vector));
        return ServerMessageResult.Applied;
    }

    // retail: CPhysicsObj::set_description (acclient.c:322268), after the factory's motion table: the movement (unpacked
    // without stamps), state, scale, friction (only within [0, 1]), elasticity, translucency, velocity, omega and the
    // nine stamps. The sound and script tables and the default script are the client's.
    private void SetDescription(PhysicsObj obj, PhysicsDesc d)
    {
        if (d.MovementBufferLength != 0)
        {
            obj.LastMoveWasAutonomous = d.AutonomousMovement;
            _createMovement.ObjectId = obj.Id;
            if (obj.MakeMovementManager(true) is MovementManager mm)
            {
                MovementEvent.UnPack(mm, _createMovement);
            }
        }

        obj.SetState(d.State);
        obj.SetScaleStatic(d.Scale);
        if (d.Friction >= 0f && d.Friction <= 1f)
        {
            obj.Friction = d.Friction;
        }

        obj.Elasticity = d.Elasticity;
        obj.TranslucencyOriginal = d.Translucency;
        if (d.Translucency != 0f)
        {
            obj.SetTranslucencyInternal(d.Translucency);
        }

        obj.SetVelocity(d.Velocity);
        obj.SetOmega(d.Omega);
        for (int i = 0; i < 9; i++)
        {
            obj.SetUpdateTime((PhysicsTimeStamp)i, d.GetTimestamp((PhysicsTimeStamp)i));
        }
    }
}
