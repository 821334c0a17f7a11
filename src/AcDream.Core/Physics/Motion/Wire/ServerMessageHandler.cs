using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Motion.Wire;

/// <summary>Makes the object of a CreateObject (the object-from-data door: its Setup, motion table and weenie from
/// <see cref="PhysicsDesc.SetupId"/> and <see cref="PhysicsDesc.MotionTableId"/>). Return null to refuse the object.</summary>
/// <param name="world">The world to create it in.</param>
/// <param name="objectId">The object's id.</param>
/// <param name="desc">Its physics description (the handler applies the rest after the factory returns).</param>
public delegate PhysicsObj? PhysicsObjectFactory(PhysicsWorld world, uint objectId, PhysicsDesc desc);

/// <summary>Finds a parent's holding location (retail <c>CPhysicsObj::add_child</c> reads it from the parent's Setup): the
/// part the child hangs from and its frame relative to that part.</summary>
/// <returns>False when the parent has no such location (the child is not attached, as retail).</returns>
public delegate bool HoldingLocationResolver(PhysicsObj parent, uint location, out uint partIndex, out Frame frame);

/// <summary>
/// The server's physics messages applied to a world as retail's <c>SmartBox</c> applies them: each message's retail entry
/// point with its timestamp gates (<c>CPhysicsObj::newer_event</c> over the instance, position, teleport, force-position,
/// state, vector, movement and server-control stamps, 16-bit wrap-around), the player's own echoes, blips and teleports,
/// and the queue of messages for objects not created yet (<c>QueueBlobForObject</c> / <c>ProcessObjectNetBlobs</c>).
/// </summary>
/// <remarks><para>A client passes every physics message to <see cref="HandleMessage"/> (its opcode and body); or decodes
/// with <see cref="PhysicsMessageDecoder"/> / <see cref="MovementEventDecoder"/> itself and calls the typed entry points,
/// which keep nothing (they answer <see cref="ServerMessageResult.UnknownObject"/> where the byte path queues).</para>
/// <para>Decoding and applying allocate nothing once warm; queueing a message copies its body.</para></remarks>
public sealed partial class ServerMessageHandler
{
    private readonly Dictionary<uint, List<QueuedBlob>> _queued = [];
    private readonly UpdatePositionMessage _position = new();
    private readonly VectorUpdateMessage _vector = new();
    private readonly SetStateMessage _state = new();
    private readonly ParentEventMessage _parent = new();
    private readonly PickupEventMessage _pickup = new();
    private readonly PlayerTeleportMessage _teleport = new();
    private readonly DeleteObjectMessage _delete = new();
    private readonly MovementEventMessage _movement = new();
    private readonly CreateObjectMessage _create = new();
    private readonly MovementEventMessage _createMovement = new();
    private uint _queueFor;

    /// <summary>Creates a handler for <paramref name="world"/>.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="world"/> is null.</exception>
    public ServerMessageHandler(PhysicsWorld world)
    {
        ArgumentNullException.ThrowIfNull(world);
        World = world;
    }

    /// <summary>The world the messages apply to.</summary>
    public PhysicsWorld World { get; }

    /// <summary>The id of this client's player (retail <c>player_id</c>, set by the server's CreatePlayer); 0 before.</summary>
    public uint PlayerId { get; set; }

    /// <summary>The player's object, or null before its CreateObject (retail <c>SmartBox::player</c>).</summary>
    public PhysicsObj? Player => PlayerId == 0 ? null : World.GetObjectById(PlayerId);

    /// <summary>The player's command interpreter (<see cref="Input.PlayerInput"/> or a client's own); null: the player
    /// follows every server position and vector (as <see cref="IPlayerControl.UsePositionFromServer"/> true).</summary>
    public IPlayerControl? PlayerControl { get; set; }

    /// <summary>The object-from-data door: makes a CreateObject's object from its Setup id. Null: a bare
    /// <see cref="PhysicsWorld.CreateObject"/> (no part array, no motion table).</summary>
    public PhysicsObjectFactory? ObjectFactory { get; set; }

    /// <summary>The parents' holding locations (ParentEvent, and a CreateObject with a parent). Null: no object has any,
    /// and a parent event attaches nothing.</summary>
    public HoldingLocationResolver? HoldingLocations { get; set; }

    /// <summary>The player is being teleported: a PlayerTeleport arrived and the player is still hidden (retail
    /// <c>waiting_for_teleport</c>).</summary>
    public bool WaitingForTeleport { get; private set; }

    /// <summary>Retail <c>position_update_complete</c>: set by <see cref="UseTime"/> once no teleport is pending.</summary>
    public bool PositionUpdateComplete { get; private set; }

    /// <summary>Retail <c>has_been_teleported</c>: set with <see cref="PositionUpdateComplete"/>; cleared by a teleport.</summary>
    public bool HasBeenTeleported { get; private set; }

    /// <summary>The last UpdatePosition's outcome for a remote object (what <see cref="PhysicsObj.HandleReceivedPosition"/>
    /// answered: interpolating, placed, no contact, ...).</summary>
    public ReceivedPositionResult LastReceivedPosition { get; private set; }

    /// <summary>Number of messages kept for objects not created yet.</summary>
    public int QueuedMessageCount
    {
        get
        {
            int n = 0;
            foreach (List<QueuedBlob> list in _queued.Values)
            {
                n += list.Count;
            }

            return n;
        }
    }

