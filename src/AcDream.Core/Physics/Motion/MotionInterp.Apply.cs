using System;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Motion;

// The conversions (adjust_motion, apply_run_to_command), the raw and interpreted states re-applied (apply_raw_movement,
// apply_interpreted_movement, move_to_interpreted_state) and the hold keys that re-apply them.
public sealed partial class MotionInterp
{
    /// <summary>
    /// Converts a command in place (only for a creature or an object with no weenie): turn left becomes turn right at
    /// negative speed, walk backwards becomes walk forward at -0.65 speed, side-steps become side-step right at ±1.248
    /// speed; then, with the run key (the given one, or the raw state's when <see cref="HoldKey.Invalid"/>),
    /// <see cref="ApplyRunToCommand"/>. A run forward is left alone.
    /// </summary>
    /// <param name="motion">The command, converted in place.</param>
    /// <param name="speed">Its speed, converted in place: any float (a pure conversion; nothing is stored, so there is no
    /// domain to check; a speed handed on to the interpreter's entries must be within ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/>).</param>
    /// <param name="key">The hold key; <see cref="HoldKey.Invalid"/> takes the raw state's.</param>
    // retail: CMotionInterp::adjust_motion (acclient.c:343745)
    public void AdjustMotion(ref MotionCommand motion, ref float speed, HoldKey key)
    {
        if (_weenieObj is not null && !_weenieObj.IsCreature)
        {
            return;
        }

        switch (motion)
        {
            case MotionCommand.TurnLeft:
                motion = MotionCommand.TurnRight;
                speed = (float)(speed * -1.0);
                break;
            case MotionCommand.RunForward:
                return;
            case MotionCommand.WalkBackwards:
                motion = MotionCommand.WalkForward;
                speed = (float)(-(double)BackwardsFactor * speed);
                break;
            case MotionCommand.SideStepRight:
                speed = (float)(SidestepSpeedRatio * speed);
                break;
            case MotionCommand.SideStepLeft:
                motion = MotionCommand.SideStepRight;
                speed = (float)(speed * -1.0);
                speed = (float)(SidestepSpeedRatio * speed);
                break;
        }

        if (key == HoldKey.Invalid)
        {
            key = RawState.CurrentHoldKey;
        }

        if (key == HoldKey.Run)
        {
            ApplyRunToCommand(ref motion, ref speed);
        }
    }

    /// <summary>Applies the run key: a walk forward (at positive speed) becomes a run, every walk speed is multiplied by
    /// the run rate; a turn is 1.5 times faster; a side-step is multiplied by the run rate and clamped to ±3.</summary>
    /// <param name="motion">The command, converted in place.</param>
    /// <param name="speed">Its speed, converted in place: any float (a pure conversion; nothing is stored).</param>
    // retail: CMotionInterp::apply_run_to_command (acclient.c:343438)
    public void ApplyRunToCommand(ref MotionCommand motion, ref float speed)
    {
        double rate = RunRate();
        switch (motion)
        {
            case MotionCommand.WalkForward:
                if (speed > 0.0)
                {
                    motion = MotionCommand.RunForward;
                }

                speed = (float)(rate * speed);
                break;
            case MotionCommand.TurnRight:
                speed = (float)(RunTurnFactor * speed);
                break;
            case MotionCommand.SideStepRight:
                double v = rate * speed;
                speed = (float)v;
                if (Math.Abs(v) > MaxSidestepAnimRate)
                {
                    speed = v <= 0.0 ? (float)(-1.0 * MaxSidestepAnimRate) : (float)(1.0 * MaxSidestepAnimRate);
                }

                break;
        }
    }

