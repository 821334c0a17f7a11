using System.Numerics;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Motion.Wire;

/// <summary>One server VectorUpdate (message 0xF74E): <c>u32</c> object, velocity and omega (three floats each), <c>u16</c>
/// instance and vector stamps. A remote's jump arrives as one. Applied by
/// <see cref="ServerMessageHandler.HandleVectorUpdate"/>. Reusable.</summary>
public sealed class VectorUpdateMessage
{
    /// <summary>The object.</summary>
    public uint ObjectId { get; set; }

    /// <summary>The velocity, m/s in world axes.</summary>
    public Vector3 Velocity { get; set; }

    /// <summary>The angular velocity, rad/s in world axes.</summary>
    public Vector3 Omega { get; set; }

    /// <summary>The object's instance stamp (INSTANCE_TS).</summary>
    public ushort InstanceTimestamp { get; set; }

    /// <summary>The vector stamp (VECTOR_TS).</summary>
    public ushort VectorTimestamp { get; set; }
}

/// <summary>One server SetState (message 0xF74B): <c>u32</c> object, <c>u32</c> physics state, <c>u16</c> instance and
/// state stamps. Applied by <see cref="ServerMessageHandler.HandleSetState"/>. Reusable.</summary>
public sealed class SetStateMessage
{
    /// <summary>The object.</summary>
    public uint ObjectId { get; set; }

    /// <summary>The new persistent state bits (retail <c>state</c>).</summary>
    public PhysicsState State { get; set; }

    /// <summary>The object's instance stamp (INSTANCE_TS).</summary>
    public ushort InstanceTimestamp { get; set; }

    /// <summary>The state stamp (STATE_TS).</summary>
    public ushort StateTimestamp { get; set; }
}

/// <summary>One server ParentEvent (message 0xF749): <c>u32</c> parent, <c>u32</c> child, <c>u32</c> location (the parent's
/// holding location), <c>u32</c> placement id, <c>u16</c> the parent's instance stamp and the child's position stamp.
/// Applied by <see cref="ServerMessageHandler.HandleParentEvent"/>. Reusable.</summary>
public sealed class ParentEventMessage
{
    /// <summary>The parent object (retail's <c>object_id</c>, whose instance is checked).</summary>
    public uint ParentId { get; set; }

    /// <summary>The child object.</summary>
    public uint ChildId { get; set; }

    /// <summary>The parent's holding location the child goes to (retail <c>child_location</c>).</summary>
    public uint Location { get; set; }

    /// <summary>The child's placement (animation frame) id.</summary>
    public uint PlacementId { get; set; }

    /// <summary>The parent's instance stamp (INSTANCE_TS).</summary>
    public ushort ParentInstanceTimestamp { get; set; }

    /// <summary>The child's position stamp (POSITION_TS).</summary>
    public ushort ChildPositionTimestamp { get; set; }
}

/// <summary>One server PickupEvent (message 0xF74A): <c>u32</c> object, <c>u16</c> instance and position stamps. The object
/// leaves the world. Applied by <see cref="ServerMessageHandler.HandlePickupEvent"/>. Reusable.</summary>
public sealed class PickupEventMessage
{
    /// <summary>The object.</summary>
    public uint ObjectId { get; set; }

    /// <summary>The object's instance stamp (INSTANCE_TS).</summary>
    public ushort InstanceTimestamp { get; set; }

    /// <summary>The position stamp (POSITION_TS).</summary>
    public ushort PositionTimestamp { get; set; }
}

/// <summary>One server PlayerTeleport (message 0xF751): <c>u16</c> teleport stamp, padding to 4 bytes. Applied by
/// <see cref="ServerMessageHandler.HandlePlayerTeleport"/>. Reusable.</summary>
public sealed class PlayerTeleportMessage
{
    /// <summary>The teleport stamp (retail <c>physics_timestamp</c>, compared with the player's TELEPORT_TS).</summary>
    public ushort TeleportTimestamp { get; set; }
}

/// <summary>One server DeleteObject (message 0xF747): <c>u32</c> object, <c>u16</c> instance stamp, padding to 4 bytes.
/// Applied by <see cref="ServerMessageHandler.HandleDeleteObject"/>. Reusable.</summary>
public sealed class DeleteObjectMessage
{
    /// <summary>The object.</summary>
    public uint ObjectId { get; set; }

    /// <summary>The object's instance stamp (INSTANCE_TS): only the instance the client holds is deleted.</summary>
    public ushort InstanceTimestamp { get; set; }
}
