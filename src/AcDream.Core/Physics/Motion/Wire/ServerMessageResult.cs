namespace AcDream.Core.Physics.Motion.Wire;

/// <summary>What <see cref="ServerMessageHandler"/> did with a server message. Retail's handlers answer 1 (handled), 2
/// (an older instance), 3 (not for this client) or 4 (queued for an object not yet created); the library names their
/// branches, including the timestamp gates retail passes silently.</summary>
public enum ServerMessageResult
{
    /// <summary>Applied to the object.</summary>
    Applied = 0,

    /// <summary>A timestamp gate dropped it (retail <c>CPhysicsObj::newer_event</c> and its inline copies): not newer
    /// than the last one applied, or (positions) an older teleport stamp. Nothing changed but the stamps retail writes
    /// before the drop.</summary>
    Stale = 1,

    /// <summary>The message is for an older instance of the object than the client holds (retail's 2): dropped.</summary>
    OldInstance = 2,

    /// <summary>The object (or a parent or child it needs) is not created yet, or the message is for a newer instance:
    /// kept and applied after the object's CreateObject (retail <c>QueueBlobForObject</c>, 4). From the typed entry
    /// points (which hold no bytes to keep) the same case answers <see cref="UnknownObject"/>.</summary>
    Queued = 3,

    /// <summary>The typed entry points' <see cref="Queued"/>: the object is unknown or newer; nothing was kept.</summary>
    UnknownObject = 4,

    /// <summary>The player's own echo: a position or vector the server sends back for the player while this client is in
    /// control of it (retail's <c>UsePositionFromServer</c> is false), or a MovementEvent echo of its own motion: the
    /// stamps are taken, the client's own motion stands.</summary>
    PlayerOwnEcho = 5,

    /// <summary>The server forced the player's position (a newer force-position stamp): the player was placed there
    /// with its own heading (retail <c>BlipPlayer</c>); the client should send its position.</summary>
    PlayerBlipped = 6,

    /// <summary>The player was teleported (a newer teleport stamp on the player's own position).</summary>
    PlayerTeleported = 7,

    /// <summary>Not applicable, nothing changed (retail's 3): a delete of the player, a CreateObject the object factory
    /// refused, a parent event whose holding location the parent's setup does not have, a PlayerTeleport before the
    /// player exists, or an opcode the physics does not read.</summary>
    NotApplicable = 8,
}
