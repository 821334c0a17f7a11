using System;
using System.Buffers.Binary;

namespace AcDream.Core.Physics.Motion;

/// <summary>The header of a MovementEvent's movement data (retail <c>MovementManager::unpack_movement</c>).</summary>
/// <param name="MovementType">0 = an interpreted motion state; 6..9 = move-to and turn-to (not decoded here).</param>
/// <param name="Style">The style the object is in (full command).</param>
/// <param name="StickToObject">The object to stick to (0 when none).</param>
/// <param name="StandingLongJump">The object is charging a standing long jump.</param>
public readonly record struct MovementEventHeader(byte MovementType, MotionCommand Style, uint StickToObject, bool StandingLongJump)
{
    // Commands print by name (an unnamed one as its hex id), object ids in hex.
    private bool PrintMembers(System.Text.StringBuilder builder)
    {
        builder.Append("MovementType = ").Append(MovementType)
               .Append(", Style = ").Append(MotionCommandText.Format(Style))
               .Append(", StickToObject = 0x").Append(StickToObject.ToString("X8", System.Globalization.CultureInfo.InvariantCulture))
               .Append(", StandingLongJump = ").Append(StandingLongJump);
        return true;
    }
}

/// <summary>
/// Decodes the movement data of a MovementEvent (0xF74C) of movement type 0 (retail <c>MovementManager::unpack_movement</c>
/// and <c>InterpretedMotionState::UnPack</c>). The bytes are those after the message's header (guid, the three 16-bit
/// sequences, the autonomous byte and its pad), which start 4-byte aligned.
/// </summary>
public static class MovementEventDecoder
{
    /// <summary>
    /// Decodes <paramref name="data"/> into <paramref name="state"/>: true only for movement type 0 read to exactly the
    /// data's length; false (and <paramref name="state"/> unspecified) for another type, an unknown command index, a short
    /// buffer or trailing bytes.
    /// </summary>
    /// <exception cref="ArgumentNullException"><paramref name="state"/> is null.</exception>
    // retail: MovementManager::unpack_movement (acclient.c:339491), the header and case 0
    public static bool TryDecode(ReadOnlySpan<byte> data, InterpretedMotionState state, out MovementEventHeader header)
    {
        ArgumentNullException.ThrowIfNull(state);
        header = default;
        if (data.Length < 4)
        {
            return false;
        }

        ushort word = BinaryPrimitives.ReadUInt16LittleEndian(data);
        ushort styleIndex = BinaryPrimitives.ReadUInt16LittleEndian(data[2..]);
        if (!MotionCommandIds.TryGet(styleIndex, out MotionCommand style))
        {
            return false;
        }

        byte type = (byte)word;
        header = new MovementEventHeader(type, style, 0, (word & 0x200) != 0);
        if (type != 0)
        {
            return false;
        }

        int offset = 4;
        if (!TryUnpackInterpretedState(data, ref offset, state))
        {
            return false;
        }

        uint stick = 0;
        if ((word & 0x100) != 0)
        {
            if (offset + 4 > data.Length)
            {
                return false;
            }

            stick = BinaryPrimitives.ReadUInt32LittleEndian(data[offset..]);
            offset += 4;
        }

        header = header with { StickToObject = stick };
        return offset == data.Length;
    }

    /// <summary>Reads an interpreted motion state at <paramref name="offset"/>: a flag word, then the style, forward,
    /// side-step and turn command indices (flags 0x1, 0x2, 0x8, 0x20), the forward, side-step and turn speeds (0x4, 0x10,
    /// 0x40), (flags >> 7) &amp; 31 actions (index, 15-bit stamp with the autonomous bit, speed), then padding to 4 bytes.
    /// Absent fields take the defaults.</summary>
    // retail: InterpretedMotionState::UnPack (acclient.c:333444)
    public static bool TryUnpackInterpretedState(ReadOnlySpan<byte> data, ref int offset, InterpretedMotionState state)
    {
        ArgumentNullException.ThrowIfNull(state);
        state.Reset();
        if (offset + 4 > data.Length)
        {
            return false;
        }

        uint flags = BinaryPrimitives.ReadUInt32LittleEndian(data[offset..]);
        offset += 4;
        MotionCommand cmd;
        if ((flags & 0x1) != 0)
        {
            if (!ReadCommand(data, ref offset, out cmd))
            {
                return false;
            }

            state.CurrentStyle = cmd;
        }

        if ((flags & 0x2) != 0)
        {
            if (!ReadCommand(data, ref offset, out cmd))
            {
                return false;
            }

            state.ForwardCommand = cmd;
        }

        if ((flags & 0x8) != 0)
        {
            if (!ReadCommand(data, ref offset, out cmd))
            {
                return false;
            }

            state.SidestepCommand = cmd;
        }

        if ((flags & 0x20) != 0)
        {
            if (!ReadCommand(data, ref offset, out cmd))
            {
                return false;
            }

            state.TurnCommand = cmd;
        }

        float speed;
        if ((flags & 0x4) != 0)
        {
            if (!ReadFloat(data, ref offset, out speed))
            {
                return false;
            }

            state.ForwardSpeed = speed;
        }

        if ((flags & 0x10) != 0)
        {
            if (!ReadFloat(data, ref offset, out speed))
            {
                return false;
            }

            state.SidestepSpeed = speed;
        }

        if ((flags & 0x40) != 0)
        {
            if (!ReadFloat(data, ref offset, out speed))
            {
                return false;
            }

            state.TurnSpeed = speed;
        }

        int actions = (int)((flags >> 7) & 0x1F);
        for (int i = 0; i < actions; i++)
        {
            if (!ReadCommand(data, ref offset, out cmd) || offset + 6 > data.Length)
            {
                return false;
            }

            ushort stamp = BinaryPrimitives.ReadUInt16LittleEndian(data[offset..]);
            offset += 2;
            ReadFloat(data, ref offset, out speed);
            state.AddAction(cmd, speed, stamp & 0x7FFFu, ((stamp >> 15) & 1) != 0);
        }

        int pad = offset % 4;
        if (pad != 0)
        {
            offset += 4 - pad;
        }

        return offset <= data.Length;
    }

    private static bool ReadCommand(ReadOnlySpan<byte> data, ref int offset, out MotionCommand command)
    {
        command = MotionCommand.None;
        if (offset + 2 > data.Length)
        {
            return false;
        }

        ushort index = BinaryPrimitives.ReadUInt16LittleEndian(data[offset..]);
        offset += 2;
        return MotionCommandIds.TryGet(index, out command);
    }

    private static bool ReadFloat(ReadOnlySpan<byte> data, ref int offset, out float value)
    {
        value = 0f;
        if (offset + 4 > data.Length)
        {
            return false;
        }

        value = BinaryPrimitives.ReadSingleLittleEndian(data[offset..]);
        offset += 4;
        return true;
    }
}
