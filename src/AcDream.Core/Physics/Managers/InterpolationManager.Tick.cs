using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Seams;

namespace AcDream.Core.Physics.Managers;

public sealed partial class InterpolationManager
{
    /// <summary>
    /// Replaces <paramref name="offset"/> (the substep's local offset, normally the animation's root motion) with a step
    /// towards the head node, expressed in the object's local frame: at most <c>speed × quantum</c> metres, where speed is
    /// 2 × the motion's adjusted max speed (7.5 m/s when that is below EPSILON). Does nothing while the queue is empty, the
    /// object is not in contact, or the head is a Jump/Velocity node. Every <see cref="ProgressCheckFrames"/> substeps the
    /// progress since the last audit must reach 30 % of <c>speed × elapsed</c>; otherwise the node completes (within 0.2 m)
    /// or fails (fail counter + 1) and the offset is left untouched.
    /// </summary>
    /// <param name="offset">The substep's offset frame, replaced when a step is taken.</param>
    /// <param name="quantum">Substep duration, seconds.</param>
    /// <exception cref="System.ArgumentException"><paramref name="quantum"/> is NaN or infinite (state unchanged).</exception>
    // retail: InterpolationManager::adjust_offset (acclient.c:389177)
    internal void AdjustOffset(ref Frame offset, double quantum)
    {
        if (!double.IsFinite(quantum))
        {
            throw new System.ArgumentException("Quantum must be finite.", nameof(quantum));
        }

        if (_count == 0)
        {
            return;
        }

        PhysicsObj obj = PhysicsObj;
        if ((obj.TransientState & TransientState.Contact) == 0)
        {
            return;
        }

        ref InterpolationNode head = ref Head;
        if (head.Type is InterpolationNodeType.Jump or InterpolationNodeType.Velocity)
        {
            return;
        }

        Position body = obj.Position;
        double d = body.DistanceInDouble(head.Position);
        float currDistance = (float)d;
        if (d < DesiredDistance)
        {
            NodeCompleted(true);
            return;
        }

        float myMaxSpeed = 0f;
        IMotionInterpreter? minterp = obj.GetOrCreateMotionInterpreter();
        if (minterp is not null)
        {
            double s = UseAdjustedSpeed ? minterp.GetAdjustedMaxSpeed() : minterp.GetMaxSpeed();
            myMaxSpeed = (float)(s * SpeedMultiplier);
        }

        if (myMaxSpeed < PhysicsGlobals.Epsilon)
        {
            myMaxSpeed = MaxInterpolatedVelocity;
        }

        uint frames = FrameCounter + 1;
        ProgressQuantum = (float)(quantum + ProgressQuantum);
        FrameCounter = frames;
        if (frames >= ProgressCheckFrames)
        {
            float progressMade = OriginalDistance - currDistance;
            bool passed = obj.StickyObjectId != 0
                || (progressMade >= PhysicsGlobals.Epsilon
                    && (double)progressMade / ProgressQuantum / myMaxSpeed >= MinProgressFraction);
            if (!passed)
            {
                if (currDistance < NearEnoughDistance)
                {
                    NodeCompleted(true);
                    return;
                }

                NodeFailCounter++;
                NodeCompleted(false);
                return;
            }

            FrameCounter = 0;
            ProgressQuantum = 0f;
            OriginalDistance = currDistance;
        }

        // The head in the body's local frame, block-offset aware (Position::subtract2, acclient.c:388972).
        Frame adjustment = Position.RelativeFrame(head.Position, body);
        float progress = (float)(myMaxSpeed * quantum);
        double adjustmentMagnitude = VectorMath.Magnitude(adjustment.Origin);
        float adjustmentDistance = (float)adjustmentMagnitude;
        if (adjustmentMagnitude <= DesiredDistance)
        {
            // Retail completes the node here and still takes this last step.
            NodeCompleted(true);
        }

        if (adjustmentDistance > progress)
        {
            float rhs = progress / adjustmentDistance;
            Vector3 o = adjustment.Origin;
            adjustment.Origin = new Vector3(o.X * rhs, o.Y * rhs, o.Z * rhs);
        }

        if (KeepHeading)
        {
            adjustment.SetHeading(0f);
        }

        offset = adjustment;
    }

