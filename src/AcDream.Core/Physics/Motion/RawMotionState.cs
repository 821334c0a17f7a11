namespace AcDream.Core.Physics.Motion;

/// <summary>
/// The motion commands as the player gave them, before the interpreter's conversions (retail <c>RawMotionState</c>,
/// PORTAL/canim/CMInterpPrim.c): walk backwards and side-step left stay as given, each with its own hold key.
/// </summary>
public sealed class RawMotionState
{
    /// <summary>Creates the default state: hold key <see cref="HoldKey.None"/>, non-combat style, Ready, every speed 1.</summary>
    // retail: RawMotionState::RawMotionState (acclient.c:332561)
    public RawMotionState() => Reset();

    /// <summary>The hold key that applies to commands given without one (None or Run).</summary>
    public HoldKey CurrentHoldKey { get; set; }

    /// <summary>The stance (style command).</summary>
    public MotionCommand CurrentStyle { get; set; }

    /// <summary>The forward command as given (Ready, WalkForward, WalkBackwards...).</summary>
    public MotionCommand ForwardCommand { get; set; }

    /// <summary>The hold key given with the forward command (<see cref="HoldKey.Invalid"/>: the current one).</summary>
    public HoldKey ForwardHoldKey { get; set; }

    /// <summary>Speed of the forward command.</summary>
    /// <exception cref="System.ArgumentException">The value is NaN, infinite or beyond ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/> (state unchanged).</exception>
    public float ForwardSpeed
    {
        get => _forwardSpeed;
        set => _forwardSpeed = MotionChecks.Speed(value);
    }

    private float _forwardSpeed;

    /// <summary>The side-step command as given (0, SideStepRight or SideStepLeft).</summary>
    public MotionCommand SidestepCommand { get; set; }

    /// <summary>The hold key given with the side-step.</summary>
    public HoldKey SidestepHoldKey { get; set; }

    /// <summary>Speed of the side-step.</summary>
    /// <exception cref="System.ArgumentException">The value is NaN, infinite or beyond ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/> (state unchanged).</exception>
    public float SidestepSpeed
    {
        get => _sidestepSpeed;
        set => _sidestepSpeed = MotionChecks.Speed(value);
    }

    private float _sidestepSpeed;

    /// <summary>The turn command as given (0, TurnRight or TurnLeft).</summary>
    public MotionCommand TurnCommand { get; set; }

    /// <summary>The hold key given with the turn.</summary>
    public HoldKey TurnHoldKey { get; set; }

    /// <summary>Speed of the turn.</summary>
    /// <exception cref="System.ArgumentException">The value is NaN, infinite or beyond ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/> (state unchanged).</exception>
    public float TurnSpeed
    {
        get => _turnSpeed;
        set => _turnSpeed = MotionChecks.Speed(value);
    }

    private float _turnSpeed;

    /// <summary>The queued actions.</summary>
    public ActionList Actions { get; } = new();

    /// <summary>Puts the state back to its constructed default (and empties the actions).</summary>
    public void Reset()
    {
        CurrentHoldKey = HoldKey.None;
        CurrentStyle = MotionCommand.NonCombat;
        ForwardCommand = MotionCommand.Ready;
        ForwardHoldKey = HoldKey.Invalid;
        ForwardSpeed = 1f;
        SidestepCommand = MotionCommand.None;
        SidestepHoldKey = HoldKey.Invalid;
        SidestepSpeed = 1f;
        TurnCommand = MotionCommand.None;
        TurnHoldKey = HoldKey.Invalid;
        TurnSpeed = 1f;
        Actions.Clear();
    }

    /// <summary>Copies everything, the actions included.</summary>
    /// <exception cref="System.ArgumentNullException"><paramref name="rhs"/> is null.</exception>
    // retail: RawMotionState::operator= (acclient.c:332923)
    public void CopyFrom(RawMotionState rhs)
    {
        System.ArgumentNullException.ThrowIfNull(rhs);
        CurrentHoldKey = rhs.CurrentHoldKey;
        CurrentStyle = rhs.CurrentStyle;
        ForwardCommand = rhs.ForwardCommand;
        ForwardHoldKey = rhs.ForwardHoldKey;
        ForwardSpeed = rhs.ForwardSpeed;
        SidestepCommand = rhs.SidestepCommand;
        SidestepHoldKey = rhs.SidestepHoldKey;
        SidestepSpeed = rhs.SidestepSpeed;
        TurnCommand = rhs.TurnCommand;
        TurnHoldKey = rhs.TurnHoldKey;
        TurnSpeed = rhs.TurnSpeed;
        Actions.CopyFrom(rhs.Actions);
    }

