using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// Where <c>MovementManager::unpack_movement</c> hands movement types 6-9 to the move-to manager (acclient.c:339564-339612:
/// <c>MakeMoveToManager</c>, then <c>CPhysicsObj::MoveToObject</c> or, for an unknown target,
/// <c>MoveToManager::MoveToPosition</c> at the origin; <c>MoveToManager::MoveToPosition</c>; <c>CPhysicsObj::TurnToObject</c>
/// or <c>MoveToManager::TurnToHeading</c> at the event's heading; <c>MoveToManager::TurnToHeading</c>).
/// </summary>
internal static class MoveToSeam
{
    /// <summary>Starts the move-to or turn-to of <paramref name="m"/>; false while the move-to manager is not ported.</summary>
    public static bool Dispatch(MovementManager mm, PhysicsObj obj, MovementEventMessage m) => false;
}
