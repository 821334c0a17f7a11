using System.Numerics;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// A speed-only stand-in for a motion-table player (<see cref="IMotionPlayer"/>), for a client without the real motion
/// tables: not retail's table or its player, only the locomotion cycles and modifiers of a humanoid at retail's own speeds,
/// with no animations (every motion completes at once). Walk forward 3.12 m/s, run forward 4 m/s, side-step
/// 1.25 m/s and turn 1.5 rad/s, each times its speed, so the body moves exactly as fast as the interpreter's
/// <see cref="MotionInterp.StateVelocity"/> says.
/// </summary>
/// <remarks>
/// <para>What is retail: the velocity and omega arithmetic of <c>add_motion</c> and <c>combine_motion</c>
/// (acclient.c:337430, 337476: speed times the motion data, rounded to float, summed in float) and the rule that a new
/// substate replaces the cycle while the modifiers (side-step, turn) are re-applied on top (<c>CMotionTable::re_modify</c>,
/// acclient.c:337285). What stands in for the data: one cycle velocity per substate and one velocity or omega per
/// modifier, instead of the motion table file's entries; no link animations, so no motion waits for one.</para>
/// <para>The speeds are those the interpreter itself assumes (<see cref="MotionInterp.WalkAnimSpeed"/>,
/// <see cref="MotionInterp.RunAnimSpeed"/>, <see cref="MotionInterp.SidestepAnimSpeed"/>); the turn rate
/// <see cref="TurnAnimSpeed"/> is not in the client code: retail's omega is <c>speed_mod × MotionData.omega</c>
/// (<c>add_motion</c> acclient.c:337430, <c>combine_motion</c> 337476), so it is the humanoid motion data's value. The one
/// reading of the real humanoid table found (table 0x09000001, TurnRight modifier, read by the acdream client's installed-data
/// test) gives −1.5 rad/s; that is the value used. Retail may also play a TurnRight cycle when turning in place
/// (<c>CMotionTable::GetObjectSequence</c> 337318, <c>is_allowed</c> 337559); the stand-in keeps turning a modifier.</para>
/// <para>Errors: a motion the table has no entry for gives <see cref="MotionError.NoMotionTableData"/> (0x43), as retail's
/// <c>MotionTableManager::PerformMovement</c> returns when <c>DoObjectMotion</c> / <c>StopObjectMotion</c> fail
/// (acclient.c:330205–330240).</para>
/// </remarks>
public sealed class SpeedOnlyMotionPlayer : IMotionPlayer
{
    /// <summary>Turn rate of <see cref="MotionCommand.TurnRight"/> at speed 1, rad/s: 1.5 (bits 0x3FC00000), the humanoid
    /// motion table's TurnRight omega as read from the installed data (data-derived, not a client constant).
    /// TurnRight turns clockwise seen from above, so its omega about +Z is negative.</summary>
    public const float TurnAnimSpeed = 1.5f;

    private const int CompletedCapacity = 32;
    private readonly MotionCommand[] _completed = new MotionCommand[CompletedCapacity];
    private int _completedHead;
    private int _completedCount;
    private MotionCommand _style = MotionCommand.NonCombat;
    private MotionCommand _substate = MotionCommand.Ready;
    private float _substateMod = 1f;
    private float _sidestepMod;
    private bool _sidestep;
    private float _turnMod;
    private bool _turn;

    /// <summary>The current style.</summary>
    public MotionCommand Style => _style;

    /// <summary>The current substate (cycle).</summary>
    public MotionCommand Substate => _substate;

    /// <summary>The current substate's speed.</summary>
    public float SubstateSpeed => _substateMod;

    /// <inheritdoc />
    public Vector3 Velocity { get; private set; }

    /// <inheritdoc />
    public Vector3 Omega { get; private set; }

