using System;

namespace AcDream.Core.Physics.Objects;

/// <summary>
/// The per-frame state bits of a physics object (retail <c>TransientState</c>, acclient.h:3688).
/// Values are retail's and must not change.
/// </summary>
[Flags]
public enum TransientState : uint
{
    /// <summary>No bit set.</summary>
    None = 0,

    /// <summary>CONTACT_TS: the last sweep found a contact plane.</summary>
    Contact = 0x1,

    /// <summary>ON_WALKABLE_TS: the contact plane is walkable floor.</summary>
    OnWalkable = 0x2,

    /// <summary>SLIDING_TS: the last sweep produced a sliding normal.</summary>
    Sliding = 0x4,

    /// <summary>WATER_CONTACT_TS.</summary>
    WaterContact = 0x8,

    /// <summary>STATIONARY_FALL_TS.</summary>
    StationaryFall = 0x10,

    /// <summary>STATIONARY_STOP_TS.</summary>
    StationaryStop = 0x20,

    /// <summary>STATIONARY_STUCK_TS.</summary>
    StationaryStuck = 0x40,

    /// <summary>ACTIVE_TS: the object is simulated (the sign bit of the low byte in the decompilation).</summary>
    Active = 0x80,

    /// <summary>CHECK_ETHEREAL_TS: the object waits to become solid again.</summary>
    CheckEthereal = 0x100,
}
