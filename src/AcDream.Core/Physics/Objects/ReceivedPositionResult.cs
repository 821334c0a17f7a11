namespace AcDream.Core.Physics.Objects;

/// <summary>What <see cref="PhysicsObj.HandleReceivedPosition"/> did with a server position report.</summary>
/// <remarks>Not retail: retail's <c>SmartBox::HandleReceivedPosition</c> returns nothing; the values name its branches
/// (acclient.c:145124, <c>CPhysicsObj::MoveOrTeleport</c> acclient.c:323450).</remarks>
public enum ReceivedPositionResult
{
    /// <summary>The position timestamp is not newer than the last one accepted: dropped, nothing changed.</summary>
    Stale = 0,

    /// <summary>The teleport timestamp is older than the last one: dropped, nothing changed (the position stamp is restored).</summary>
    StaleTeleport = 1,

    /// <summary>No teleport, the object is in a cell and the report has no contact: not used (its position stamp is kept, as
    /// retail keeps it).</summary>
    NoContact = 2,

    /// <summary>Queued for interpolation (an object within 96 m of the player, retail smoothing): the object moves towards the
    /// report over the next ticks.</summary>
    Interpolating = 3,

    /// <summary>Queued for interpolation, but the report's cell is not loaded (its landblock, or its indoor cell): where the
    /// object ends depends on when the cell loads; a later placement there sends it out of the world.</summary>
    InterpolatingToUnloadedCell = 4,

    /// <summary>Placed at the report (a teleport, a snap beyond 96 m from the player, or a non-retail smoothing mode's snap), in
    /// a loaded cell.</summary>
    Placed = 5,

    /// <summary>The report asked for a placement that failed (the spot is blocked: <see cref="SetPositionError.Collided"/> or
    /// <see cref="SetPositionError.NoValidPosition"/>): the object stays where it was. The report still counts as used, as in
    /// retail (its stamps are kept and the leash is re-armed).</summary>
    PlacementFailed = 6,

    /// <summary>Placed at a report whose cell is not loaded (or is not a cell): the object left the world, as retail's lost
    /// cell — <see cref="PhysicsObj.CellId"/> 0, no shadows, not simulated — until a later report or
    /// <see cref="PhysicsObj.EnterWorld"/> places it in a loaded cell.</summary>
    LeftWorld = 7,
}
