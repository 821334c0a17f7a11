using System;
using System.Buffers.Binary;
using System.Numerics;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Input;

// What the client sends back (retail CommandInterpreter::SendMovementEvent, SendPositionEvent, ShouldSendPositionEvent,
// RawMotionState::Pack, MoveToStatePack::Pack, AutonomousPositionPack::Pack, JumpPack::Pack): the bodies written into
// buffers the input owns (nothing allocated per frame).
public sealed partial class PlayerInput
{
    private readonly byte[] _moveToState = new byte[256];
    private readonly byte[] _autonomousPosition = new byte[64];
    private readonly byte[] _jump = new byte[64];
    private int _moveToStateLength, _autonomousPositionLength, _jumpLength;
    private OutboundMessages _pending;
    private double _lastSentPositionTime;
    private Position _lastSentPosition;
    private Vector3 _lastSentPlaneNormal;
    private float _lastSentPlaneD;

    /// <summary>Seconds between two AutonomousPositions while the player moves (retail <c>time_between_position_events</c>,
    /// 1).</summary>
    public double TimeBetweenPositionEvents { get; set; } = 1.0;

    /// <summary>The last MoveToState body (0xF61C, after the game action's opcode): the raw motion state
    /// (<c>RawMotionState::Pack</c>: a flag word whose bits 0-10 say which of hold key, style, forward command, hold key
    /// and speed, side-step command, hold key and speed, turn command, hold key and speed differ from their defaults and
    /// follow, bits 11-15 the action count, then the actions), the position (cell, origin, w, x, y, z), the instance,
    /// server-control, teleport and force-position stamps, the contact byte (bit 0 contact and walkable, bit 1 the standing
    /// long jump) and padding to 4.</summary>
    public ReadOnlySpan<byte> MoveToStateBody => _moveToState.AsSpan(0, _moveToStateLength);

    /// <summary>The last AutonomousPosition body (0xF753): the position, the four stamps, the contact byte, padding.</summary>
    public ReadOnlySpan<byte> AutonomousPositionBody => _autonomousPosition.AsSpan(0, _autonomousPositionLength);

    /// <summary>The last Jump body (0xF61B): the extent, the leave-ground velocity (local axes), the position, the four
    /// stamps, padding.</summary>
    public ReadOnlySpan<byte> JumpBody => _jump.AsSpan(0, _jumpLength);

    /// <summary>
    /// Once per frame, after the world's tick: what the client should send now. A MoveToState is due after every command a key sent
    /// (packed when the key went, as retail sends it), after a jump charge and a teleport; a Jump after a jump; and an AutonomousPosition when the
    /// interpreter's rule says so (retail <c>ShouldSendPositionEvent</c>: with autonomy level 2, more than
    /// <see cref="TimeBetweenPositionEvents"/> after the last send and the player's position differs from the last sent,
    /// or sooner when it changed cell or contact plane; at once after a blip). The bodies stay valid until the next call.
    /// </summary>
    /// <exception cref="InvalidOperationException">The player was removed from its world.</exception>
    // retail: CommandInterpreter::UseTime (acclient.c:717594), its first line: ShouldSendPositionEvent -> SendPositionEvent
    public OutboundMessages TakeOutbound()
    {
        ThrowIfRemoved();
        if (PositionDue || ShouldSendPositionEvent())
        {
            PositionDue = false;
            SendPositionEvent();
        }

        OutboundMessages r = _pending;
        _pending = OutboundMessages.None;
        return r;
    }

    // retail: CommandInterpreter::ShouldSendPositionEvent (acclient.c:718107)
    private bool ShouldSendPositionEvent()
    {
        if (_autonomyLevel != 2)
        {
            return false;
        }

        Position now = _player.Position;
        if (TimeBetweenPositionEvents + _lastSentPositionTime < _player.World.CurrentTime)
        {
            return _lastSentPosition.ObjCellId != now.ObjCellId || !_lastSentPosition.Frame.IsEqual(now.Frame);
        }

        return _lastSentPosition.ObjCellId != now.ObjCellId
            || _lastSentPlaneNormal != _player.ContactPlaneNormal || _lastSentPlaneD != _player.ContactPlaneD;
    }

