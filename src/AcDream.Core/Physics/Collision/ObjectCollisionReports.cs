using System.Numerics;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Collision;

/// <summary>What an object reports when it runs into another object. Retail: <c>ObjCollisionProfile</c>.</summary>
public readonly struct ObjCollisionProfile
{
    /// <summary>Creates a profile.</summary>
    public ObjCollisionProfile(uint id, Vector3 velocity, bool missile, bool inContact, bool meInContact)
    {
        Id = id;
        Velocity = velocity;
        Missile = missile;
        InContact = inContact;
        MeInContact = meInContact;
    }

    /// <summary>The other object's id. Retail: <c>id</c>.</summary>
    public uint Id { get; }

    /// <summary>The relative velocity (the mover's minus the obstacle's), m/s. Retail: <c>velocity</c>.</summary>
    public Vector3 Velocity { get; }

    /// <summary>The other object is a missile. Retail: <c>SetMissile</c>.</summary>
    public bool Missile { get; }

    /// <summary>The other object is in contact with the ground. Retail: <c>SetInContact</c>.</summary>
    public bool InContact { get; }

    /// <summary>The reporting object is in contact with the ground. Retail: <c>SetMeInContact</c>.</summary>
    public bool MeInContact { get; }
}

/// <summary>What a missile reports when it hits an object, or an object when a missile hits it. Retail:
/// <c>AtkCollisionProfile</c>.</summary>
public readonly struct AtkCollisionProfile
{
    /// <summary>Creates a profile.</summary>
    public AtkCollisionProfile(uint id, int part, int location)
    {
        Id = id;
        Part = part;
        Location = location;
    }

    /// <summary>The other object's id. Retail: <c>id</c>.</summary>
    public uint Id { get; }

    /// <summary>The part hit; -1 (retail never resolves a part here). Retail: <c>part</c>.</summary>
    public int Part { get; }

    /// <summary>The quadrant hit (<see cref="PhysicsObj.DetermineQuadrant"/>). Retail: <c>location</c>.</summary>
    public int Location { get; }
}

/// <summary>
/// The client's object-collision callbacks (retail: the two objects' weenies, <c>DoCollision</c> /
/// <c>DoCollisionEnd</c>). Called inside the tick: implementations must not allocate and must not sweep.
/// </summary>
public interface IObjectCollisionListener
{
    /// <summary><paramref name="obj"/> (with REPORT_COLLISIONS and a weenie) started touching another object.</summary>
    // retail caller: CPhysicsObj::report_object_collision (acclient.c:320227) -> weenie DoCollision(ObjCollisionProfile)
    void OnObjectCollision(PhysicsObj obj, in ObjCollisionProfile profile);

    /// <summary>A missile hit, or <paramref name="obj"/> was hit by a missile.</summary>
    // retail caller: CPhysicsObj::report_object_collision (acclient.c:320227) -> weenie DoCollision(AtkCollisionProfile)
    void OnAttackCollision(PhysicsObj obj, in AtkCollisionProfile profile);

    /// <summary><paramref name="obj"/> stopped touching the object <paramref name="otherId"/>.</summary>
    // retail caller: CPhysicsObj::report_object_collision_end (acclient.c:317868) -> weenie DoCollisionEnd
    void OnObjectCollisionEnd(PhysicsObj obj, uint otherId);
}

/// <summary>One entry of an object's collision table: who it touched, when, and whether that object was ethereal.
/// Retail: <c>CPhysicsObj::CollisionRecord</c> in <c>collision_table</c> (keyed by object id).</summary>
public struct CollisionRecord
{
    /// <summary>The touched object's id (the table key).</summary>
    public uint ObjectId;

    /// <summary>Physics time of the last touch, seconds. Retail: <c>touched_time</c>.</summary>
    public double TouchedTime;

    /// <summary>The touched object was ethereal. Retail: <c>ethereal</c>.</summary>
    public bool Ethereal;
}
