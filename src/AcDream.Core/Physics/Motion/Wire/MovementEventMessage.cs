using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Motion.Wire;

/// <summary>
/// One server MovementEvent (message 0xF74C) decoded from its bytes by <see cref="MovementEventDecoder.Decode"/>: the object,
/// its three 16-bit stamps, the autonomous flag and the movement data (retail's <c>CPhysics::SetObjectMovement</c> and
/// <c>MovementManager::unpack_movement</c> read the same fields). <see cref="Objects.PhysicsObj.HandleMovementEvent"/> applies
/// it. Reusable: decode every event into one instance (nothing is allocated per event after the first).
/// </summary>
public sealed class MovementEventMessage
{
    /// <summary>The object the event is for (retail: the guid the SmartBox looks the object up by).</summary>
    public uint ObjectId { get; set; }

    /// <summary>The object's 16-bit instance stamp (the SmartBox compares it with the object's; the physics does not).</summary>
    public ushort InstanceTimestamp { get; set; }

    /// <summary>The 16-bit movement stamp (retail MOVEMENT_TS): an event not newer than the last one applied is dropped.</summary>
    public ushort MovementTimestamp { get; set; }

    /// <summary>The 16-bit server-control stamp (retail SERVER_CONTROLLED_MOVE_TS): an event older than the last one is
    /// dropped.</summary>
    public ushort ServerControlTimestamp { get; set; }

    /// <summary>The motion was started by the object's own client (the server's echo of a player's own command).</summary>
    public bool Autonomous { get; set; }

    /// <summary>The kind of movement.</summary>
    public MovementEventType MovementType { get; set; }

    /// <summary>The style the object is to be in (the header's, which <c>unpack_movement</c> switches to first).</summary>
    public MotionCommand Style { get; set; } = MotionCommand.NonCombat;

    /// <summary>Type 0: the object to stick to (0: none; motion flag 0x01).</summary>
    public uint StickToObject { get; set; }

    /// <summary>Type 0: the object is charging a standing long jump (motion flag 0x02).</summary>
    public bool StandingLongJump { get; set; }

    /// <summary>Type 0: the interpreted motion state.</summary>
    public InterpretedMotionState State { get; } = new();

    /// <summary>Types 6 and 8: the target object.</summary>
    public uint TargetId { get; set; }

    /// <summary>Types 6 and 7: the position to move to (type 6: the target's position when the event was sent; used when
    /// the client does not know the target). The rotation is the identity (retail <c>Position::UnPackOrigin</c>).</summary>
    public Position Origin { get; set; } = new(0, Frame.Identity);

    /// <summary>Types 6-9: the move-to or turn-to parameters (retail <c>MovementParameters::UnPackNet</c>: types 6 and 7
    /// carry flags, distance to object, min distance, fail distance, speed, walk/run threshold and desired heading; 8 and 9
    /// flags, speed and desired heading; the other fields keep retail's defaults).</summary>
    public MovementParameters Parameters { get; set; } = new();

    /// <summary>Types 6 and 7: the object's run rate (retail <c>my_run_rate</c>).</summary>
    public float RunRate { get; set; } = 1f;

    /// <summary>Type 8: the heading, degrees, to turn to when the client does not know the target.</summary>
    public float TurnToObjectHeading { get; set; }

    /// <summary>Puts every field back to its default (a type-0 event in the non-combat style with the default state).</summary>
    public void Reset()
    {
        ObjectId = 0;
        InstanceTimestamp = 0;
        MovementTimestamp = 0;
        ServerControlTimestamp = 0;
        Autonomous = false;
        MovementType = MovementEventType.InterpretedMotion;
        Style = MotionCommand.NonCombat;
        StickToObject = 0;
        StandingLongJump = false;
        State.Reset();
        TargetId = 0;
        Origin = new Position(0, Frame.Identity);
        Parameters = new MovementParameters();
        RunRate = 1f;
        TurnToObjectHeading = 0f;
    }
}
