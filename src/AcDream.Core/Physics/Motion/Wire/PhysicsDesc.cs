using System;
using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Motion.Wire;

/// <summary>
/// The physics description of a CreateObject (0xF745), every field retail's <c>PhysicsDesc::UnPack</c> (acclient.c:331864)
/// reads, with retail's defaults (<c>PhysicsDesc::PhysicsDesc</c>, acclient.c:331344) for the fields the flags leave out.
/// Decoded by <see cref="PhysicsMessageDecoder.DecodePhysicsDesc"/> (or inside a
/// <see cref="CreateObjectMessage"/>); applied by <see cref="ServerMessageHandler.HandleCreateObject"/>. Reusable: the
/// movement buffer and the child arrays grow once and are then rewritten in place.
/// </summary>
public sealed class PhysicsDesc
{
    /// <summary>Retail's default state (4197384 = REPORT_COLLISIONS | GRAVITY | LIGHTING_ON | EDGE_SLIDE).</summary>
    public const PhysicsState DefaultState = (PhysicsState)0x400C08u;

    /// <summary>Retail's default friction (DEFAULT_FRICTION).</summary>
    public const float DefaultFriction = 0.95f;

    /// <summary>Retail's default elasticity (DEFAULT_ELASTICITY).</summary>
    public const float DefaultElasticity = 0.05f;

    private byte[] _movement = [];
    private uint[] _childIds = [];
    private uint[] _childLocations = [];
    private readonly ushort[] _timestamps = new ushort[9];

    /// <summary>The flag word as received.</summary>
    public PhysicsDescFlags Flags { get; internal set; }

    /// <summary>The persistent state bits (always present).</summary>
    public PhysicsState State { get; internal set; } = DefaultState;

    /// <summary>The movement buffer (<see cref="PhysicsDescFlags.Movement"/>): a MovementEvent's movement data (from its
    /// type byte), applied through the MovementEvent entry point with this description's movement and server-control
    /// stamps. Empty when absent.</summary>
    public ReadOnlySpan<byte> MovementBuffer => _movement.AsSpan(0, MovementBufferLength);

    /// <summary>Length of <see cref="MovementBuffer"/>.</summary>
    public int MovementBufferLength { get; private set; }

    /// <summary>The movement was the object's own client's (read only with a non-empty movement buffer).</summary>
    public bool AutonomousMovement { get; internal set; }

    /// <summary>The animation (placement) frame id (<see cref="PhysicsDescFlags.AnimationFrame"/>), 0 when absent.</summary>
    public uint AnimationFrameId { get; internal set; }

    /// <summary>The position (<see cref="PhysicsDescFlags.Position"/>); cell 0 and the identity frame when absent.</summary>
    public Position Position { get; internal set; } = new(0, Frame.Identity);

    /// <summary>The motion table id, 0 when absent.</summary>
    public uint MotionTableId { get; internal set; }

    /// <summary>The sound table id, 0 when absent.</summary>
    public uint SoundTableId { get; internal set; }

    /// <summary>The physics script table id, 0 when absent.</summary>
    public uint PhysicsScriptTableId { get; internal set; }

    /// <summary>The Setup id, 0 when absent.</summary>
    public uint SetupId { get; internal set; }

    /// <summary>The parent object (<see cref="PhysicsDescFlags.Parent"/>), 0 when none.</summary>
    public uint ParentId { get; internal set; }

    /// <summary>The parent's holding location (read with the parent).</summary>
    public uint ParentLocation { get; internal set; }

    /// <summary>Number of children.</summary>
    public int ChildCount { get; private set; }

    /// <summary>Child <paramref name="index"/>'s object id.</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="index"/> is not below <see cref="ChildCount"/>.</exception>
    public uint GetChildId(int index) => (uint)index < (uint)ChildCount ? _childIds[index] : throw new ArgumentOutOfRangeException(nameof(index));

    /// <summary>Child <paramref name="index"/>'s holding location.</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="index"/> is not below <see cref="ChildCount"/>.</exception>
    public uint GetChildLocation(int index) => (uint)index < (uint)ChildCount ? _childLocations[index] : throw new ArgumentOutOfRangeException(nameof(index));

    /// <summary>The object scale (default 1).</summary>
    public float Scale { get; internal set; } = 1f;

    /// <summary>The friction (default 0.95).</summary>
    public float Friction { get; internal set; } = DefaultFriction;

    /// <summary>The elasticity (default 0.05).</summary>
    public float Elasticity { get; internal set; } = DefaultElasticity;

    /// <summary>The translucency (default 0).</summary>
    public float Translucency { get; internal set; }

    /// <summary>The velocity, m/s in world axes (default zero).</summary>
    public Vector3 Velocity { get; internal set; }

    /// <summary>The acceleration, m/s² (default zero). Retail unpacks it; its <c>HandleCreateObject</c> does not apply it.</summary>
    public Vector3 Acceleration { get; internal set; }

    /// <summary>The omega, rad/s (default zero).</summary>
    public Vector3 Omega { get; internal set; }

    /// <summary>The default script id, 0 when absent.</summary>
    public uint DefaultScript { get; internal set; }

    /// <summary>The default script's intensity, 0 when absent.</summary>
    public float DefaultScriptIntensity { get; internal set; }

    /// <summary>The nine physics timestamps (retail <c>timestamps[9]</c>), by <see cref="PhysicsTimeStamp"/>.</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="stamp"/> is not a defined stamp.</exception>
    // retail: PhysicsDesc::get_timestamp (acclient.c:331296)
    public ushort GetTimestamp(PhysicsTimeStamp stamp) =>
        (uint)stamp < 9u ? _timestamps[(int)stamp] : throw new ArgumentOutOfRangeException(nameof(stamp));

    internal void SetTimestamp(int index, ushort value) => _timestamps[index] = value;

    // retail: PhysicsDesc::Destroy (acclient.c:331401): every field back to its default
    internal void Reset()
    {
        Flags = PhysicsDescFlags.None;
        State = DefaultState;
        MovementBufferLength = 0;
        AutonomousMovement = false;
        AnimationFrameId = 0;
        Position = new Position(0, Frame.Identity);
        MotionTableId = SoundTableId = PhysicsScriptTableId = SetupId = 0;
        ParentId = ParentLocation = 0;
        ChildCount = 0;
        Scale = 1f;
        Friction = DefaultFriction;
        Elasticity = DefaultElasticity;
        Translucency = 0f;
        Velocity = Acceleration = Omega = Vector3.Zero;
        DefaultScript = 0;
        DefaultScriptIntensity = 0f;
        Array.Clear(_timestamps);
    }

    internal Span<byte> MovementBufferFor(int length)
    {
        if (_movement.Length < length)
        {
            _movement = new byte[Math.Max(length, 2 * _movement.Length)];
        }

        MovementBufferLength = length;
        return _movement.AsSpan(0, length);
    }

    internal void SetChildCount(int count)
    {
        if (_childIds.Length < count)
        {
            _childIds = new uint[count];
            _childLocations = new uint[count];
        }

        ChildCount = count;
    }

    internal void SetChild(int index, uint id, uint location)
    {
        _childIds[index] = id;
        _childLocations[index] = location;
    }
}
