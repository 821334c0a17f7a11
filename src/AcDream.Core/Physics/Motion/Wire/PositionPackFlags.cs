using System;

namespace AcDream.Core.Physics.Motion.Wire;

/// <summary>The flag word of a position pack (retail <c>PositionPack</c>, the body of UpdatePosition 0xF748): which optional
/// fields follow and whether the object stands on the ground. A quaternion component whose flag is set is not sent and reads
/// as 0 (retail <c>PositionPack::UnPack</c>, acclient.c:323686).</summary>
[Flags]
public enum PositionPackFlags : uint
{
    /// <summary>No optional field; a full quaternion; not grounded.</summary>
    None = 0,

    /// <summary>0x01: a velocity (three floats) follows the quaternion.</summary>
    HasVelocity = 0x01,

    /// <summary>0x02: a placement (animation frame) id follows.</summary>
    HasPlacementId = 0x02,

    /// <summary>0x04: the object stands on the ground (retail <c>has_contact</c>).</summary>
    IsGrounded = 0x04,

    /// <summary>0x08: the quaternion's w is omitted (0).</summary>
    OrientationHasNoW = 0x08,

    /// <summary>0x10: the quaternion's x is omitted (0).</summary>
    OrientationHasNoX = 0x10,

    /// <summary>0x20: the quaternion's y is omitted (0).</summary>
    OrientationHasNoY = 0x20,

    /// <summary>0x40: the quaternion's z is omitted (0).</summary>
    OrientationHasNoZ = 0x40,
}
