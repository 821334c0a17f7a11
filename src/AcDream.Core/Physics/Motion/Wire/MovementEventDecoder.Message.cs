using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Motion.Wire;

public static partial class MovementEventDecoder
{
    /// <summary>Bytes of a MovementEvent body before its movement data: guid, instance, movement and server-control stamps,
    /// the autonomous byte and one pad byte (12).</summary>
    public const int BodyHeaderLength = 12;

    /// <summary>
    /// Decodes a whole MovementEvent body — the message's bytes after its 0xF74C opcode: <c>u32</c> object id, <c>u16</c>
    /// instance, movement and server-control stamps, <c>u8</c> autonomous, padding to 4 bytes, then the movement data
    /// (<see cref="DecodeMovementData"/>) — into <paramref name="message"/>, every field of it.
    /// </summary>
    /// <param name="body">The bytes after the opcode; must be consumed exactly.</param>
    /// <param name="message">Receives the event (reused: every field is rewritten).</param>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    /// <exception cref="RetailDataFormatException">The bytes are not a MovementEvent: too short for a field (naming it and
    /// its offset), an unknown movement type or motion command index, a NaN or infinite number, or bytes left over.
    /// Nothing is applied to any object; <paramref name="message"/> is then unspecified.</exception>
    // retail: CPhysics::SetObjectMovement (acclient.c:311220), the stamps and the autonomous byte, then the movement data
    public static void Decode(ReadOnlySpan<byte> body, MovementEventMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        var r = new RetailDataReader(body, "MovementEvent");
        message.ObjectId = r.ReadUInt32("object id");
        message.InstanceTimestamp = r.ReadUInt16("instance stamp");
        message.MovementTimestamp = r.ReadUInt16("movement stamp");
        message.ServerControlTimestamp = r.ReadUInt16("server-control stamp");
        message.Autonomous = r.ReadByte("autonomous") != 0;
        r.Align4();
        ReadMovementData(ref r, message);
    }

    /// <summary>
    /// Decodes the movement data of a MovementEvent (the bytes from offset 16 of the message, 4-byte aligned) into
    /// <paramref name="message"/>'s movement fields (type, style, flags and the type's fields; the object id, stamps and
    /// autonomous flag are left as they are): <c>u8</c> type, <c>u8</c> motion flags (0x01 sticky, 0x02 standing long
    /// jump), <c>u16</c> style index, then for type 0 an interpreted motion state and the sticky object when flagged; type 6
    /// the target, the origin (cell, x, y, z), the move-to parameters (flags, distance to object, min distance, fail
    /// distance, speed, walk/run threshold, desired heading) and the run rate; type 7 the same without the target; type 8
    /// the target, a heading and the turn-to parameters (flags, speed, desired heading); type 9 the turn-to parameters.
    /// </summary>
    /// <param name="data">The movement data; must be consumed exactly.</param>
    /// <param name="message">Receives the movement fields.</param>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    /// <exception cref="RetailDataFormatException">As <see cref="Decode"/>.</exception>
    // retail: MovementManager::unpack_movement (acclient.c:339491), the reads
    public static void DecodeMovementData(ReadOnlySpan<byte> data, MovementEventMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        var r = new RetailDataReader(data, "MovementEvent data");
        ReadMovementData(ref r, message);
    }

    private static void ReadMovementData(ref RetailDataReader r, MovementEventMessage m)
    {
        int typeAt = r.Offset;
        byte type = r.ReadByte("movement type");
        byte flags = r.ReadByte("motion flags");
        m.Style = ReadCommand(ref r, "style");
        m.StickToObject = 0;
        m.StandingLongJump = false;
        m.TargetId = 0;
        m.Origin = new Position(0, Frame.Identity);
        m.Parameters = new MovementParameters();
        m.RunRate = 1f;
        m.TurnToObjectHeading = 0f;
        m.State.Reset();
        switch (type)
        {
            case 0:
                m.MovementType = MovementEventType.InterpretedMotion;
                UnPackInterpretedState(ref r, m.State);
                if ((flags & 0x01) != 0)
                {
                    m.StickToObject = r.ReadUInt32("sticky object");
                }

                m.StandingLongJump = (flags & 0x02) != 0;
                break;
            case 6:
            case 7:
                m.MovementType = (MovementEventType)type;
                if (type == 6)
                {
                    m.TargetId = r.ReadUInt32("target object");
                }

                m.Origin = UnPackOrigin(ref r);
                m.Parameters = UnPackNet(ref r, (MovementEventType)type);
                m.RunRate = ReadRunRate(ref r);
                break;
            case 8:
                m.MovementType = MovementEventType.TurnToObject;
                m.TargetId = r.ReadUInt32("target object");
                m.TurnToObjectHeading = r.ReadFiniteSingle("heading");
                m.Parameters = UnPackNet(ref r, MovementEventType.TurnToObject);
                break;
            case 9:
                m.MovementType = MovementEventType.TurnToHeading;
                m.Parameters = UnPackNet(ref r, MovementEventType.TurnToHeading);
                break;
            default:
                throw r.ErrorAt(typeAt, $"movement type {type} is not 0, 6, 7, 8 or 9");
        }

        if (r.Remaining != 0)
        {
            throw r.Error($"{r.Remaining} bytes after the movement data");
        }
    }

    // retail: Position::UnPackOrigin (acclient.c:467193): the cell and the origin; the rotation stays the identity
    private static Position UnPackOrigin(ref RetailDataReader r)
    {
        uint cell = r.ReadUInt32("origin cell");
        float x = r.ReadFiniteSingle("origin x");
        float y = r.ReadFiniteSingle("origin y");
        float z = r.ReadFiniteSingle("origin z");
        return new Position(cell, new Vector3(x, y, z));
    }

    // The move-to (types 6, 7) or turn-to (8, 9) parameters as the network sends them (MovementParameters::UnPackNet); the
    // fields not sent keep retail's defaults.
    private static MovementParameters UnPackNet(ref RetailDataReader r, MovementEventType type)
    {
        var p = new MovementParameters();
        p.UnPackNet(ref r, (MovementType)type);
        return p;
    }
}
