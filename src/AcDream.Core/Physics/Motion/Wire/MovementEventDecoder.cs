using System;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Motion.Wire;

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
/// Decodes MovementEvents (message 0xF74C) from their bytes: the whole body (<see cref="Decode"/>, every movement type,
/// into a reusable <see cref="MovementEventMessage"/>), the movement data alone (<see cref="DecodeMovementData"/>), or the
/// type-0 data into an interpreted state (<see cref="TryDecode"/>). Retail reads the same fields in
/// <c>CPhysics::SetObjectMovement</c> (the stamps), <c>MovementManager::unpack_movement</c> (the header and each type),
/// <c>InterpretedMotionState::UnPack</c>, <c>Position::UnPackOrigin</c> and <c>MovementParameters::UnPackNet</c>; this is
/// the wire side only, and applies nothing (<see cref="Objects.PhysicsObj.HandleMovementEvent"/> does).
/// </summary>
public static partial class MovementEventDecoder
{
    /// <summary>
    /// Decodes the movement data of a type-0 event into <paramref name="state"/>: true only for movement type 0 read to
    /// exactly the data's length; false (and <paramref name="state"/> unspecified) for another type, an unknown command
    /// index, a NaN or infinite speed, a short buffer or trailing bytes. The bytes are those after the message's header
    /// (guid, the three 16-bit sequences, the autonomous byte and its pad), which start 4-byte aligned.
    /// </summary>
    /// <exception cref="ArgumentNullException"><paramref name="state"/> is null.</exception>
    // retail: MovementManager::unpack_movement (acclient.c:339491), the header and case 0
    public static bool TryDecode(ReadOnlySpan<byte> data, InterpretedMotionState state, out MovementEventHeader header)
    {
        ArgumentNullException.ThrowIfNull(state);
        header = default;
        var r = new RetailDataReader(data, "MovementEvent");
        try
        {
            ushort word = r.ReadUInt16("movement type and flags");
            MotionCommand style = ReadCommand(ref r, "style");
            byte type = (byte)word;
            header = new MovementEventHeader(type, style, 0, (word & 0x200) != 0);
            if (type != 0)
            {
                return false;
            }

            UnPackInterpretedState(ref r, state);
            uint stick = (word & 0x100) != 0 ? r.ReadUInt32("sticky object") : 0u;
            header = header with { StickToObject = stick };
            return r.Remaining == 0;
        }
        catch (RetailDataFormatException)
        {
            return false;
        }
    }

    /// <summary>Reads an interpreted motion state at <paramref name="offset"/>: a flag word, then the style, forward,
    /// side-step and turn command indices (flags 0x1, 0x2, 0x8, 0x20), the forward, side-step and turn speeds (0x4, 0x10,
    /// 0x40), (flags >> 7) &amp; 31 actions (index, 15-bit stamp with the autonomous bit, speed), then padding to 4 bytes.
    /// Absent fields take the defaults. False (state unspecified) for a short buffer, an unknown command index, a speed
    /// that is NaN, infinite or beyond ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/>, or a RunForward whose speed is
    /// not a run rate in (0, <see cref="Spatial.InputLimits.MaxRunRate"/>].</summary>
    /// <exception cref="ArgumentNullException"><paramref name="state"/> is null.</exception>
    // retail: InterpretedMotionState::UnPack (acclient.c:333444)
    public static bool TryUnPackInterpretedState(ReadOnlySpan<byte> data, ref int offset, InterpretedMotionState state)
    {
        ArgumentNullException.ThrowIfNull(state);
        state.Reset();
        if (offset < 0 || offset > data.Length)
        {
            return false;
        }

        var r = new RetailDataReader(data, "InterpretedMotionState");
        try
        {
            r.Skip(offset);
            UnPackInterpretedState(ref r, state);
            offset = r.Offset;
            return true;
        }
        catch (RetailDataFormatException)
        {
            return false;
        }
    }

    // retail: InterpretedMotionState::UnPack (acclient.c:333444), through the bounds-checked reader
    internal static void UnPackInterpretedState(ref RetailDataReader r, InterpretedMotionState state)
    {
        state.Reset();
        int flagsAt = r.Offset;
        uint flags = r.ReadUInt32("InterpretedMotionState flags");
        if ((flags & 0x1) != 0)
        {
            state.CurrentStyle = ReadCommand(ref r, "current style");
        }

        if ((flags & 0x2) != 0)
        {
            state.ForwardCommand = ReadCommand(ref r, "forward command");
        }

        if ((flags & 0x8) != 0)
        {
            state.SidestepCommand = ReadCommand(ref r, "sidestep command");
        }

        if ((flags & 0x20) != 0)
        {
            state.TurnCommand = ReadCommand(ref r, "turn command");
        }

        if ((flags & 0x4) != 0)
        {
            state.ForwardSpeed = ReadSpeed(ref r, "forward speed");
        }

        if ((flags & 0x10) != 0)
        {
            state.SidestepSpeed = ReadSpeed(ref r, "sidestep speed");
        }

        if ((flags & 0x40) != 0)
        {
            state.TurnSpeed = ReadSpeed(ref r, "turn speed");
        }

        int actions = r.CheckCount((flags >> 7) & 0x1F, "actions", 8, flagsAt);
        for (int i = 0; i < actions; i++)
        {
            MotionCommand cmd = ReadCommand(ref r, "action");
            ushort stamp = r.ReadUInt16("action stamp");
            float speed = ReadSpeed(ref r, "action speed");
            state.AddAction(cmd, speed, stamp & 0x7FFFu, ((stamp >> 15) & 1) != 0);
        }

        // non-retail: a RunForward's speed is the interpreter's next run rate, in (0, MaxRunRate] (retail's server sends the
        // character's rate, about 1 to 4.5; at zero or below a standing object's state velocity is NaN)
        if (state.ForwardCommand == MotionCommand.RunForward && !MotionChecks.IsRunRateInDomain(state.ForwardSpeed))
        {
            throw r.Error($"a RunForward state's speed {state.ForwardSpeed} is not a run rate in (0, {Spatial.InputLimits.MaxRunRate}]");
        }

        r.Align4();
    }

    // non-retail: a run rate in (0, MaxRunRate] (retail stores any float as my_run_rate), else a format error
    private static float ReadRunRate(ref RetailDataReader r)
    {
        int at = r.Offset;
        float v = r.ReadFiniteSingle("run rate");
        if (!MotionChecks.IsRunRateInDomain(v))
        {
            throw r.ErrorAt(at, $"run rate {v} is not in (0, {Spatial.InputLimits.MaxRunRate}]");
        }

        return v;
    }

    // non-retail: a speed in the motion speeds' domain (InputLimits.MaxMotionSpeed), else a format error
    private static float ReadSpeed(ref RetailDataReader r, string what)
    {
        int at = r.Offset;
        float v = r.ReadFiniteSingle(what);
        if (!MotionChecks.IsSpeedInDomain(v))
        {
            throw r.ErrorAt(at, $"{what} {v} is beyond ±{Spatial.InputLimits.MaxMotionSpeed}");
        }

        return v;
    }

    // A 16-bit command index, through retail's command_ids table; an index past it is a format error.
    private static MotionCommand ReadCommand(ref RetailDataReader r, string what)
    {
        int at = r.Offset;
        ushort index = r.ReadUInt16(what);
        if (!MotionCommandIds.TryGet(index, out MotionCommand command))
        {
            throw r.ErrorAt(at, $"{what} index 0x{index:X4} is not a motion command (the table has {MotionCommandIds.Count})");
        }

        return command;
    }
}