    /// <summary>Copies the raw state into the interpreted state, converts its three commands with their hold keys, and
    /// applies the result.</summary>
    // retail: CMotionInterp::apply_raw_movement (acclient.c:344258)
    public void ApplyRawMovement(bool cancelMoveTo, bool disallowJump)
    {
        if (_physicsObj is null)
        {
            return;
        }

        RawMotionState r = RawState;
        InterpretedMotionState s = InterpretedState;
        s.CurrentStyle = r.CurrentStyle;
        s.ForwardCommand = r.ForwardCommand;
        s.SidestepCommand = r.SidestepCommand;
        s.TurnCommand = r.TurnCommand;

        // The conversions may go beyond MaxMotionSpeed (a run is the walk speed times the run rate): stored unchecked.
        MotionCommand c = s.ForwardCommand;
        float forward = r.ForwardSpeed;
        AdjustMotion(ref c, ref forward, r.ForwardHoldKey);
        s.ForwardCommand = c;

        c = s.SidestepCommand;
        float side = r.SidestepSpeed;
        AdjustMotion(ref c, ref side, r.SidestepHoldKey);
        s.SidestepCommand = c;

        c = s.TurnCommand;
        float turn = r.TurnSpeed;
        AdjustMotion(ref c, ref turn, r.TurnHoldKey);
        s.TurnCommand = c;
        s.SetSpeedsInternal(forward, side, turn);

        ApplyInterpretedMovement(cancelMoveTo, disallowJump);
    }

    /// <summary>
    /// Sends the interpreted state to the motion table without changing it: the style; then on the ground the forward
    /// command and the side-step (or its stop), or Ready while a standing long jump charges; in the air Falling; then the
    /// turn (or its stop). A run's speed becomes <see cref="MyRunRate"/>.
    /// </summary>
    // retail: CMotionInterp::apply_interpreted_movement (acclient.c:344146)
    public void ApplyInterpretedMovement(bool cancelMoveTo, bool disallowJump)
    {
        PhysicsObj? obj = _physicsObj;
        if (obj is null)
        {
            return;
        }

        var p = new MovementParameters();
        // 0xFFFD37FF clears set-hold-key, modify-interpreted-state, cancel-move-to and disable-jump-during-link.
        p.Flags = (MovementParameterFlags)(((uint)p.Flags & 0xFFFD37FFu)
                                           | (((cancelMoveTo ? 1u : 0u) | (4u * (disallowJump ? 1u : 0u))) << 15));
        InterpretedMotionState s = InterpretedState;
        // non-retail: a run speed outside the run rate's domain (0, MaxRunRate] is not taken as the run rate (retail takes
        // any; at zero or below the state velocity of a standing object is NaN). The entries refuse such a state; this
        // keeps a client's own hand-edited InterpretedState from reaching the rate.
        if (s.ForwardCommand == MotionCommand.RunForward && MotionChecks.IsRunRateInDomain(s.ForwardSpeed))
        {
            _myRunRate = s.ForwardSpeed;
        }

        DoInterpretedMotionUnchecked(s.CurrentStyle, p);
        if (ContactAllowsMove(s.ForwardCommand))
        {
            if (StandingLongJump)
            {
                p.Speed = 1f;
                DoInterpretedMotionUnchecked(MotionCommand.Ready, p);
                StopInterpretedMotionUnchecked(MotionCommand.SideStepRight, p);
            }
            else
            {
                p.Speed = s.ForwardSpeed;
                DoInterpretedMotionUnchecked(s.ForwardCommand, p);
                MotionCommand side = s.SidestepCommand;
                if (side != MotionCommand.None)
                {
                    p.Speed = s.SidestepSpeed;
                    DoInterpretedMotionUnchecked(side, p);
                }
                else
                {
                    StopInterpretedMotionUnchecked(MotionCommand.SideStepRight, p);
                }
            }
        }
        else
        {
            p.Speed = 1f;
            DoInterpretedMotionUnchecked(MotionCommand.Falling, p);
        }

        MotionCommand turn = s.TurnCommand;
        if (turn != MotionCommand.None)
        {
            p.Speed = s.TurnSpeed;
            DoInterpretedMotionUnchecked(turn, p);
        }
        else
        {
            if (obj.StopInterpretedMotion(MotionCommand.TurnRight, p) == MotionError.None)
            {
                AddToQueue(p.ContextId, MotionCommand.Ready, MotionError.None);
                if (p.Has(MovementParameterFlags.ModifyInterpretedState))
                {
                    s.RemoveMotion(MotionCommand.TurnRight);
                }
            }

            if (obj.CellId == 0)
            {
                obj.RemoveLinkAnimations();
            }
        }
    }

