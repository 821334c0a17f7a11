namespace AcDream.Core.Physics.Motion;

/// <summary>
/// The result of a motion call (retail's weenie error numbers, <c>WERROR</c>; <see cref="None"/> is success). Names are
/// those of the server protocol's error list; a number without a name prints as itself.
/// </summary>
public enum MotionError : uint
{
    /// <summary>Success.</summary>
    None = 0,

    /// <summary>The object's part array has no motion table, or it has no part array (7). (Retail's
    /// <c>CPhysicsObj::DoMotion</c> also answers 7 for an object without a movement manager; here that is
    /// <see cref="NoMovementManager"/>.)</summary>
    NoMotionTable = 7,

    /// <summary>Non-retail: the object has no retail movement manager (none yet, or a client's own), so
    /// <see cref="Objects.PhysicsObj.DoMotion"/> / <see cref="Objects.PhysicsObj.StopMotion"/> started nothing (retail
    /// answers 7, <see cref="NoMotionTable"/>). <see cref="Objects.PhysicsObj.GetOrCreateMotionInterpreter"/> creates one.
    /// 0x10007, outside retail's error numbers.</summary>
    NoMovementManager = 0x10007,

    /// <summary>The interpreter has no physics object (8).</summary>
    NoPhysicsObject = 8,

    /// <summary>The object's movement manager is not the retail one, so it has no motion interpreter to play a move-to's
    /// motions (0xB). Retail <c>WeenieError::NoMotionInterpreter</c>, from <c>MoveToManager::_DoMotion</c>.</summary>
    NoMotionInterpreter = 0xB,

    /// <summary>The object is in the air and may not move or jump (0x24).</summary>
    YouCantJumpWhileInTheAir = 0x24,

    /// <summary>Crouching is refused outside the non-combat style (0x3F).</summary>
    CantCrouchInCombat = 0x3F,

    /// <summary>Sitting is refused outside the non-combat style (0x40).</summary>
    CantSitInCombat = 0x40,

    /// <summary>Lying down is refused outside the non-combat style (0x41).</summary>
    CantLieDownInCombat = 0x41,

    /// <summary>Chat emotes are refused outside the non-combat style (0x42).</summary>
    CantChatEmoteInCombat = 0x42,

    /// <summary>The action was cancelled: the error a move-to is cancelled with when the object unsticks (0x36).</summary>
    ActionCancelled = 0x36,

    /// <summary>The target of a running move-to or turn-to left (a report with a status other than Ok after the first,
    /// 0x37). Retail <c>WeenieError::ObjectGone</c>, from <c>MoveToManager::HandleUpdateTarget</c>.</summary>
    ObjectGone = 0x37,

    /// <summary>The target of a move-to or turn-to was never found (its first report is not Ok, e.g. timed out: 0x38).
    /// Retail <c>WeenieError::NoObject</c>, from <c>MoveToManager::HandleUpdateTarget</c>.</summary>
    NoObject = 0x38,

    /// <summary>The object teleported: the error a move-to is cancelled with on a teleport (0x3C).</summary>
    ITeleported = 0x3C,

    /// <summary>A move-to went farther than its fail distance from where it started (0x3D). Retail
    /// <c>WeenieError::YouChargedTooFar</c>, from <c>MoveToManager::HandleMoveToPosition</c>.</summary>
    YouChargedTooFar = 0x3D,

    /// <summary>The motion table has no link, cycle or modifier for the requested motion (0x43). Retail
    /// <c>WeenieError::NoMtableData</c>, returned by <c>MotionTableManager::PerformMovement</c> (acclient.c:330205) when
    /// <c>CMotionTable::DoObjectMotion</c> or <c>StopObjectMotion</c> fails.</summary>
    NoMotionTableData = 0x43,

    /// <summary>Six actions are already queued (0x45).</summary>
    TooManyActions = 0x45,

    /// <summary>General failure: no part array, fully constrained, or the jump stamina cost was refused (0x47).</summary>
    GeneralMovementFailure = 0x47,

    /// <summary>The current motion does not allow a jump (0x48).</summary>
    YouCantJumpFromThisPosition = 0x48,

    /// <summary>The character is too loaded down to jump (0x49).</summary>
    CantJumpLoadedDown = 0x49,
}
