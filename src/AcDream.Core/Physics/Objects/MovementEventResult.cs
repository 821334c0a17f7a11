namespace AcDream.Core.Physics.Objects;

/// <summary>What <see cref="PhysicsObj.HandleMovementEvent"/> did with a server MovementEvent (0xF74C).</summary>
/// <remarks>Not retail: retail's <c>CPhysics::SetObjectMovement</c> (acclient.c:311148) answers 1 only when it applied the
/// event to this client's own player (the SmartBox then lets the command interpreter know) and 0 otherwise; the values name
/// its branches.</remarks>
public enum MovementEventResult
{
    /// <summary>The movement stamp is not newer than the last one accepted (a duplicate or an out-of-order event): dropped,
    /// nothing changed.</summary>
    Stale = 0,

    /// <summary>The server-control stamp is older than the last one: dropped. As retail, the movement stamp has already
    /// been taken (a later event with the same movement stamp is then stale).</summary>
    StaleServerControl = 1,

    /// <summary>The server's echo of this client's own player's autonomous motion (the autonomous flag on an object whose
    /// weenie is <see cref="Motion.IMotionWeenie.IsThePlayer"/>): ignored, the client already moved it. Both stamps are
    /// taken.</summary>
    OwnAutonomousEcho = 2,

    /// <summary>The object's movement manager is a client's own (<see cref="World.PhysicsWorld.MovementManagerFactory"/>),
    /// which the library cannot unpack into: the stamps and <see cref="PhysicsObj.LastMoveWasAutonomous"/> are taken, the
    /// movement is not applied.</summary>
    NotApplied = 3,

    /// <summary>Applied: the object switched to the event's style and its motion interpreter (type 0) or move-to manager
    /// (types 6-9) runs the movement; its part array's motion table plays it, so the object moves.</summary>
    Applied = 4,

    /// <summary>Unpacked as <see cref="Applied"/> (the stamps, the style, the interpreter's state or the move-to are taken),
    /// but the object cannot play it: it has no part array, or its part array has no motion table
    /// (<see cref="Parts.IPartArray.MotionPlayer"/> null), so the motion commands reach nothing and the body does not move
    /// while its interpreter reports the motion. <see cref="PhysicsObj.SetupIssues"/> names it
    /// (<see cref="ObjectSetupIssues.NoMotionTable"/>, <see cref="ObjectSetupIssues.NoPartArray"/>). Non-retail: retail's
    /// entry point answers nothing.</summary>
    NoMotionTable = 5,
}
