using System;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Motion;

// The move-to's steps: starting, running and ending each pending step, and the per-step update.
public sealed partial class MoveToManager
{
    private const float Eps = PhysicsGlobals.Epsilon;

    // The heading to the target relative to the object's own, as BeginMoveForward and MoveToPosition compute it inline:
    // heading_to(target) − (float)heading in double, rounded to float; within EPSILON of 0 it is 0, below −EPSILON + 360.
    private static float RelativeHeading(PhysicsObj obj, in Position target)
    {
        float h = (float)obj.GetHeading();
        double d = obj.Position.HeadingTo(target) - h;
        float relative = (float)d;
        if (Math.Abs(d) < Eps)
        {
            relative = 0f;
        }

        if (-Eps > relative)
        {
            relative = (float)(relative + 360.0);
        }

        return relative;
    }

    /// <summary>True when heading <paramref name="x"/> is past <paramref name="y"/> in the direction of
    /// <paramref name="motion"/> (turn right: clockwise, else anticlockwise), across the 0/360 wrap.</summary>
    // retail: heading_greater (acclient.c:344714)
    internal static bool HeadingGreater(float x, float y, MotionCommand motion)
    {
        bool less, equal;
        if (Math.Abs((double)x - y) <= 180.0)
        {
            less = x < (double)y;
            equal = x == y;
        }
        else
        {
            less = y < (double)x;
            equal = y == x;
        }

        bool result = !(less || equal);
        if (motion != MotionCommand.TurnRight)
        {
            result = less || equal;
        }

        return result;
    }

    /// <summary>The turn from <paramref name="y"/> to <paramref name="x"/>, degrees in [0, 360): clockwise for
    /// <paramref name="motion"/> = turn right, else anticlockwise; within EPSILON of 0 is 0.</summary>
    // retail: heading_diff (acclient.c:344737)
    internal static double HeadingDiff(float x, float y, MotionCommand motion)
    {
        double result = (double)x - y;
        if (Math.Abs(result) < Eps)
        {
            result = 0.0;
        }

        if (result < -Eps)
        {
            result += 360.0;
        }

        if (result > Eps && motion != MotionCommand.TurnRight)
        {
            result = 360.0 - result;
        }

        return result;
    }

    /// <summary>Starts the move step: the command for the current distance (none: the step is done), played with the
    /// move-to's speed and the hold key <c>get_command</c> chose (walk or run); the progress checks start here.</summary>
    // retail: MoveToManager::BeginMoveForward (acclient.c:345370)
    private void BeginMoveForward()
    {
        PhysicsObj? obj = PhysicsObj;
        if (obj is null)
        {
            CancelMoveTo(MotionError.NoPhysicsObject);
            return;
        }

        float currDistance = (float)GetCurrentDistance();
        float currHeading = RelativeHeading(obj, CurrentTargetPosition);

        bool moveAway = false;
        _movementParams.GetCommand(currDistance, currHeading, out MotionCommand motion, out HoldKey holdKey, ref moveAway);
        if (motion != 0)
        {
            var p = new MovementParameters();
            p.HoldKeyToApply = holdKey;
            p.Flags &= ~MovementParameterFlags.CancelMoveTo;
            p.Speed = _movementParams.Speed;
            MotionError e = _DoMotion(motion, ref p);
            if (e != MotionError.None)
            {
                CancelMoveTo(e);
            }
            else
            {
                CurrentCommand = motion;
                MovingAway = moveAway;
                _movementParams.HoldKeyToApply = holdKey;
                PreviousDistance = currDistance;
                PreviousDistanceTime = CurTime;
                OriginalDistance = currDistance;
                OriginalDistanceTime = CurTime;
            }
        }
        else
        {
            RemovePendingActionsHead();
            BeginNextNode();
        }
    }