    // retail: CommandInterpreter::SendMovementEvent (acclient.c:718141) with MoveToStatePack::Pack (acclient.c:323813)
    private void SendMovementEvent()
    {
        if (_autonomyLevel == 0)
        {
            return;
        }

        Span<byte> b = _moveToState;
        int at = PackRawMotionState(b, _interp.RawState);
        at = PackPose(b, at);
        b[at++] = (byte)((OnWalkableContact ? 1 : 0) | (_interp.StandingLongJump ? 2 : 0));
        _moveToStateLength = Align(b, at);
        _lastSentPositionTime = _player.World.CurrentTime;
        _pending |= OutboundMessages.MoveToState;
    }

    // retail: CommandInterpreter::SendPositionEvent (acclient.c:718201) with AutonomousPositionPack::Pack (acclient.c:323933):
    // only with contact and walkable ground.
    private void SendPositionEvent()
    {
        if (!OnWalkableContact)
        {
            return;
        }

        Span<byte> b = _autonomousPosition;
        int at = PackPose(b, 0);
        b[at++] = 1;
        _autonomousPositionLength = Align(b, at);
        _lastSentPositionTime = _player.World.CurrentTime;
        _lastSentPosition = _player.Position;
        _lastSentPlaneNormal = _player.ContactPlaneNormal;
        _lastSentPlaneD = _player.ContactPlaneD;
        _pending |= OutboundMessages.AutonomousPosition;
    }

    // JumpPack::Pack (acclient.c:324067): extent, velocity, position, the four stamps, padding.
    // non-retail: the send site (the jump's game action) is not traced; the velocity is the interpreter's leave-ground
    // velocity right after jump(), what the recorded F61B bodies carry for a standing jump (0, 0, vz)
    private void SendJump(float extent)
    {
        Span<byte> b = _jump;
        BinaryPrimitives.WriteSingleLittleEndian(b, extent);
        Vector3 v = _interp.LeaveGroundVelocity;
        BinaryPrimitives.WriteSingleLittleEndian(b[4..], v.X);
        BinaryPrimitives.WriteSingleLittleEndian(b[8..], v.Y);
        BinaryPrimitives.WriteSingleLittleEndian(b[12..], v.Z);
        int at = PackPosition(b, 16, _player.Position);
        at = PackStamps(b, at);
        _jumpLength = Align(b, at);
        _pending |= OutboundMessages.Jump;
    }

    private bool OnWalkableContact =>
        (_player.TransientState & (TransientState.Contact | TransientState.OnWalkable)) == (TransientState.Contact | TransientState.OnWalkable);