    /// <summary>
    /// End-of-substep work, after the sweep. Blips when the fail counter exceeds 3, or when the queue ran dry with failures:
    /// to the newest node if it is a Position; for a Jump/Velocity tail, to the last Position node before it and then restores
    /// the tail's velocity; else to <see cref="BliptoPosition"/>. A blip is <see cref="PhysicsObj.SetPositionSimple"/> with
    /// sliding; when it fails nothing changes and the next call retries. Without a blip, a Velocity head sets the object's
    /// velocity and completes, and a Jump head completes.
    /// </summary>
    // retail: InterpolationManager::UseTime (acclient.c:389277)
    internal void UseTime()
    {
        PhysicsObj obj = PhysicsObj;
        int fails = NodeFailCounter;
        if (fails <= BlipFailThreshold)
        {
            if (_count > 0)
            {
                ref InterpolationNode head = ref Head;
                if (head.Type == InterpolationNodeType.Velocity)
                {
                    obj.SetVelocity(head.Velocity);
                    NodeCompleted(true);
                }
                else if (head.Type == InterpolationNodeType.Jump)
                {
                    NodeCompleted(true);
                }

                return;
            }

            if (fails <= 0)
            {
                return;
            }
        }

        Blip(obj);
    }

    private void Blip(PhysicsObj obj)
    {
        if (_count > 0)
        {
            ref InterpolationNode tail = ref Tail;
            if (tail.Type is not (InterpolationNodeType.Jump or InterpolationNodeType.Velocity))
            {
                if (obj.SetPositionSimple(tail.Position, true) != SetPositionError.Ok)
                {
                    return;
                }

                StopInterpolating();
                return;
            }

            // Jump/Velocity tail: the last Position node before it, then restore the tail's velocity.
            Vector3 v = tail.Velocity;
            int found = -1;
            for (int i = 0; i < _count - 1; i++)
            {
                if (At(i).Type == InterpolationNodeType.Position)
                {
                    found = i;
                }
            }

            if (found >= 0)
            {
                Position pos = At(found).Position;
                if (obj.SetPositionSimple(pos, true) != SetPositionError.Ok)
                {
                    return;
                }

                obj.SetVelocity(v);
                StopInterpolating();
                return;
            }
        }

        if (obj.SetPositionSimple(BliptoPosition, true) != SetPositionError.Ok)
        {
            return;
        }

        StopInterpolating();
    }

    /// <summary>
    /// Pops the head. The next Position head becomes the audit's reference distance; a failure remembers the popped node as
    /// the blip target when no Position node follows; a success that empties the queue stops interpolating.
    /// </summary>
    // retail: InterpolationManager::NodeCompleted (acclient.c:388881)
    private void NodeCompleted(bool success)
    {
        FrameCounter = 0;
        ProgressQuantum = 0f;
        if (_count == 0)
        {
            // Unreachable from retail's callers (both hold a head); kept as retail has it.
            OriginalDistance = BigDistance;
            if (success)
            {
                StopInterpolating();
            }

            return;
        }

        Position completed = Head.Position;
        RemoveHead();
        if (_count > 0)
        {
            ref InterpolationNode next = ref Head;
            if (next.Type == InterpolationNodeType.Position)
            {
                OriginalDistance = (float)PhysicsObj.Position.DistanceInDouble(next.Position);
            }
            else if (!success)
            {
                BliptoPosition = completed;
            }

            return;
        }

        OriginalDistance = BigDistance;
        if (success)
        {
            StopInterpolating();
        }
        else
        {
            BliptoPosition = completed;
        }
    }
}
