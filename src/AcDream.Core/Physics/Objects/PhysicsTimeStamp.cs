namespace AcDream.Core.Physics.Objects;

/// <summary>Which network event a 16-bit timestamp orders (retail <c>PhysicsTimeStamp</c>, acclient.h:6084).</summary>
public enum PhysicsTimeStamp
{
    /// <summary>POSITION_TS.</summary>
    Position = 0,

    /// <summary>MOVEMENT_TS.</summary>
    Movement = 1,

    /// <summary>STATE_TS.</summary>
    State = 2,

    /// <summary>VECTOR_TS.</summary>
    Vector = 3,

    /// <summary>TELEPORT_TS.</summary>
    Teleport = 4,

    /// <summary>SERVER_CONTROLLED_MOVE_TS.</summary>
    ServerControlledMove = 5,

    /// <summary>FORCE_POSITION_TS.</summary>
    ForcePosition = 6,

    /// <summary>OBJDESC_TS.</summary>
    ObjDesc = 7,

    /// <summary>INSTANCE_TS.</summary>
    Instance = 8,
}