    // retail: RawMotionState::Pack (acclient.c:332969)
    internal static int PackRawMotionState(Span<byte> b, RawMotionState s)
    {
        uint flags = 0;
        if (s.CurrentHoldKey != HoldKey.None) flags |= 0x1;
        if (s.CurrentStyle != MotionCommand.NonCombat) flags |= 0x2;
        if (s.ForwardCommand != MotionCommand.Ready) flags |= 0x4;
        if (s.ForwardHoldKey != HoldKey.Invalid) flags |= 0x8;
        if (s.ForwardSpeed != 1f) flags |= 0x10;
        if (s.SidestepCommand != 0) flags |= 0x20;
        if (s.SidestepHoldKey != HoldKey.Invalid) flags |= 0x40;
        if (s.SidestepSpeed != 1f) flags |= 0x80;
        if (s.TurnCommand != 0) flags |= 0x100;
        if (s.TurnHoldKey != HoldKey.Invalid) flags |= 0x200;
        if (s.TurnSpeed != 1f) flags |= 0x400;
        int actions = s.Actions.Count;
        flags |= (uint)(actions << 11) & 0xF800;
        int at = 0;
        Put(b, ref at, flags);
        if ((flags & 0x1) != 0) Put(b, ref at, (uint)s.CurrentHoldKey);
        if ((flags & 0x2) != 0) Put(b, ref at, (uint)s.CurrentStyle);
        if ((flags & 0x4) != 0) Put(b, ref at, (uint)s.ForwardCommand);
        if ((flags & 0x8) != 0) Put(b, ref at, (uint)s.ForwardHoldKey);
        if ((flags & 0x10) != 0) Put(b, ref at, s.ForwardSpeed);
        if ((flags & 0x20) != 0) Put(b, ref at, (uint)s.SidestepCommand);
        if ((flags & 0x40) != 0) Put(b, ref at, (uint)s.SidestepHoldKey);
        if ((flags & 0x80) != 0) Put(b, ref at, s.SidestepSpeed);
        if ((flags & 0x100) != 0) Put(b, ref at, (uint)s.TurnCommand);
        if ((flags & 0x200) != 0) Put(b, ref at, (uint)s.TurnHoldKey);
        if ((flags & 0x400) != 0) Put(b, ref at, s.TurnSpeed);
        for (int i = 0; i < actions; i++)
        {
            ActionNode n = s.Actions[i];
            BinaryPrimitives.WriteUInt16LittleEndian(b[at..], (ushort)n.Action);
            BinaryPrimitives.WriteUInt16LittleEndian(b[(at + 2)..], (ushort)((n.Stamp & 0x7FFF) | (n.Autonomous ? 0x8000u : 0u)));
            BinaryPrimitives.WriteSingleLittleEndian(b[(at + 4)..], n.Speed);
            at += 8;
        }

        return at;
    }

    // The pose and the stamps of MoveToStatePack / AutonomousPositionPack: Position::Pack, then instance, server control,
    // teleport, force position (the order of the packs' constructors' fields).
    private int PackPose(Span<byte> b, int at) => PackStamps(b, PackPosition(b, at, _player.Position));

    // retail: Position::Pack: the cell, then Frame::Pack (origin, w, x, y, z)
    private static int PackPosition(Span<byte> b, int at, in Position p)
    {
        Put(b, ref at, p.ObjCellId);
        Vector3 o = p.Frame.Origin;
        Quaternion q = p.Frame.Rotation;
        Put(b, ref at, o.X);
        Put(b, ref at, o.Y);
        Put(b, ref at, o.Z);
        Put(b, ref at, q.W);
        Put(b, ref at, q.X);
        Put(b, ref at, q.Y);
        Put(b, ref at, q.Z);
        return at;
    }

    private int PackStamps(Span<byte> b, int at)
    {
        BinaryPrimitives.WriteUInt16LittleEndian(b[at..], _player.GetUpdateTime(PhysicsTimeStamp.Instance));
        BinaryPrimitives.WriteUInt16LittleEndian(b[(at + 2)..], _player.GetUpdateTime(PhysicsTimeStamp.ServerControlledMove));
        BinaryPrimitives.WriteUInt16LittleEndian(b[(at + 4)..], _player.GetUpdateTime(PhysicsTimeStamp.Teleport));
        BinaryPrimitives.WriteUInt16LittleEndian(b[(at + 6)..], _player.GetUpdateTime(PhysicsTimeStamp.ForcePosition));
        return at + 8;
    }

    private static void Put(Span<byte> b, ref int at, uint v)
    {
        BinaryPrimitives.WriteUInt32LittleEndian(b[at..], v);
        at += 4;
    }

    private static void Put(Span<byte> b, ref int at, float v)
    {
        BinaryPrimitives.WriteSingleLittleEndian(b[at..], v);
        at += 4;
    }

    // PackObj::ALIGN_PTR: zero bytes to the next multiple of 4.
    private static int Align(Span<byte> b, int at)
    {
        while ((at & 3) != 0)
        {
            b[at++] = 0;
        }

        return at;
    }
}
