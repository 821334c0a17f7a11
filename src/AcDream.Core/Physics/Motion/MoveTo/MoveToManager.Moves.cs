using System;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Motion.MoveTo;

// The move-to's entry points: the four moves, the target reports, and the movement manager's dispatch.
public sealed partial class MoveToManager
{
    /// <summary>Starts a move to object <paramref name="objectId"/> (its top-level object <paramref name="topLevelId"/> is
    /// tracked; the steps are planned at its first report). A move to the object itself only stops.</summary>
    // retail: MoveToManager::MoveToObject (acclient.c:345183)
    internal void MoveToObject(uint objectId, uint topLevelId, float objectRadius, float objectHeight, in MovementParameters p)
    {
        PhysicsObj? obj = PhysicsObj;
        if (obj is not null)
        {
            obj.StopCompletelyUnchecked();
            StartingPosition = obj.Position;
            SoughtObjectId = objectId;
            SoughtObjectRadius = objectRadius;
            SoughtObjectHeight = objectHeight;
            MovementType = MovementType.MoveToObject;
            TopLevelObjectId = topLevelId;
            _movementParams = p;
            Initialized = false;
            if (topLevelId != obj.Id)
            {
                obj.SetTarget(0, TopLevelObjectId, TargetTrackRadius, TargetTrackQuantum);
                return;
            }

            CleanUp();
        }

        PhysicsObj?.StopCompletelyUnchecked();
    }

    /// <summary>Starts a turn to object <paramref name="objectId"/> (planned at its first report). A turn to the object
    /// itself only stops.</summary>
    // retail: MoveToManager::TurnToObject (acclient.c:345241)
    internal void TurnToObject(uint objectId, uint topLevelId, in MovementParameters p)
    {
        PhysicsObj? obj = PhysicsObj;
        if (obj is not null)
        {
            if ((p.Flags & MovementParameterFlags.StopCompletely) != 0)
            {
                obj.StopCompletelyUnchecked();
            }

            MovementType = MovementType.TurnToObject;
            SoughtObjectId = objectId;
            Position ctp = CurrentTargetPosition;
            ctp.Frame.SetHeading(p.DesiredHeading);
            CurrentTargetPosition = ctp;
            TopLevelObjectId = topLevelId;
            _movementParams = p;
            if (topLevelId != obj.Id)
            {
                Initialized = false;
                obj.SetTarget(0, topLevelId, TargetTrackRadius, TargetTrackQuantum);
                return;
            }

            CleanUp();
        }
        else
        {
            _movementParams.ContextId = p.ContextId;
        }

        PhysicsObj?.StopCompletelyUnchecked();
    }

    /// <summary>Starts a move to <paramref name="p"/>: a turn to face it and the move when it is farther than the
    /// parameters allow (<c>get_command</c>), then a turn to the desired heading with
    /// <see cref="MovementParameterFlags.UseFinalHeading"/>.</summary>
    // retail: MoveToManager::MoveToPosition (acclient.c:345789)
    internal void MoveToPosition(in Position p, in MovementParameters mp)
    {
        PhysicsObj? obj = PhysicsObj;
        if (obj is null)
        {
            return;
        }

        obj.StopCompletelyUnchecked();
        CurrentTargetPosition = p;
        SoughtObjectRadius = 0f;
        float distance = (float)GetCurrentDistance();
        float pa = RelativeHeading(obj, p);

        bool moveAway = false;
        mp.GetCommand(distance, pa, out MotionCommand command, out _, ref moveAway);
        if (command != 0)
        {
            float pc = (float)obj.Position.HeadingTo(p);
            AddTurnToHeadingNode(pc);
            AddMoveToPositionNode();
        }

        if ((mp.Flags & MovementParameterFlags.UseFinalHeading) != 0)
        {
            AddTurnToHeadingNode(mp.DesiredHeading);
        }

        SoughtPosition = p;
        StartingPosition = obj.Position;
        MovementType = MovementType.MoveToPosition;
        _movementParams = mp;
        _movementParams.Flags &= ~MovementParameterFlags.Sticky;
        BeginNextNode();
    }

    /// <summary>Plans a move to object at its first report: the target at <paramref name="targetPosition"/>, its predicted
    /// position <paramref name="interpolatedPosition"/> (the direction to face).</summary>
    // retail: MoveToManager::MoveToObject_Internal (acclient.c:345858)
    private void MoveToObject_Internal(in Position targetPosition, in Position interpolatedPosition)
    {
        PhysicsObj? obj = PhysicsObj;
        if (obj is null)
        {
            CancelMoveTo(MotionError.NoPhysicsObject);
            return;
        }

        SoughtPosition = interpolatedPosition;
        CurrentTargetPosition = targetPosition;
        float tp = (float)obj.Position.HeadingTo(interpolatedPosition);
        float distance = (float)GetCurrentDistance();
        double d = tp - obj.GetHeading();
        float headingToObject = (float)d;
        if (Math.Abs(d) < Eps)
        {
            headingToObject = 0f;
        }

        if (-Eps > headingToObject)
        {
            headingToObject = (float)(headingToObject + 360.0);
        }

        bool moveAway = false;
        _movementParams.GetCommand(distance, headingToObject, out MotionCommand command, out _, ref moveAway);
        if (command != 0)
        {
            AddTurnToHeadingNode(tp);
            AddMoveToPositionNode();
        }

        if ((_movementParams.Flags & MovementParameterFlags.UseFinalHeading) != 0)
        {
            double h = tp + (double)_movementParams.DesiredHeading;
            float final = (float)h;
            if (h >= 360.0)
            {
                final = (float)(final - 360.0);
            }

            AddTurnToHeadingNode(final);
        }

        Initialized = true;
        BeginNextNode();
    }

