using System;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Motion;

public sealed partial class MotionInterp
{
    /// <summary>
    /// Starts a command as the player gives it: sets the hold key when asked, converts the command
    /// (<see cref="AdjustMotion"/>), refuses postures and emotes outside the non-combat style and a seventh action, plays
    /// the result (<see cref="DoInterpretedMotion"/>) and records the command in the raw state.
    /// </summary>
    /// <returns><see cref="MotionError.None"/> on success, else the error (nothing recorded).</returns>
    /// <exception cref="System.ArgumentException"><paramref name="p"/> is <c>default(MovementParameters)</c> (all zeros; use <c>new MovementParameters()</c>) or its speed is NaN, infinite or beyond ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/> (nothing changes).</exception>
    // retail: CMotionInterp::DoMotion (acclient.c:344599)
    public MotionError DoMotion(MotionCommand motion, in MovementParameters p)
    {
        MotionChecks.Check(p);
        PhysicsObj? obj = _physicsObj;
        if (obj is null)
        {
            return MotionError.NoPhysicsObject;
        }

        obj.Touch();
        MovementParameters adjusted = p;
        if (p.Has(MovementParameterFlags.CancelMoveTo))
        {
            obj.CancelMoveTo();
        }

        if (p.Has(MovementParameterFlags.SetHoldKey))
        {
            SetHoldKey(p.HoldKeyToApply, p.Has(MovementParameterFlags.CancelMoveTo));
        }

        MotionCommand adjustedMotion = motion;
        AdjustMotion(ref adjustedMotion, ref adjusted.Speed, p.HoldKeyToApply);
        if (InterpretedState.CurrentStyle != MotionCommand.NonCombat)
        {
            switch (motion)
            {
                case MotionCommand.Crouch:
                    return MotionError.CantCrouchInCombat;
                case MotionCommand.Sitting:
                    return MotionError.CantSitInCombat;
                case MotionCommand.Sleeping:
                    return MotionError.CantLieDownInCombat;
            }

            if (((uint)motion & (uint)MotionCommandClass.ChatEmote) != 0)
            {
                return MotionError.CantChatEmoteInCombat;
            }
        }

        if (((uint)motion & (uint)MotionCommandClass.Action) != 0 && InterpretedState.Actions.Count >= 6)
        {
            return MotionError.TooManyActions;
        }

        // The converted speed (a run: times the run rate) may exceed MaxMotionSpeed; p itself was checked above.
        MotionError result = DoInterpretedMotionUnchecked(adjustedMotion, adjusted);
        if (result == MotionError.None && p.Has(MovementParameterFlags.ModifyRawState))
        {
            RawState.ApplyMotion(motion, p);
        }

        return result;
    }

    /// <summary>Stops a command as the player gives it: converts it as <see cref="DoMotion"/> does, stops the result and
    /// removes the command from the raw state.</summary>
    /// <returns><see cref="MotionError.None"/> on success, else the error.</returns>
    /// <exception cref="System.ArgumentException"><paramref name="p"/> is <c>default(MovementParameters)</c> (all zeros; use <c>new MovementParameters()</c>) or its speed is NaN, infinite or beyond ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/> (nothing changes).</exception>
    // retail: CMotionInterp::StopMotion (acclient.c:344080)
    public MotionError StopMotion(MotionCommand motion, in MovementParameters p)
    {
        MotionChecks.Check(p);
        PhysicsObj? obj = _physicsObj;
        if (obj is null)
        {
            return MotionError.NoPhysicsObject;
        }

        obj.Touch();
        if (p.Has(MovementParameterFlags.CancelMoveTo))
        {
            obj.CancelMoveTo();
        }

        MovementParameters adjusted = p;
        MotionCommand adjustedMotion = motion;
        AdjustMotion(ref adjustedMotion, ref adjusted.Speed, p.HoldKeyToApply);
        MotionError result = StopInterpretedMotionUnchecked(adjustedMotion, adjusted);
        if (result == MotionError.None && p.Has(MovementParameterFlags.ModifyRawState))
        {
            RawState.RemoveMotion(motion);
        }

        return result;
    }