    /// <summary>Starts the turn step (once no motion is pending): turn right when the heading is at most 180° clockwise
    /// away, else left; a heading within EPSILON ends the step at once.</summary>
    // retail: MoveToManager::BeginTurnToHeading (acclient.c:345455)
    private void BeginTurnToHeading()
    {
        PhysicsObj? obj = PhysicsObj;
        if (_pendingActions.Count == 0 || obj is null)
        {
            CancelMoveTo(MotionError.NoPhysicsObject);
            return;
        }

        if (obj.MotionsPending())
        {
            return;
        }

        float target = _pendingActions.Head.Heading;
        float y = (float)obj.GetHeading();
        double diff = HeadingDiff(target, y, MotionCommand.TurnRight);
        MotionCommand turn;
        if (diff <= 180.0)
        {
            if (diff > Eps)
            {
                turn = MotionCommand.TurnRight;
            }
            else
            {
                RemovePendingActionsHead();
                BeginNextNode();
                return;
            }
        }
        else
        {
            if (diff + Eps >= 360.0)
            {
                RemovePendingActionsHead();
                BeginNextNode();
                return;
            }

            turn = MotionCommand.TurnLeft;
        }

        var p = new MovementParameters();
        p.Flags &= ~MovementParameterFlags.CancelMoveTo;
        p.Speed = _movementParams.Speed;
        p.HoldKeyToApply = _movementParams.HoldKeyToApply;
        MotionError e = _DoMotion(turn, ref p);
        if (e != MotionError.None)
        {
            CancelMoveTo(e);
        }
        else
        {
            CurrentCommand = turn;
            PreviousHeading = (float)diff;
        }
    }

    /// <summary>Starts the next pending step; with none left the move-to ends (cleaned up, the object stopped completely)
    /// and, with <see cref="MovementParameterFlags.Sticky"/>, the object sticks to the target.</summary>
    // retail: MoveToManager::BeginNextNode (acclient.c:345520)
    private void BeginNextNode()
    {
        if (_pendingActions.Count != 0)
        {
            MovementType t = _pendingActions.Head.Type;
            if (t == MovementType.MoveToPosition)
            {
                BeginMoveForward();
            }
            else if (t == MovementType.TurnToHeading)
            {
                BeginTurnToHeading();
            }
        }
        else if ((_movementParams.Flags & MovementParameterFlags.Sticky) == 0)
        {
            CleanUp();
            LastResult = MotionError.None;
            PhysicsObj?.StopCompletelyUnchecked();
        }
        else
        {
            float oldHeight = SoughtObjectHeight;
            uint id = TopLevelObjectId;
            float oldRadius = SoughtObjectRadius;
            CleanUp();
            LastResult = MotionError.None;
            PhysicsObj? obj = PhysicsObj;
            obj?.StopCompletelyUnchecked();
            obj?.GetPositionManager().StickTo(id, oldRadius, oldHeight);
        }
    }

    /// <summary>The object landed: the current step starts again.</summary>
    // retail: MoveToManager::HitGround (acclient.c:345569)
    internal void HitGround()
    {
        if (MovementType != MovementType.Invalid)
        {
            BeginNextNode();
        }
    }

