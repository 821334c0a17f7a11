namespace AcDream.Core.Physics.Motion;

/// <summary>
/// The motion an object is actually performing, after the hold key and the backwards, side-step and turn conversions
/// (retail <c>InterpretedMotionState</c>, PORTAL/canim/CMInterpPrim.c). This is what a MovementEvent carries for a
/// remote object.
/// </summary>
public sealed class InterpretedMotionState
{
    /// <summary>Creates the default state: non-combat style, <see cref="MotionCommand.Ready"/>, no side-step, no turn,
    /// every speed 1.</summary>
    // retail: InterpretedMotionState::InterpretedMotionState (acclient.c:332641)
    public InterpretedMotionState() => Reset();

    /// <summary>The stance (style command).</summary>
    public MotionCommand CurrentStyle { get; set; }

    /// <summary>The forward substate (Ready, WalkForward, RunForward, Falling...).</summary>
    public MotionCommand ForwardCommand { get; set; }

    /// <summary>Speed of <see cref="ForwardCommand"/> (negative for backwards; the run rate when running).</summary>
    /// <exception cref="System.ArgumentException">The value is NaN, infinite or beyond ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/>
    /// (state unchanged). The interpreter's own state may hold more (a run is the walk speed times the run rate).</exception>
    public float ForwardSpeed
    {
        get => _forwardSpeed;
        set => _forwardSpeed = MotionChecks.Speed(value);
    }

    private float _forwardSpeed;

    /// <summary>The side-step modifier (0 or <see cref="MotionCommand.SideStepRight"/>).</summary>
    public MotionCommand SidestepCommand { get; set; }

    /// <summary>Speed of the side-step (negative is left).</summary>
    /// <exception cref="System.ArgumentException">The value is NaN, infinite or beyond ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/>
    /// (state unchanged). The interpreter's own state may hold more (a run is the walk speed times the run rate).</exception>
    public float SidestepSpeed
    {
        get => _sidestepSpeed;
        set => _sidestepSpeed = MotionChecks.Speed(value);
    }

    private float _sidestepSpeed;

    /// <summary>The turn modifier (0 or <see cref="MotionCommand.TurnRight"/>).</summary>
    public MotionCommand TurnCommand { get; set; }

    /// <summary>Speed of the turn (negative is left).</summary>
    /// <exception cref="System.ArgumentException">The value is NaN, infinite or beyond ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/>
    /// (state unchanged). The interpreter's own state may hold more (a run is the walk speed times the run rate).</exception>
    public float TurnSpeed
    {
        get => _turnSpeed;
        set => _turnSpeed = MotionChecks.Speed(value);
    }

    private float _turnSpeed;

    /// <summary>The three speeds as the interpreter's conversions give them (<c>apply_raw_movement</c>), unchecked.</summary>
    internal void SetSpeedsInternal(float forward, float sidestep, float turn)
    {
        _forwardSpeed = forward;
        _sidestepSpeed = sidestep;
        _turnSpeed = turn;
    }

    /// <summary>The queued actions; their number, <see cref="ActionList.Count"/>, is retail's
    /// <c>InterpretedMotionState::GetNumActions</c>.</summary>
    public ActionList Actions { get; } = new();

    /// <summary>Puts the state back to its constructed default (and empties the actions).</summary>
    public void Reset()
    {
        CurrentStyle = MotionCommand.NonCombat;
        ForwardCommand = MotionCommand.Ready;
        ForwardSpeed = 1f;
        SidestepCommand = MotionCommand.None;
        SidestepSpeed = 1f;
        TurnCommand = MotionCommand.None;
        TurnSpeed = 1f;
        Actions.Clear();
    }

    /// <summary>Copies the style, the three commands and their speeds (not the actions).</summary>
    /// <exception cref="System.ArgumentNullException"><paramref name="rhs"/> is null.</exception>
    // retail: InterpretedMotionState::copy_movement_from (acclient.c:332524)
    public void CopyMovementFrom(InterpretedMotionState rhs)
    {
        System.ArgumentNullException.ThrowIfNull(rhs);
        // The fields, not the setters: a state's own speeds always copy (the interpreter's may exceed MaxMotionSpeed).
        CurrentStyle = rhs.CurrentStyle;
        ForwardCommand = rhs.ForwardCommand;
        _forwardSpeed = rhs._forwardSpeed;
        SidestepCommand = rhs.SidestepCommand;
        _sidestepSpeed = rhs._sidestepSpeed;
        TurnCommand = rhs.TurnCommand;
        _turnSpeed = rhs._turnSpeed;
    }