    /// <summary>
    /// Plays an interpreted motion: on the ground (or for a motion allowed in the air) it goes to the motion table, is
    /// queued with the jump error it imposes, and is recorded in the interpreted state; in the air (or, while a standing
    /// long jump charges, a walk, run or side-step) it is only recorded; an action in the air fails with 0x24.
    /// </summary>
    /// <returns><see cref="MotionError.None"/> on success, else the error.</returns>
    /// <exception cref="System.ArgumentException"><paramref name="p"/> is <c>default(MovementParameters)</c> (all zeros; use <c>new MovementParameters()</c>) or its speed is NaN, infinite or beyond ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/> (nothing changes).</exception>
    // retail: CMotionInterp::DoInterpretedMotion (acclient.c:343974)
    public MotionError DoInterpretedMotion(MotionCommand motion, in MovementParameters p)
    {
        MotionChecks.Check(p);
        return DoInterpretedMotionUnchecked(motion, p);
    }

    // The body of DoInterpretedMotion, for apply_interpreted_movement: its parameters are retail's defaults with the interpreted
    // state's speeds (finite by their setters), so the tick's path runs no argument check.
    // retail: CMotionInterp::DoInterpretedMotion (acclient.c:343974)
    internal MotionError DoInterpretedMotionUnchecked(MotionCommand motion, in MovementParameters p)
    {
        PhysicsObj? obj = _physicsObj;
        if (obj is null)
        {
            return MotionError.NoPhysicsObject;
        }

        obj.Touch();
        MotionError result;
        if (ContactAllowsMove(motion))
        {
            if (!StandingLongJump || (motion != MotionCommand.WalkForward && motion != MotionCommand.RunForward
                                      && motion != MotionCommand.SideStepRight))
            {
                if (motion == MotionCommand.Dead)
                {
                    obj.RemoveLinkAnimations();
                }

                result = obj.DoInterpretedMotion(motion, p);
                if (result == MotionError.None)
                {
                    MotionError jumpError;
                    if (p.Has(MovementParameterFlags.DisableJumpDuringLink))
                    {
                        jumpError = MotionError.YouCantJumpFromThisPosition;
                    }
                    else
                    {
                        jumpError = MotionAllowsJump(motion);
                        if (jumpError == MotionError.None && ((uint)motion & (uint)MotionCommandClass.Action) == 0)
                        {
                            jumpError = MotionAllowsJump(InterpretedState.ForwardCommand);
                        }
                    }

                    AddToQueue(p.ContextId, motion, jumpError);
                    if (p.Has(MovementParameterFlags.ModifyInterpretedState))
                    {
                        InterpretedState.ApplyMotionInternal(motion, p);
                    }
                }
            }
            else
            {
                result = RecordOnly(motion, p);
            }
        }
        else if (((uint)motion & (uint)MotionCommandClass.Action) == 0)
        {
            result = RecordOnly(motion, p);
        }
        else
        {
            result = MotionError.YouCantJumpWhileInTheAir;
        }

        if (obj.CellId == 0)
        {
            obj.RemoveLinkAnimations();
        }

        return result;
    }

    private MotionError RecordOnly(MotionCommand motion, in MovementParameters p)
    {
        if (p.Has(MovementParameterFlags.ModifyInterpretedState))
        {
            InterpretedState.ApplyMotionInternal(motion, p);
        }

        return MotionError.None;
    }

    /// <summary>Stops an interpreted motion: through the motion table when it may move (queueing a Ready), otherwise only
    /// in the interpreted state.</summary>
    /// <returns><see cref="MotionError.None"/> on success, else the error.</returns>
    /// <exception cref="System.ArgumentException"><paramref name="p"/> is <c>default(MovementParameters)</c> (all zeros; use <c>new MovementParameters()</c>) or its speed is NaN, infinite or beyond ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/> (nothing changes).</exception>
    // retail: CMotionInterp::StopInterpretedMotion (acclient.c:344033)
    public MotionError StopInterpretedMotion(MotionCommand motion, in MovementParameters p)
    {
        MotionChecks.Check(p);
        return StopInterpretedMotionUnchecked(motion, p);
    }