    /// <summary>The teleport bookkeeping of retail's frame: once the player exists and no teleport is pending, the
    /// position update is complete. Call once per frame (before or after the world's tick).</summary>
    // retail: SmartBox::UseTime (acclient.c:146255), its player lines
    public void UseTime()
    {
        if (Player is not null && !WaitingForTeleport && !PositionUpdateComplete)
        {
            PositionUpdateComplete = true;
            HasBeenTeleported = true;
        }
    }

    /// <summary>
    /// Decodes and applies one server message: <paramref name="opcode"/> and its body (the bytes after the opcode). A
    /// message for an object not yet created (or for a newer instance of it) is copied and kept, and applied after that
    /// object's CreateObject (<see cref="ServerMessageResult.Queued"/>).
    /// </summary>
    /// <returns>What happened; <see cref="ServerMessageResult.NotApplicable"/> for an opcode the physics does not read.</returns>
    /// <exception cref="Format.RetailDataFormatException">The body is not a message of that opcode (nothing changed).</exception>
    /// <exception cref="ArgumentException">A decoded value is outside the library's domain (a position, a scale),
    /// or the entry point refuses the message (nothing changed).</exception>
    // retail: ACSmartBox::DispatchSmartBoxEvent (the physics opcodes) and the CM_Physics::DispatchSB_* it calls
    public ServerMessageResult HandleMessage(uint opcode, ReadOnlySpan<byte> body)
    {
        ServerMessageResult r;
        _queueFor = 0;
        switch ((PhysicsMessageOpcode)opcode)
        {
            case PhysicsMessageOpcode.UpdatePosition:
                PhysicsMessageDecoder.Decode(body, _position);
                r = HandleUpdatePosition(_position);
                break;
            case PhysicsMessageOpcode.VectorUpdate:
                PhysicsMessageDecoder.Decode(body, _vector);
                r = HandleVectorUpdate(_vector);
                break;
            case PhysicsMessageOpcode.SetState:
                PhysicsMessageDecoder.Decode(body, _state);
                r = HandleSetState(_state);
                break;
            case PhysicsMessageOpcode.ParentEvent:
                PhysicsMessageDecoder.Decode(body, _parent);
                r = HandleParentEvent(_parent);
                break;
            case PhysicsMessageOpcode.PickupEvent:
                PhysicsMessageDecoder.Decode(body, _pickup);
                r = HandlePickupEvent(_pickup);
                break;
            case PhysicsMessageOpcode.PlayerTeleport:
                PhysicsMessageDecoder.Decode(body, _teleport);
                r = HandlePlayerTeleport(_teleport);
                break;
            case PhysicsMessageOpcode.DeleteObject:
                PhysicsMessageDecoder.Decode(body, _delete);
                r = HandleDeleteObject(_delete);
                break;
            case PhysicsMessageOpcode.MovementEvent:
                MovementEventDecoder.Decode(body, _movement);
                r = HandleMovementEvent(_movement);
                break;
            case PhysicsMessageOpcode.CreateObject:
                PhysicsMessageDecoder.Decode(body, _create);
                r = HandleCreateObject(_create);
                break;
            default:
                return ServerMessageResult.NotApplicable;
        }

        if (r != ServerMessageResult.UnknownObject)
        {
            return r;
        }

        // retail: CObjectMaint::QueueBlobForObject: the message waits for its object's creation.
        if (!_queued.TryGetValue(_queueFor, out List<QueuedBlob>? list))
        {
            list = [];
            _queued.Add(_queueFor, list);
        }

        list.Add(new QueuedBlob(opcode, body.ToArray()));
        return ServerMessageResult.Queued;
    }

    /// <summary>Drops every kept message (retail <c>SmartBox::DestroyQueuedNetBlobs</c>, at a reset).</summary>
    public void ClearQueuedMessages() => _queued.Clear();

    // retail: SmartBox::ProcessObjectNetBlobs (acclient.c:145766): the object's kept messages, in arrival order.
    private void ProcessObjectNetBlobs(uint objectId)
    {
        if (!_queued.Remove(objectId, out List<QueuedBlob>? list))
        {
            return;
        }

        foreach (QueuedBlob blob in list)
        {
            HandleMessage(blob.Opcode, blob.Body);
        }
    }

    // The SmartBox handlers' instance test (e.g. HandleSetState, acclient.c:144394): no object, or a message for a newer
    // instance, is kept for later (4); an older instance is dropped (2); the same instance is applied.
    private ServerMessageResult InstanceGate(uint objectId, ushort instance, out PhysicsObj obj)
    {
        PhysicsObj? o = World.GetObjectById(objectId);
        obj = o!;
        if (o is null || o.IsRemoved)
        {
            _queueFor = objectId;
            return ServerMessageResult.UnknownObject;
        }

        ushort have = o.GetUpdateTime(PhysicsTimeStamp.Instance);
        if (IsNewer(have, instance))
        {
            _queueFor = objectId;
            return ServerMessageResult.UnknownObject;
        }

        return have == instance ? ServerMessageResult.Applied : ServerMessageResult.OldInstance;
    }

    // retail: CPhysicsObj::is_newer (and newer_event's comparison): newTime after oldTime in 16-bit wrap-around order.
    internal static bool IsNewer(ushort oldTime, ushort newTime) =>
        Math.Abs(newTime - oldTime) > 0x7FFF ? newTime < oldTime : oldTime < newTime;

    private bool UsePositionFromServer => PlayerControl?.UsePositionFromServer ?? true;

    private readonly record struct QueuedBlob(uint Opcode, byte[] Body);
}
