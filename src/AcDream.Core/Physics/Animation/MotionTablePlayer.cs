using System;
using System.Numerics;
using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Animation;

/// <summary>
/// The retail motion table as an <see cref="IMotionPlayer"/>: a <see cref="Animation.MotionTable"/> played by its
/// motion-table manager onto an <see cref="AnimSequence"/> (retail <c>CPartArray</c>'s <c>motion_table_manager</c> and
/// <c>sequence</c>). The interpreter's motions reach <c>MotionTableManager::PerformMovement</c>, which asks
/// <c>CMotionTable::GetObjectSequence</c> for the links and cycle and queues them on the sequence; a motion is done when
/// its animations have ended.
/// </summary>
/// <remarks>
/// <see cref="Objects.Parts.AnimatedPartArray"/> owns one and plays its sequence (animations, root motion, hooks). Set on a
/// <see cref="Objects.Parts.SimplePartArray"/> (<see cref="Objects.Parts.SimplePartArray.MotionPlayer"/>), only the
/// sequence's <see cref="Velocity"/> and <see cref="Omega"/> move the body and its animations are not played, so motions
/// waiting for animations never finish there: use it so only for a table whose motions queue none.
/// Not shareable between objects (it holds one object's state); the <see cref="Animation.MotionTable"/> is.
/// </remarks>
public sealed class MotionTablePlayer : IMotionPlayer
{
    private readonly MotionTableManager _manager;

    /// <summary>Creates a player for <paramref name="table"/> with its own sequence, resolving animations through
    /// <paramref name="animations"/> (null: no animation is played; only the motion data's velocity and omega).</summary>
    /// <param name="table">The motion table (shareable between objects).</param>
    /// <param name="animations">The animations by data id, or null.</param>
    /// <exception cref="ArgumentNullException"><paramref name="table"/> is null.</exception>
    // retail: MotionTableManager::Create (acclient.c:329813), with CPartArray's sequence
    public MotionTablePlayer(MotionTable table, IAnimationSource? animations = null)
    {
        ArgumentNullException.ThrowIfNull(table);
        _manager = new MotionTableManager(table);
        Sequence = new AnimSequence(animations);
    }

    /// <summary>The sequence the table plays onto (retail <c>CPartArray::sequence</c>).</summary>
    public AnimSequence Sequence { get; }

    /// <summary>The motion table (retail <c>MotionTableManager::table</c>).</summary>
    public MotionTable Table => _manager.Table!;

    internal MotionTableManager Manager => _manager;

    /// <summary>The current style (retail <c>MotionState::style</c>).</summary>
    public MotionCommand Style => (MotionCommand)_manager.State.Style;

    /// <summary>The current substate, the cycle playing (retail <c>MotionState::substate</c>).</summary>
    public MotionCommand Substate => (MotionCommand)_manager.State.Substate;

    /// <summary>The substate's speed (retail <c>MotionState::substate_mod</c>).</summary>
    public float SubstateSpeed => _manager.State.SubstateMod;

    /// <summary>Number of modifiers on top of the cycle (side-step, turn, …).</summary>
    public int ModifierCount => _manager.State.ModifierCount;

    /// <summary>Number of actions still playing (retail <c>MotionState</c>'s action list).</summary>
    public int ActionCount => _manager.State.ActionCount;

    /// <summary>Number of motions started and not yet done (retail <c>pending_animations</c>).</summary>
    public int PendingMotionCount => _manager.PendingCount;

    /// <inheritdoc />
    public Vector3 Velocity => Sequence.Velocity;

    /// <inheritdoc />
    public Vector3 Omega => Sequence.Omega;

    /// <inheritdoc />
    // retail: CPartArray::DoInterpretedMotion (acclient.c:326017)
    public MotionError DoInterpretedMotion(MotionCommand motion, in MovementParameters p) =>
        _manager.PerformMovement(MovementType.InterpretedCommand, (uint)motion, p.Speed, Sequence);

    /// <inheritdoc />
    // retail: CPartArray::StopInterpretedMotion (acclient.c:326053)
    public MotionError StopInterpretedMotion(MotionCommand motion, in MovementParameters p) =>
        _manager.PerformMovement(MovementType.StopInterpretedCommand, (uint)motion, p.Speed, Sequence);

    /// <inheritdoc />
    // retail: CPartArray::StopCompletelyInternal (acclient.c:326089)
    public MotionError StopCompletely() => _manager.PerformMovement(MovementType.StopCompletely, 0, 1f, Sequence);

    /// <inheritdoc />
    // retail: CPartArray::InitializeMotionTables (acclient.c:325067)
    public void InitializeMotionTables() => _manager.InitializeState(Sequence);

    /// <inheritdoc />
    // retail: CPartArray::HandleEnterWorld (acclient.c:325115)
    public void RemoveLinkAnimations() => _manager.HandleEnterWorld(Sequence);

    /// <summary>The object left the world: every pending motion is done, unsuccessfully.</summary>
    // retail: CPartArray::HandleExitWorld (acclient.c:325127)
    public void HandleExitWorld() => _manager.HandleExitWorld(Sequence);

    /// <inheritdoc />
    // retail: CPartArray::CheckForCompletedMotions (acclient.c:325095)
    public void CheckForCompletedMotions() => _manager.CheckForCompletedMotions();

    /// <summary>One animation of the sequence ended (the AnimDone hook): the motions waiting for it are done.</summary>
    /// <param name="success">False when the animations were cut short.</param>
    // retail: CPartArray::AnimationDone (acclient.c:325079)
    public void AnimationDone(bool success) => _manager.AnimationDone(success);

    /// <summary>Per-step bookkeeping: the motions waiting for no animation are done.</summary>
    // retail: CPartArray::HandleMovement (acclient.c:325105)
    public void HandleMovement() => _manager.UseTime();

    /// <inheritdoc />
    public bool TryTakeCompletedMotion(out MotionCommand motion, out bool success) =>
        _manager.TryTakeCompletedMotion(out motion, out success);
}