    /// <summary>
    /// Runs the move step: keeps facing the target (a correcting turn while the heading is more than 20° off), checks the
    /// progress, ends the step at the distance (<see cref="MovementParameters.DistanceToObject"/>, or moving away
    /// <see cref="MovementParameters.MinDistance"/>), cancels with <see cref="MotionError.YouChargedTooFar"/> past the fail
    /// distance from the start, and sets the target's report quantum to the time to get there.
    /// </summary>
    // retail: MoveToManager::HandleMoveToPosition (acclient.c:345576)
    private void HandleMoveToPosition()
    {
        PhysicsObj? obj = PhysicsObj;
        if (obj is null)
        {
            CancelMoveTo(MotionError.NoPhysicsObject);
            return;
        }

        Position currPos = obj.Position;
        var p = new MovementParameters();
        p.Speed = _movementParams.Speed;
        p.Flags &= ~MovementParameterFlags.CancelMoveTo;
        p.HoldKeyToApply = _movementParams.HoldKeyToApply;
        if (obj.MotionsPending())
        {
            if (AuxCommand != 0)
            {
                _StopMotion(AuxCommand, ref p);
                AuxCommand = 0;
            }
        }
        else
        {
            float toTarget = (float)currPos.HeadingTo(CurrentTargetPosition);
            double desired = MovementParameters.GetDesiredHeading(CurrentCommand, MovingAway) + toTarget;
            float heading = (float)desired;
            if (desired >= 360.0)
            {
                heading = (float)(heading - 360.0);
            }

            double off = heading - obj.GetHeading();
            if (Math.Abs(off) < Eps)
            {
                off = 0.0;
            }

            if (off < -Eps)
            {
                off += 360.0;
            }

            if (off <= AuxTurnThreshold || off >= 360.0 - AuxTurnThreshold)
            {
                if (AuxCommand != 0)
                {
                    _StopMotion(AuxCommand, ref p);
                    AuxCommand = 0;
                }
            }
            else
            {
                MotionCommand turn = MotionCommand.TurnRight;
                if (off >= 180.0)
                {
                    turn = MotionCommand.TurnLeft;
                }

                if (turn != AuxCommand)
                {
                    _DoMotion(turn, ref p);
                    AuxCommand = turn;
                }
            }
        }

        float dist = (float)GetCurrentDistance();
        if (!CheckProgressMade(dist))
        {
            if (!obj.IsInterpolating && !obj.MotionsPending())
            {
                FailProgressCount++;
            }
        }
        else
        {
            FailProgressCount = 0;
            bool arrived = MovingAway ? !(dist < _movementParams.MinDistance) : dist <= _movementParams.DistanceToObject;
            if (arrived)
            {
                RemovePendingActionsHead();
                _StopMotion(CurrentCommand, ref p);
                CurrentCommand = 0;
                if (AuxCommand != 0)
                {
                    _StopMotion(AuxCommand, ref p);
                    AuxCommand = 0;
                }

                BeginNextNode();
            }
            else if (StartingPosition.DistanceInDouble(obj.Position) > _movementParams.FailDistance)
            {
                CancelMoveTo(MotionError.YouChargedTooFar);
            }
        }

        if (TopLevelObjectId != 0 && MovementType != MovementType.Invalid)
        {
            double speed = VectorMath.Magnitude(obj.CachedVelocity);
            if (speed > QuantumMinSpeed)
            {
                double timeToGetThere = dist / speed;
                if (Math.Abs(timeToGetThere - obj.TargetQuantum) > QuantumChangeThreshold)
                {
                    obj.SetTargetQuantum(timeToGetThere);
                }
            }
        }
    }

    /// <summary>Runs the turn step: once the heading passes the step's heading it is set exactly and the step ends; else the
    /// progress counter follows whether the heading still moves the right way.</summary>
    // retail: MoveToManager::HandleTurnToHeading (acclient.c:345711)
    private void HandleTurnToHeading()
    {
        PhysicsObj? obj = PhysicsObj;
        if (obj is null)
        {
            CancelMoveTo(MotionError.NoPhysicsObject);
            return;
        }

        MotionCommand cmd = CurrentCommand;
        if (cmd != MotionCommand.TurnLeft && cmd != MotionCommand.TurnRight)
        {
            BeginTurnToHeading();
            return;
        }

        float target = _pendingActions.Head.Heading;
        float currHeading = (float)obj.GetHeading();
        if (HeadingGreater(currHeading, target, cmd))
        {
            FailProgressCount = 0;
            obj.SetHeadingUnchecked(target);
            RemovePendingActionsHead();
            var p = new MovementParameters();
            p.Flags &= ~MovementParameterFlags.CancelMoveTo;
            p.HoldKeyToApply = _movementParams.HoldKeyToApply;
            _StopMotion(CurrentCommand, ref p);
            CurrentCommand = 0;
            BeginNextNode();
        }
        else
        {
            double turned = HeadingDiff(currHeading, PreviousHeading, cmd);
            if (turned >= 180.0 || turned <= Eps)
            {
                PreviousHeading = currHeading;
                if (!obj.IsInterpolating && !obj.MotionsPending())
                {
                    FailProgressCount++;
                }
            }
            else
            {
                FailProgressCount = 0;
                PreviousHeading = currHeading;
            }
        }
    }

    /// <summary>The per-step update, on the ground only (CONTACT) and, for an object target, once its first report came:
    /// runs the head step.</summary>
    // retail: MoveToManager::UseTime (acclient.c:346017)
    internal void UseTime()
    {
        PhysicsObj? obj = PhysicsObj;
        if (obj is null || (obj.TransientState & TransientState.Contact) == 0 || _pendingActions.Count == 0)
        {
            return;
        }

        if (TopLevelObjectId == 0 || MovementType == MovementType.Invalid || Initialized)
        {
            MovementType t = _pendingActions.Head.Type;
            if (t == MovementType.MoveToPosition)
            {
                HandleMoveToPosition();
            }
            else if (t == MovementType.TurnToHeading)
            {
                HandleTurnToHeading();
            }
        }
    }
}
