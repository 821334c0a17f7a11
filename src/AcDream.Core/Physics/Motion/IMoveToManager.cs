namespace AcDream.Core.Physics.Motion;

/// <summary>
/// Seam to an object's move-to manager (retail <c>MoveToManager</c>: walking or turning to an object or a position, not
/// ported). A client that runs move-tos sets <see cref="MovementManager.MoveToManager"/>; without one nothing moves to
/// anything. Called inside the tick: implementations must not allocate.
/// </summary>
public interface IMoveToManager
{
    /// <summary>Per-step update (retail <c>MoveToManager::UseTime</c>).</summary>
    void UseTime();

    /// <summary>The object landed (retail <c>MoveToManager::HitGround</c>).</summary>
    void HitGround();

    /// <summary>True while a move-to runs (retail <c>MoveToManager::is_moving_to</c>).</summary>
    bool IsMovingTo();

    /// <summary>Cancels the move-to with a weenie error code (retail <c>MoveToManager::CancelMoveTo</c>).</summary>
    void CancelMoveTo(MotionError error);
}
