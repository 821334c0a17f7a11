namespace AcDream.Core.Physics.Objects.Seams;

/// <summary>
/// The game-object questions the physics asks during object collisions (retail: virtual functions of the object's
/// <c>CWeenieObject</c>). A client sets <see cref="PhysicsObj.Weenie"/> to answer them; an object without one is a plain
/// physics object (not a creature, not a player). Called inside the tick: implementations must not allocate.
/// </summary>
public interface IWeenieObject
{
    /// <summary>The object is a creature (retail <c>CWeenieObject::IsCreature</c>, vtable slot 11).</summary>
    bool IsCreature { get; }

    /// <summary>The object is a player (retail <c>IsPlayer</c>, slot 4).</summary>
    bool IsPlayer { get; }

    /// <summary>The object may not be walked through by players (retail <c>IsImpenetrable</c>, slot 10).</summary>
    bool IsImpenetrable { get; }

    /// <summary>The object is a player killer (retail <c>IsPK</c>, slot 8).</summary>
    bool IsPK { get; }

    /// <summary>The object is a PK-lite player (retail <c>IsPKLite</c>, slot 9).</summary>
    bool IsPKLite { get; }
}

/// <summary>A fixed-answer <see cref="IWeenieObject"/> for clients and tests that know an object's kind up front.</summary>
public sealed class WeenieTraits : IWeenieObject
{
    /// <inheritdoc />
    public bool IsCreature { get; init; }

    /// <inheritdoc />
    public bool IsPlayer { get; init; }

    /// <inheritdoc />
    public bool IsImpenetrable { get; init; }

    /// <inheritdoc />
    public bool IsPK { get; init; }

    /// <inheritdoc />
    public bool IsPKLite { get; init; }

    /// <summary>A creature that is not a player.</summary>
    public static WeenieTraits Creature { get; } = new() { IsCreature = true };

    /// <summary>A player (players are creatures).</summary>
    public static WeenieTraits Player { get; } = new() { IsCreature = true, IsPlayer = true };
}