    /// <summary>Plans a turn to object at its first report: the heading to <paramref name="targetPosition"/> plus the
    /// heading held in <see cref="SoughtPosition"/>'s frame.</summary>
    // retail: MoveToManager::TurnToObject_Internal (acclient.c:345910)
    private void TurnToObject_Internal(in Position targetPosition)
    {
        PhysicsObj? obj = PhysicsObj;
        if (obj is null)
        {
            CancelMoveTo(MotionError.NoPhysicsObject);
            return;
        }

        CurrentTargetPosition = targetPosition;
        float soughtHeading = (float)SoughtPosition.Frame.Heading;
        float heading = (float)((obj.Position.HeadingTo(CurrentTargetPosition) + soughtHeading) % 360.0);
        Position sp = SoughtPosition;
        sp.Frame.SetHeading(heading);
        SoughtPosition = sp;
        _pendingActions.Append(MovementType.TurnToHeading, heading);
        Initialized = true;
        BeginNextNode();
    }

    /// <summary>Starts a turn to <see cref="MovementParameters.DesiredHeading"/> (stopping completely first with
    /// <see cref="MovementParameterFlags.StopCompletely"/>).</summary>
    // retail: MoveToManager::TurnToHeading (acclient.c:345953)
    internal void TurnToHeading(in MovementParameters p)
    {
        PhysicsObj? obj = PhysicsObj;
        if (obj is null)
        {
            _movementParams.ContextId = p.ContextId;
            return;
        }

        if ((p.Flags & MovementParameterFlags.StopCompletely) != 0)
        {
            obj.StopCompletelyUnchecked();
        }

        _movementParams = p;
        _movementParams.Flags &= ~MovementParameterFlags.Sticky;
        Position sp = SoughtPosition;
        sp.Frame.SetHeading(p.DesiredHeading);
        SoughtPosition = sp;
        MovementType = MovementType.TurnToHeading;
        _pendingActions.Append(MovementType.TurnToHeading, p.DesiredHeading);
        BeginNextNode();
    }

    /// <summary>
    /// A report of the tracked target: the first Ok report plans the move or turn (a move to itself ends at once), a later
    /// one (move-to-object) retargets and restarts the progress checks; any other status cancels
    /// (<see cref="MotionError.ObjectGone"/> once started, <see cref="MotionError.NoObject"/> before).
    /// </summary>
    // retail: MoveToManager::HandleUpdateTarget (acclient.c:346050)
    internal void HandleUpdateTarget(in TargetInfo info)
    {
        PhysicsObj? obj = PhysicsObj;
        if (obj is null)
        {
            CancelMoveTo(MotionError.NoPhysicsObject);
            return;
        }

        if (TopLevelObjectId != info.ObjectId)
        {
            return;
        }

        if (Initialized)
        {
            if (info.Status == TargetStatus.Ok)
            {
                if (MovementType == MovementType.MoveToObject)
                {
                    SoughtPosition = info.InterpolatedPosition;
                    CurrentTargetPosition = info.TargetPosition;
                    PreviousDistance = float.MaxValue;
                    PreviousDistanceTime = CurTime;
                    OriginalDistance = float.MaxValue;
                    OriginalDistanceTime = CurTime;
                }
            }
            else
            {
                CancelMoveTo(MotionError.ObjectGone);
            }
        }
        else if (TopLevelObjectId == obj.Id)
        {
            SoughtPosition = obj.Position;
            CurrentTargetPosition = obj.Position;
            CleanUpAndCallWeenie(MotionError.None);
        }
        else if (info.Status == TargetStatus.Ok)
        {
            if (MovementType == MovementType.MoveToObject)
            {
                MoveToObject_Internal(info.TargetPosition, info.InterpolatedPosition);
            }
            else if (MovementType == MovementType.TurnToObject)
            {
                TurnToObject_Internal(info.TargetPosition);
            }
        }
        else
        {
            CancelMoveTo(MotionError.NoObject);
        }
    }

    /// <summary>A new move-to (types 6–9): cancels the running one (<see cref="MotionError.ActionCancelled"/>), unsticks,
    /// then starts it.</summary>
    /// <returns>Always <see cref="MotionError.None"/>, as retail.</returns>
    // retail: MoveToManager::PerformMovement (acclient.c:346118)
    internal MotionError PerformMovement(in MovementStruct mvs)
    {
        CancelMoveTo(MotionError.ActionCancelled);
        PhysicsObj?.UnstickFromObject();
        switch (mvs.Type)
        {
            case MovementType.MoveToObject:
                MoveToObject(mvs.ObjectId, mvs.TopLevelId, mvs.Radius, mvs.Height, mvs.Params);
                break;
            case MovementType.MoveToPosition:
                MoveToPosition(mvs.Pos, mvs.Params);
                break;
            case MovementType.TurnToObject:
                TurnToObject(mvs.ObjectId, mvs.TopLevelId, mvs.Params);
                break;
            case MovementType.TurnToHeading:
                TurnToHeading(mvs.Params);
                break;
        }

        return MotionError.None;
    }
}