    /// <inheritdoc />
    public MotionError DoInterpretedMotion(MotionCommand motion, in MovementParameters p)
    {
        float speed = p.Speed;
        // Side-step and turn first: their ids (0x65...) carry the substate bit too.
        if (motion == MotionCommand.SideStepRight)
        {
            _sidestep = true;
            _sidestepMod = speed;
        }
        else if (motion == MotionCommand.TurnRight)
        {
            _turn = true;
            _turnMod = speed;
        }
        else if (((uint)motion & (uint)MotionCommandClass.Style) != 0)
        {
            _style = motion;
            _substate = MotionCommand.Ready;
            _substateMod = 1f;
        }
        else if (((uint)motion & (uint)MotionCommandClass.Substate) != 0)
        {
            _substate = motion;
            _substateMod = speed;
        }
        else if (((uint)motion & (uint)MotionCommandClass.Action) == 0)
        {
            return MotionError.NoMotionTableData;
        }

        Recompute();
        Complete(motion);
        return MotionError.None;
    }

    /// <inheritdoc />
    public MotionError StopInterpretedMotion(MotionCommand motion, in MovementParameters p)
    {
        if (motion == MotionCommand.SideStepRight && _sidestep)
        {
            _sidestep = false;
        }
        else if (motion == MotionCommand.TurnRight && _turn)
        {
            _turn = false;
        }
        else if (((uint)motion & (uint)MotionCommandClass.Substate) != 0 && motion == _substate)
        {
            _substate = MotionCommand.Ready;
            _substateMod = 1f;
        }
        else
        {
            return MotionError.NoMotionTableData;
        }

        Recompute();
        Complete(MotionCommand.Ready);
        return MotionError.None;
    }

    /// <inheritdoc />
    public MotionError StopCompletely()
    {
        _substate = MotionCommand.Ready;
        _substateMod = 1f;
        _sidestep = false;
        _turn = false;
        Recompute();
        Complete(MotionCommand.Ready);
        return MotionError.None;
    }

    /// <inheritdoc />
    public void InitializeMotionTables()
    {
        _style = MotionCommand.NonCombat;
        _substate = MotionCommand.Ready;
        _substateMod = 1f;
        _sidestep = false;
        _turn = false;
        Recompute();
        // The default state's cycle is a started motion too (MotionTableManager::initialize_state queues it).
        Complete(MotionCommand.Ready);
    }

    /// <inheritdoc />
    public void RemoveLinkAnimations()
    {
    }

    /// <inheritdoc />
    public bool TryTakeCompletedMotion(out MotionCommand motion, out bool success)
    {
        success = true;
        if (_completedCount == 0)
        {
            motion = 0;
            return false;
        }

        motion = _completed[_completedHead];
        _completedHead = (_completedHead + 1) % CompletedCapacity;
        _completedCount--;
        return true;
    }

    private void Complete(MotionCommand motion)
    {
        // non-retail: a bounded completion queue; when full the oldest completion is dropped (it is long past).
        if (_completedCount == CompletedCapacity)
        {
            _completedHead = (_completedHead + 1) % CompletedCapacity;
            _completedCount--;
        }

        _completed[(_completedHead + _completedCount) % CompletedCapacity] = motion;
        _completedCount++;
    }

    // The cycle's velocity (add_motion: speed * data, stored as float), then each modifier combined on top
    // (combine_motion: speed * data as float, added in float).
    private void Recompute()
    {
        float cycleY = _substate switch
        {
            MotionCommand.WalkForward => (float)((double)_substateMod * MotionInterp.WalkAnimSpeed),
            MotionCommand.RunForward => (float)((double)_substateMod * MotionInterp.RunAnimSpeed),
            _ => 0f,
        };

        var v = new Vector3(0f, cycleY, 0f);
        var w = Vector3.Zero;
        if (_sidestep)
        {
            v = new Vector3(v.X + (float)((double)_sidestepMod * MotionInterp.SidestepAnimSpeed), v.Y, v.Z);
        }

        if (_turn)
        {
            w = new Vector3(w.X, w.Y, w.Z + (float)((double)_turnMod * -(double)TurnAnimSpeed));
        }

        Velocity = v;
        Omega = w;
    }
}