    /// <summary>Records a started command with its hold key (none when the parameters set the hold key).</summary>
    /// <exception cref="System.ArgumentException"><paramref name="p"/> is <c>default(MovementParameters)</c> or its speed
    /// is NaN, infinite or beyond ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/> (state unchanged).</exception>
    // retail: RawMotionState::ApplyMotion (acclient.c:332851)
    public void ApplyMotion(MotionCommand motion, in MovementParameters p)
    {
        MotionChecks.Check(p);
        HoldKey key = p.Has(MovementParameterFlags.SetHoldKey) ? HoldKey.Invalid : p.HoldKeyToApply;
        switch (motion)
        {
            case MotionCommand.SideStepRight:
            case MotionCommand.SideStepLeft:
                SidestepCommand = motion;
                SidestepHoldKey = key;
                SidestepSpeed = p.Speed;
                break;
            case MotionCommand.TurnRight:
            case MotionCommand.TurnLeft:
                TurnCommand = motion;
                TurnHoldKey = key;
                TurnSpeed = p.Speed;
                break;
            default:
                if (((uint)motion & (uint)MotionCommandClass.Substate) != 0)
                {
                    if (motion != MotionCommand.RunForward)
                    {
                        ForwardCommand = motion;
                        ForwardHoldKey = key;
                        ForwardSpeed = p.Speed;
                    }
                }
                else if (((uint)motion & (uint)MotionCommandClass.Style) == 0)
                {
                    if (((uint)motion & (uint)MotionCommandClass.Action) != 0)
                    {
                        AddAction(motion, p.Speed, p.ActionStamp, p.Has(MovementParameterFlags.Autonomous));
                    }
                }
                else if (CurrentStyle != motion)
                {
                    ForwardCommand = MotionCommand.Ready;
                    CurrentStyle = motion;
                }

                break;
        }
    }

    /// <summary>Records a stopped command.</summary>
    // retail: RawMotionState::RemoveMotion (acclient.c:332494)
    public void RemoveMotion(MotionCommand motion)
    {
        switch (motion)
        {
            case MotionCommand.SideStepRight:
            case MotionCommand.SideStepLeft:
                SidestepCommand = MotionCommand.None;
                break;
            case MotionCommand.TurnRight:
            case MotionCommand.TurnLeft:
                TurnCommand = MotionCommand.None;
                break;
            default:
                if (((uint)motion & (uint)MotionCommandClass.Substate) != 0)
                {
                    if (motion == ForwardCommand)
                    {
                        ForwardCommand = MotionCommand.Ready;
                        ForwardSpeed = 1f;
                    }
                }
                else if (((uint)motion & (uint)MotionCommandClass.Style) != 0 && motion == CurrentStyle)
                {
                    CurrentStyle = MotionCommand.NonCombat;
                }

                break;
        }
    }

    /// <summary>Queues an action.</summary>
    /// <exception cref="System.ArgumentException"><paramref name="speed"/> is NaN, infinite or beyond
    /// ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/> (state unchanged). A full list ignores the action.</exception>
    // retail: RawMotionState::AddAction (acclient.c:332581)
    public void AddAction(MotionCommand action, float speed, uint stamp, bool autonomous) =>
        Actions.Add(new ActionNode(action, speed, stamp, autonomous));

    /// <summary>Removes the oldest action and returns its command (<see cref="MotionCommand.None"/> when none).</summary>
    // retail: RawMotionState::RemoveAction (acclient.c:332615)
    public MotionCommand RemoveAction() => Actions.RemoveFirst();

    /// <summary>The state's commands by name (an unnamed one as its hex id), their speeds and the number of queued actions.</summary>
    public override string ToString() => string.Create(System.Globalization.CultureInfo.InvariantCulture,
        $"RawMotionState {{ CurrentHoldKey = {CurrentHoldKey}, CurrentStyle = {MotionCommandText.Format(CurrentStyle)}, "
        + $"ForwardCommand = {MotionCommandText.Format(ForwardCommand)}, ForwardSpeed = {ForwardSpeed}, "
        + $"SidestepCommand = {MotionCommandText.Format(SidestepCommand)}, SidestepSpeed = {SidestepSpeed}, "
        + $"TurnCommand = {MotionCommandText.Format(TurnCommand)}, TurnSpeed = {TurnSpeed}, Actions = {Actions.Count} }}");
}