    // The body of StopInterpretedMotion, for apply_interpreted_movement: its parameters are retail's defaults with the interpreted
    // state's speeds (finite by their setters), so the tick's path runs no argument check.
    // retail: CMotionInterp::StopInterpretedMotion (acclient.c:344033)
    internal MotionError StopInterpretedMotionUnchecked(MotionCommand motion, in MovementParameters p)
    {
        PhysicsObj? obj = _physicsObj;
        if (obj is null)
        {
            return MotionError.NoPhysicsObject;
        }

        obj.Touch();
        MotionError result;
        if (!ContactAllowsMove(motion)
            || (StandingLongJump && (motion == MotionCommand.WalkForward || motion == MotionCommand.RunForward
                                     || motion == MotionCommand.SideStepRight)))
        {
            if (p.Has(MovementParameterFlags.ModifyInterpretedState))
            {
                InterpretedState.RemoveMotion(motion);
            }

            result = MotionError.None;
        }
        else
        {
            result = obj.StopInterpretedMotion(motion, p);
            if (result == MotionError.None)
            {
                AddToQueue(p.ContextId, MotionCommand.Ready, MotionError.None);
                if (p.Has(MovementParameterFlags.ModifyInterpretedState))
                {
                    InterpretedState.RemoveMotion(motion);
                }
            }
        }

        if (obj.CellId == 0)
        {
            obj.RemoveLinkAnimations();
        }

        return result;
    }

    /// <summary>Stops everything: both states back to Ready with no side-step or turn, the motion table stopped, a Ready
    /// queued with the jump error of the motion that was playing.</summary>
    /// <returns><see cref="MotionError.None"/>, or <see cref="MotionError.NoPhysicsObject"/>.</returns>
    // retail: CMotionInterp::StopCompletely (acclient.c:343596)
    public MotionError StopCompletely()
    {
        PhysicsObj? obj = _physicsObj;
        if (obj is null)
        {
            return MotionError.NoPhysicsObject;
        }

        obj.Touch();
        obj.CancelMoveTo();
        MotionError jumpError = MotionAllowsJump(InterpretedState.ForwardCommand);
        RawState.ForwardCommand = MotionCommand.Ready;
        RawState.ForwardSpeed = 1f;
        RawState.SidestepCommand = 0;
        RawState.TurnCommand = 0;
        InterpretedState.ForwardCommand = MotionCommand.Ready;
        InterpretedState.ForwardSpeed = 1f;
        InterpretedState.SidestepCommand = 0;
        InterpretedState.TurnCommand = 0;
        obj.StopCompletelyInternal();
        AddToQueue(0, MotionCommand.Ready, jumpError);
        if (obj.CellId == 0)
        {
            obj.RemoveLinkAnimations();
        }

        return MotionError.None;
    }

    /// <summary>The motion at the head of the pending list finished: an action's stickiness and its queued entries go,
    /// and the node is removed.</summary>
    // retail: CMotionInterp::MotionDone (acclient.c:343640)
    internal void MotionDone(bool success)
    {
        PhysicsObj? obj = _physicsObj;
        if (obj is null || PendingMotions.Count == 0)
        {
            return;
        }

        if (((uint)PendingMotions.Head.Motion & (uint)MotionCommandClass.Action) != 0)
        {
            obj.StopSticking();
            InterpretedState.RemoveAction();
            RawState.RemoveAction();
        }

        PendingMotions.RemoveHead();
    }

    /// <summary>The object left the world: every pending motion is finished as <see cref="MotionDone"/> does.</summary>
    // retail: CMotionInterp::HandleExitWorld (acclient.c:343678)
    internal void HandleExitWorld()
    {
        // non-retail: retail loops while the list is non-empty and removes a node only with a physics object, so without one
        // it never ends (acclient.c:343678-343713); the port stops and leaves the motions pending (docs/divergences.md)
        while (_physicsObj is not null && PendingMotions.Count != 0)
        {
            MotionDone(true);
        }
    }
}