    /// <summary>Copies everything, the actions included.</summary>
    /// <exception cref="System.ArgumentNullException"><paramref name="rhs"/> is null.</exception>
    // retail: InterpretedMotionState::operator= (acclient.c:332682)
    public void CopyFrom(InterpretedMotionState rhs)
    {
        CopyMovementFrom(rhs);
        Actions.CopyFrom(rhs.Actions);
    }

    /// <summary>Records a started motion: turn, side-step, substate, style or action.</summary>
    /// <exception cref="System.ArgumentException"><paramref name="p"/> is <c>default(MovementParameters)</c> or its speed
    /// is NaN, infinite or beyond ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/> (state unchanged).</exception>
    // retail: InterpretedMotionState::ApplyMotion (acclient.c:332758)
    public void ApplyMotion(MotionCommand motion, in MovementParameters p)
    {
        MotionChecks.Check(p);
        ApplyMotionInternal(motion, p);
    }

    // The body of ApplyMotion, for the interpreter: its speeds are its own conversions of checked ones (a run's may exceed
    // MaxMotionSpeed), so they are stored without the setters' check.
    // retail: InterpretedMotionState::ApplyMotion (acclient.c:332758)
    internal void ApplyMotionInternal(MotionCommand motion, in MovementParameters p)
    {
        if (motion == MotionCommand.TurnRight)
        {
            TurnCommand = MotionCommand.TurnRight;
            _turnSpeed = p.Speed;
        }
        else if (motion == MotionCommand.SideStepRight)
        {
            SidestepCommand = MotionCommand.SideStepRight;
            _sidestepSpeed = p.Speed;
        }
        else if (((uint)motion & (uint)MotionCommandClass.Substate) != 0)
        {
            ForwardCommand = motion;
            _forwardSpeed = p.Speed;
        }
        else if (((uint)motion & (uint)MotionCommandClass.Style) == 0)
        {
            if (((uint)motion & (uint)MotionCommandClass.Action) != 0)
            {
                AddAction(motion, p.Speed, p.ActionStamp, p.Has(MovementParameterFlags.Autonomous));
            }
        }
        else
        {
            ForwardCommand = MotionCommand.Ready;
            CurrentStyle = motion;
        }
    }

    /// <summary>Records a stopped motion.</summary>
    // retail: InterpretedMotionState::RemoveMotion (acclient.c:332536)
    public void RemoveMotion(MotionCommand motion)
    {
        if (motion == MotionCommand.TurnRight)
        {
            TurnCommand = MotionCommand.None;
        }
        else if (motion == MotionCommand.SideStepRight)
        {
            SidestepCommand = MotionCommand.None;
        }
        else if (((uint)motion & (uint)MotionCommandClass.Substate) != 0)
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
    }

    /// <summary>Queues an action.</summary>
    /// <exception cref="System.ArgumentException"><paramref name="speed"/> is NaN, infinite or beyond
    /// ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/> (state unchanged; the action would be played at that speed after
    /// the state's movement was applied). A full list ignores the action.</exception>
    // retail: InterpretedMotionState::AddAction (acclient.c:332724)
    public void AddAction(MotionCommand action, float speed, uint stamp, bool autonomous) =>
        Actions.Add(new ActionNode(action, speed, stamp, autonomous));

    /// <summary>Removes the oldest action and returns its command (<see cref="MotionCommand.None"/> when none).</summary>
    // retail: InterpretedMotionState::RemoveAction (acclient.c:332788)
    public MotionCommand RemoveAction() => Actions.RemoveFirst();

    /// <summary>The state's commands by name (an unnamed one as its hex id), their speeds and the number of queued actions.</summary>
    public override string ToString() => string.Create(System.Globalization.CultureInfo.InvariantCulture,
        $"InterpretedMotionState {{ CurrentStyle = {MotionCommandText.Format(CurrentStyle)}, "
        + $"ForwardCommand = {MotionCommandText.Format(ForwardCommand)}, ForwardSpeed = {ForwardSpeed}, "
        + $"SidestepCommand = {MotionCommandText.Format(SidestepCommand)}, SidestepSpeed = {SidestepSpeed}, "
        + $"TurnCommand = {MotionCommandText.Format(TurnCommand)}, TurnSpeed = {TurnSpeed}, Actions = {Actions.Count} }}");
}
