namespace AcDream.Core.Physics.Motion;

/// <summary>
/// Another client's creature or player as this client sees it (retail <c>ACCWeenieObject</c> of an object that is not the
/// player): a creature whose run rate and jump the interpreter does not ask (they arrive with its MovementEvents).
/// </summary>
/// <remarks>Its members are pure queries with no value domain: every argument is accepted (the answers are fixed), and the
/// float results are outputs.</remarks>
public sealed class RemoteCreatureWeenie : IMotionWeenie
{
    /// <summary>A remote creature that is not a player.</summary>
    public static RemoteCreatureWeenie Creature { get; } = new();

    /// <summary>A remote player.</summary>
    public static RemoteCreatureWeenie Player { get; } = new() { IsPlayer = true };

    /// <inheritdoc />
    public bool IsThePlayer => false;

    /// <inheritdoc />
    public bool IsCreature => true;

    /// <inheritdoc />
    public bool IsPlayer { get; init; }

    /// <inheritdoc />
    public bool IsImpenetrable { get; init; }

    /// <inheritdoc />
    public bool IsPK { get; init; }

    /// <inheritdoc />
    public bool IsPKLite { get; init; }

    /// <inheritdoc />
    // retail: ACCWeenieObject::InqRunRate (acclient.c:436990): false unless the object is the player
    public bool InqRunRate(out float rate)
    {
        rate = 0f;
        return false;
    }

    /// <inheritdoc />
    // retail: ACCWeenieObject::InqJumpVelocity (acclient.c:436975): false unless the object is the player
    public bool InqJumpVelocity(float extent, out float vz)
    {
        vz = 0f;
        return false;
    }

    /// <inheritdoc />
    // retail: ACCWeenieObject::CanJump (acclient.c:436884): false unless the object is the player
    public bool CanJump(float extent) => false;

    /// <inheritdoc />
    // retail: ACCWeenieObject::JumpStaminaCost (acclient.c:436899): false unless the object is the player
    public bool JumpStaminaCost(float extent, out int cost)
    {
        cost = 0;
        return false;
    }
}
