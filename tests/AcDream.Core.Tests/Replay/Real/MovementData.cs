using System;
using System.Buffers.Binary;

namespace AcDream.Core.Tests.Replay.Real;

/// <summary>The interpreted motion state a MovementEvent carries (retail <c>InterpretedMotionState</c>, as unpacked).</summary>
/// <param name="CurrentStyle">Stance command (default 0x8000003D NonCombat).</param>
/// <param name="ForwardCommand">Forward command (default 0x41000003 Ready).</param>
/// <param name="ForwardSpeed">Forward speed (default 1).</param>
/// <param name="SidestepCommand">Sidestep command (default 0).</param>
/// <param name="SidestepSpeed">Sidestep speed (default 1).</param>
/// <param name="TurnCommand">Turn command (default 0).</param>
/// <param name="TurnSpeed">Turn speed (default 1).</param>
/// <param name="ActionCount">Number of queued actions (each: command, 15-bit stamp, autonomous bit, speed).</param>
internal readonly record struct WireMotionState(
    uint CurrentStyle, uint ForwardCommand, float ForwardSpeed, uint SidestepCommand, float SidestepSpeed,
    uint TurnCommand, float TurnSpeed, int ActionCount);

/// <summary>
/// The movement data of one S2C 0xF74C MovementEvent, decoded as retail's <c>MovementManager::unpack_movement</c>
/// (acclient.c:339491) reads it: a u16 header (low byte = movement type, high byte = flags: bit 0 a sticky object id follows,
/// bit 1 standing long jump), a u16 style index, then per type: 0 = <c>InterpretedMotionState::UnPack</c>
/// (acclient.c:333444) and the optional sticky id; 6 = MoveToObject (object id, origin, 28 bytes of parameters, run rate);
/// 7 = MoveToPosition (origin, 28 bytes, run rate); 8 = TurnToObject (object id, heading, 12 bytes); 9 = TurnToHeading
/// (12 bytes) (<c>MovementParameters::UnPackNet</c>, acclient.c:346343; <c>Position::UnPackOrigin</c> = cell + 3 floats).
/// </summary>
internal sealed record MovementData(int MovementType, int Flags, uint Style, WireMotionState? Motion, uint StickyObject)
{
    /// <summary>Decodes <paramref name="data"/>; throws <see cref="FormatException"/> unless it parses to exactly its length.</summary>
    public static MovementData Decode(ReadOnlySpan<byte> data)
    {
        var r = new Reader(data);
        ushort header = r.U16();
        int type = header & 0xFF;
        int flags = header >> 8;
        uint style = CommandIds.FromIndex(r.U16());
        WireMotionState? motion = null;
        uint sticky = 0;
        switch (type)
        {
            case 0:
                motion = ReadInterpretedState(ref r);
                if ((flags & 1) != 0)
                {
                    sticky = r.U32();
                }

                break;
            case 6:
                sticky = r.U32();
                r.Skip(16 + 28 + 4);
                break;
            case 7:
                r.Skip(16 + 28 + 4);
                break;
            case 8:
                sticky = r.U32();
                r.Skip(4 + 12);
                break;
            case 9:
                r.Skip(12);
                break;
            default:
                throw new FormatException($"Movement type {type} is not one unpack_movement reads.");
        }

        if (r.Offset != data.Length)
        {
            throw new FormatException($"Movement data of {data.Length} bytes parsed to {r.Offset}.");
        }

        return new MovementData(type, flags, style, motion, sticky);
    }

    // InterpretedMotionState::UnPack (acclient.c:333444): a u32 of flags (bits 0-6) and action count (bits 7-11), the
    // commands present (style 0x1, forward 0x2, sidestep 0x8, turn 0x20) as u16 indices, then the speeds present
    // (forward 0x4, sidestep 0x10, turn 0x40) as floats, then the actions (u16 command, u16 stamp|autonomous<<15, f32 speed),
    // then padding to a 4-byte boundary.
    private static WireMotionState ReadInterpretedState(ref Reader r)
    {
        uint bits = r.U32();
        uint style = (bits & 0x1) != 0 ? CommandIds.FromIndex(r.U16()) : 0x8000003Du;
        uint forward = (bits & 0x2) != 0 ? CommandIds.FromIndex(r.U16()) : 0x41000003u;
        uint sidestep = (bits & 0x8) != 0 ? CommandIds.FromIndex(r.U16()) : 0u;
        uint turn = (bits & 0x20) != 0 ? CommandIds.FromIndex(r.U16()) : 0u;
        float forwardSpeed = (bits & 0x4) != 0 ? r.F32() : 1f;
        float sidestepSpeed = (bits & 0x10) != 0 ? r.F32() : 1f;
        float turnSpeed = (bits & 0x40) != 0 ? r.F32() : 1f;
        int actions = (int)((bits >> 7) & 0x1F);
        for (int i = 0; i < actions; i++)
        {
            CommandIds.FromIndex(r.U16());
            r.U16();
            r.F32();
        }

        r.Align4();
        return new WireMotionState(style, forward, forwardSpeed, sidestep, sidestepSpeed, turn, turnSpeed, actions);
    }

    private ref struct Reader(ReadOnlySpan<byte> data)
    {
        private readonly ReadOnlySpan<byte> _data = data;

        public int Offset { get; private set; }

        public ushort U16()
        {
            ushort v = BinaryPrimitives.ReadUInt16LittleEndian(Take(2));
            return v;
        }

        public uint U32() => BinaryPrimitives.ReadUInt32LittleEndian(Take(4));

        public float F32() => BinaryPrimitives.ReadSingleLittleEndian(Take(4));

        public void Skip(int n) => Take(n);

        public void Align4()
        {
            int pad = (4 - (Offset % 4)) % 4;
            Take(pad);
        }

        private ReadOnlySpan<byte> Take(int n)
        {
            if (Offset + n > _data.Length)
            {
                throw new FormatException($"Movement data of {_data.Length} bytes ends inside a field at {Offset}.");
            }

            ReadOnlySpan<byte> s = _data.Slice(Offset, n);
            Offset += n;
            return s;
        }
    }
}
