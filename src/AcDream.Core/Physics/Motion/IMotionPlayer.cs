using System.Numerics;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// The seam between the motion interpreter and the animation: what plays an object's motions (not the motion table, the data,
/// which is <see cref="Animation.MotionTable"/>, retail <c>CMotionTable</c>, but a player of one): retail's motion-table
/// manager, its motion table and the sequence they drive (retail <c>CPartArray::DoInterpretedMotion</c> -> <c>MotionTableManager::PerformMovement</c> ->
/// <c>CMotionTable::GetObjectSequence</c>, which sets the sequence's velocity and omega from the motion data). The part
/// array exposes it as <see cref="Objects.Parts.IPartArray.MotionPlayer"/> and moves the body by
/// <see cref="Velocity"/> and <see cref="Omega"/> each step (<c>CSequence::apply_physics</c>).
/// <see cref="Animation.MotionTablePlayer"/> plays a retail motion table read from its bytes; <see cref="SpeedOnlyMotionPlayer"/>
/// is a stand-in that moves the body at retail's speeds without one; a client may plug in its own.
/// </summary>
/// <remarks>Called inside the tick: implementations must not allocate.</remarks>
public interface IMotionPlayer
{
    /// <summary>Starts <paramref name="motion"/> (a style, substate, modifier or action) at <c>p.Speed</c>.</summary>
    /// <returns><see cref="MotionError.None"/> on success, else the error.</returns>
    // retail seam: CPartArray::DoInterpretedMotion (acclient.c:326017)
    MotionError DoInterpretedMotion(MotionCommand motion, in MovementParameters p);

    /// <summary>Stops <paramref name="motion"/>.</summary>
    /// <returns><see cref="MotionError.None"/> on success, else the error.</returns>
    // retail seam: CPartArray::StopInterpretedMotion (acclient.c:326053)
    MotionError StopInterpretedMotion(MotionCommand motion, in MovementParameters p);

    /// <summary>Stops everything: back to the style's default substate with no modifiers.</summary>
    /// <returns><see cref="MotionError.None"/>.</returns>
    // retail seam: CPartArray::StopCompletelyInternal (acclient.c:326089)
    MotionError StopCompletely();

    /// <summary>Puts the table in its default state (non-combat, Ready, nothing moving).</summary>
    // retail seam: CPartArray::InitializeMotionTables
    void InitializeMotionTables();

    /// <summary>Drops the link (transition) animations still playing.</summary>
    // retail seam: CPartArray::HandleEnterWorld (acclient.c:325115), which CPhysicsObj::RemoveLinkAnimations calls
    void RemoveLinkAnimations();

    /// <summary>Reports done the started motions that wait for no animation (called before the finished motions are taken
    /// with <see cref="TryTakeCompletedMotion"/>). Does nothing by default: a table that completes each motion at once
    /// (such as <see cref="SpeedOnlyMotionPlayer"/>) has nothing to check.</summary>
    // retail seam: CPartArray::CheckForCompletedMotions (acclient.c:325095) -> MotionTableManager::CheckForCompletedMotions
    void CheckForCompletedMotions()
    {
    }

    /// <summary>Takes the oldest started motion whose animations have finished, in start order.</summary>
    /// <returns>False when none has finished.</returns>
    // retail seam: MotionTableManager::CheckForCompletedMotions (acclient.c:329959)
    bool TryTakeCompletedMotion(out MotionCommand motion, out bool success);

    /// <summary>The sequence's velocity in the object's local axes, m/s (retail <c>CSequence::velocity</c>).</summary>
    Vector3 Velocity { get; }

    /// <summary>The sequence's angular velocity in the object's local axes, rad/s (retail <c>CSequence::omega</c>).</summary>
    Vector3 Omega { get; }
}
