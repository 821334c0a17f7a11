using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Motion.Wire;

/// <summary>
/// One server UpdatePosition (message 0xF748) decoded by <see cref="PhysicsMessageDecoder.Decode(System.ReadOnlySpan{byte}, UpdatePositionMessage)"/>:
/// the object and its position pack (retail <c>PositionPack</c>: flags, cell, origin, quaternion, velocity, placement id,
/// grounded, four stamps). <see cref="ServerMessageHandler.HandleUpdatePosition"/> applies it. Reusable: every field is
/// rewritten by each decode.
/// </summary>
public sealed class UpdatePositionMessage
{
    /// <summary>The object the position is for.</summary>
    public uint ObjectId { get; set; }

    /// <summary>The pack's flag word as received.</summary>
    public PositionPackFlags Flags { get; set; }

    /// <summary>The position: the cell id and the frame local to its landblock. The quaternion's omitted components are 0
    /// (as retail reads them); the decoder refuses a quaternion whose norm is far from 1 and stores it normalised.</summary>
    public Position Position { get; set; } = new(0, Frame.Identity);

    /// <summary>The velocity when <see cref="PositionPackFlags.HasVelocity"/> is set, else zero. Retail reads past it
    /// without using it (its <c>PositionPack::UnPack</c> stores nothing for it); here it is decoded for the client.</summary>
    public Vector3 Velocity { get; set; }

    /// <summary>The placement (animation frame) id when <see cref="PositionPackFlags.HasPlacementId"/> is set, else 0.</summary>
    public uint PlacementId { get; set; }

    /// <summary>The object stands on the ground (<see cref="PositionPackFlags.IsGrounded"/>; retail <c>has_contact</c>).</summary>
    public bool HasContact { get; set; }

    /// <summary>The object's 16-bit instance stamp (INSTANCE_TS).</summary>
    public ushort InstanceTimestamp { get; set; }

    /// <summary>The 16-bit position stamp (POSITION_TS).</summary>
    public ushort PositionTimestamp { get; set; }

    /// <summary>The 16-bit teleport stamp (TELEPORT_TS).</summary>
    public ushort TeleportTimestamp { get; set; }

    /// <summary>The 16-bit force-position stamp (FORCE_POSITION_TS): newer on the player's own object means the server
    /// overrides the client's position (a blip).</summary>
    public ushort ForcePositionTimestamp { get; set; }
}