    /// <summary>
    /// Takes a whole interpreted state from the server (a MovementEvent): the style into the raw state, the movement into
    /// the interpreted state, applied (a jump disallowed while the previous motion forbade one); then each action newer
    /// than <see cref="ServerActionStamp"/> (15-bit stamps compared with wrap-around) that is not this client's own.
    /// </summary>
    /// <returns>False when there is no physics object.</returns>
    /// <exception cref="System.ArgumentNullException"><paramref name="newState"/> is null.</exception>
    /// <exception cref="System.ArgumentException">The state runs forward (<see cref="MotionCommand.RunForward"/>) at a speed
    /// outside the run rate's domain (0, <see cref="Spatial.InputLimits.MaxRunRate"/>] (nothing changes).</exception>
    // retail: CMotionInterp::move_to_interpreted_state (acclient.c:344371)
    public bool MoveToInterpretedState(InterpretedMotionState newState)
    {
        System.ArgumentNullException.ThrowIfNull(newState);
        MotionChecks.CheckState(newState, nameof(newState));
        PhysicsObj? obj = _physicsObj;
        if (obj is null)
        {
            return false;
        }

        obj.Touch();
        RawState.CurrentStyle = newState.CurrentStyle;
        obj.CancelMoveTo();
        bool disallowJump = MotionAllowsJump(InterpretedState.ForwardCommand) != MotionError.None;
        InterpretedState.CopyMovementFrom(newState);
        ApplyCurrentMovement(true, disallowJump);
        var p = new MovementParameters();
        ActionList actions = newState.Actions;
        for (int i = 0; i < actions.Count; i++)
        {
            ActionNode a = actions[i];
            uint stamp = a.Stamp & 0x7FFFu;
            uint current = ServerActionStamp & 0x7FFFu;
            uint diff = stamp <= current ? current - stamp : stamp - current;
            bool newer = diff <= 0x3FFFu ? current < stamp : stamp < current;
            if (newer && ((_weenieObj is not null && !_weenieObj.IsThePlayer) || !a.Autonomous))
            {
                ServerActionStamp = a.Stamp;
                p.Speed = a.Speed;
                p.Flags = a.Autonomous ? p.Flags | MovementParameterFlags.Autonomous : p.Flags & ~MovementParameterFlags.Autonomous;
                DoInterpretedMotionUnchecked(a.Action, p);
            }
        }

        return true;
    }

    /// <summary>Turns the run key on or off: when that changes the current hold key, the movement is re-applied (a walk
    /// becomes a run or back).</summary>
    /// <param name="run">True: the run key is held.</param>
    /// <param name="cancelMoveToOnChange">True: the re-applied movement also cancels a running move-to (as retail's key
    /// handler, <c>CommandInterpreter</c>, always asks); false keeps it. Unused when the hold key does not change.</param>
    // retail: CMotionInterp::set_hold_run (acclient.c:344491)
    public void SetHoldRun(bool run, bool cancelMoveToOnChange)
    {
        if (!run != (RawState.CurrentHoldKey != HoldKey.Run))
        {
            RawState.CurrentHoldKey = run ? HoldKey.Run : HoldKey.None;
            ApplyCurrentMovement(cancelMoveToOnChange, false);
        }
    }

    /// <summary>Sets the current hold key to None or Run (re-applying the movement when it changes; Invalid is ignored).</summary>
    /// <param name="key">The hold key.</param>
    /// <param name="cancelMoveToOnChange">True: the re-applied movement also cancels a running move-to.</param>
    // retail: CMotionInterp::SetHoldKey (acclient.c:344501)
    public void SetHoldKey(HoldKey key, bool cancelMoveToOnChange)
    {
        HoldKey current = RawState.CurrentHoldKey;
        if (key == current)
        {
            return;
        }

        if (key == HoldKey.None)
        {
            if (current == HoldKey.Run)
            {
                RawState.CurrentHoldKey = HoldKey.None;
                ApplyCurrentMovement(cancelMoveToOnChange, false);
            }
        }
        else if (key == HoldKey.Run && current != HoldKey.Run)
        {
            RawState.CurrentHoldKey = HoldKey.Run;
            ApplyCurrentMovement(cancelMoveToOnChange, false);
        }
    }
}
