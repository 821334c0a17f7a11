using System.Numerics;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Collision;

/// <summary>
/// What an object reports when it runs into the environment (terrain, walls) or lands. Retail:
/// <c>EnvCollisionProfile</c>, handed to the weenie's <c>DoCollision</c>.
/// </summary>
public readonly struct EnvCollisionProfile
{
    /// <summary>Creates a profile.</summary>
    public EnvCollisionProfile(Vector3 velocity, bool meInContact)
    {
        Velocity = velocity;
        MeInContact = meInContact;
    }

    /// <summary>The object's velocity at the moment of the collision (after the sweep, before the bounce), m/s.</summary>
    public Vector3 Velocity { get; }

    /// <summary>The object was in contact with the ground before the sweep. Retail: <c>SetMeInContact(prev_has_contact)</c>.</summary>
    public bool MeInContact { get; }
}

/// <summary>
/// The client's collision callbacks (retail: the object's weenie, <c>CWeenieObject::DoCollision</c>). Called inside the
/// tick: implementations must not allocate and must not start a sweep of the same object. Placing or sweeping another object
/// is safe: it takes a transition of its own, and the reporter's commit goes on with its own.
/// </summary>
public interface ICollisionListener
{
    /// <summary>
    /// <paramref name="obj"/>, which has <see cref="PhysicsState.ReportCollisions"/>, started colliding with the environment
    /// (reported once until the collision ends).
    /// </summary>
    // retail caller: CPhysicsObj::report_environment_collision (acclient.c:320193) -> weenie DoCollision
    void OnEnvironmentCollision(PhysicsObj obj, in EnvCollisionProfile profile);
}
