namespace AcDream.Core.Physics.Motion.Wire;

/// <summary>The opcodes of the server messages the physics reads (the first <c>u32</c> of each message; a body is the bytes
/// after it). <see cref="ServerMessageHandler.HandleMessage"/> takes the opcode and the body.</summary>
public enum PhysicsMessageOpcode : uint
{
    /// <summary>0xF745 CreateObject: an object's visual, physics and weenie descriptions (the physics reads its
    /// <see cref="PhysicsDesc"/>).</summary>
    CreateObject = 0xF745,

    /// <summary>0xF747 DeleteObject: the object and its instance stamp.</summary>
    DeleteObject = 0xF747,

    /// <summary>0xF748 UpdatePosition: the object and a position pack (<see cref="UpdatePositionMessage"/>).</summary>
    UpdatePosition = 0xF748,

    /// <summary>0xF749 ParentEvent: an object is attached to another (<see cref="ParentEventMessage"/>).</summary>
    ParentEvent = 0xF749,

    /// <summary>0xF74A PickupEvent: an object leaves the world (picked up; <see cref="PickupEventMessage"/>).</summary>
    PickupEvent = 0xF74A,

    /// <summary>0xF74B SetState: an object's physics state bits (<see cref="SetStateMessage"/>).</summary>
    SetState = 0xF74B,

    /// <summary>0xF74C MovementEvent (<see cref="MovementEventMessage"/>).</summary>
    MovementEvent = 0xF74C,

    /// <summary>0xF74E VectorUpdate: an object's velocity and omega (a remote's jump; <see cref="VectorUpdateMessage"/>).</summary>
    VectorUpdate = 0xF74E,

    /// <summary>0xF751 PlayerTeleport: the player is being teleported (<see cref="PlayerTeleportMessage"/>).</summary>
    PlayerTeleport = 0xF751,
}
