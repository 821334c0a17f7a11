using System;
using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Animation;

public sealed partial class AnimSequence
{
    // Retail's EPSILON as the x87 code loads it: the float 0.0002f (0x3951B717) widened to double, 1.99999994947575e-4 (the
    // decompiler prints 0.00019999999, a double literal 4.95e-12 smaller). Framerates and quanta at or below it move nothing.
    private const double Epsilon = PhysicsGlobals.Epsilon;

    /// <summary>
    /// Plays <paramref name="quantum"/> seconds: with animations queued, advances them (root motion and the sequence's
    /// velocity and omega into <paramref name="offsetFrame"/>, hooks queued on the object) and drops the links that played
    /// out; with none, moves <paramref name="offsetFrame"/> by the velocity and omega alone.
    /// </summary>
    // retail: CSequence::update (acclient.c:340950)
    internal void Update(double quantum, ref Frame offsetFrame) => Update(quantum, ref offsetFrame, hasFrame: true);

    /// <summary><see cref="Update(double, ref Frame)"/> without a frame (retail's null <c>retval</c>): frames and hooks only.</summary>
    internal void Update(double quantum)
    {
        Frame unused = default;
        Update(quantum, ref unused, hasFrame: false);
    }

    private void Update(double quantum, ref Frame retval, bool hasFrame)
    {
        if (_head is not null)
        {
            UpdateInternal(quantum, ref _currAnim, ref _frameNumber, ref retval, hasFrame);
            Apricot();
        }
        else if (hasFrame)
        {
            ApplyPhysics(ref retval, quantum, quantum);
        }
    }

    /// <summary>
    /// Advances the playing animation by framerate × quantum frames. Each whole frame crossed applies its root motion
    /// (combined going forwards, subtracted going backwards) and 1/framerate seconds of velocity and omega, and queues the
    /// frame's hooks for that direction. Past the range's end the rest of the time carries over to the next animation
    /// (an AnimDone hook first while links are queued). A zero framerate (or quantum) moves by velocity and omega alone.
    /// </summary>
    // retail: CSequence::update_internal (acclient.c:340658)
    internal void UpdateInternal(double quantum, ref AnimSequenceNode? currAnim, ref double frameNumber, ref Frame retval, bool hasFrame)
    {
        bool advanced = false;
        while (true)
        {
            AnimSequenceNode? curr = currAnim;
            if (curr is null)
            {
                // non-retail: retail reads a null node (never reached: a non-empty list always has a playing animation)
                return;
            }

            double framerate = curr.GetFramerate();
            double frameQuantum = framerate * quantum;
            bool advanceAnim = false;
            int lastFrame = AnimSequenceNode.FloorToFrame(frameNumber);
            double timeLeft = 0.0;
            double next = frameQuantum + frameNumber;
            frameNumber = next;
            if (frameQuantum > 0.0)
            {
                if ((double)curr.GetHighFrame() < Math.Floor(next))
                {
                    double over = frameNumber - (double)curr.GetHighFrame() - 1.0;
                    if (over < 0.0)
                    {
                        over = 0.0;
                    }

                    timeLeft = Math.Abs(framerate) <= Epsilon ? 0.0 : over / framerate;
                    advanceAnim = true;
                    frameNumber = curr.GetHighFrame();
                }

                for (; Math.Floor(frameNumber) > lastFrame; ++lastFrame)
                {
                    // non-retail (#38): the first frame from an identity offset frame may come from the memo (RootMotionMemo.cs)
                    RootMotionMemo? memo = _rootMotionMemo;
                    if (hasFrame && (memo is null || !TryRootMotionFromMemo(memo, curr, lastFrame, quantum, ref retval)))
                    {
                        curr.CombinePosFrame(lastFrame, ref retval);

                        if (Math.Abs(framerate) > Epsilon)
                        {
                            ApplyPhysics(ref retval, 1.0 / framerate, quantum);
                        }
                    }

                    ExecuteHooks(curr.GetPartFrame(lastFrame), 1);
                }
            }
            else
            {
                if (frameQuantum >= 0.0)
                {
                    break;
                }

                if ((double)curr.GetLowFrame() > Math.Floor(next))
                {
                    double under = frameNumber - (double)curr.GetLowFrame();
                    if (under > 0.0)
                    {
                        under = 0.0;
                    }

                    timeLeft = Math.Abs(framerate) <= Epsilon ? 0.0 : under / framerate;
                    advanceAnim = true;
                    frameNumber = curr.GetLowFrame();
                }

                for (; Math.Floor(frameNumber) < lastFrame; --lastFrame)
                {
                    if (hasFrame)
                    {
                        if (curr.TryGetPosFrame(lastFrame, out AFrame pos))
                        {
                            AFrame.Subtract1(ref retval, pos);
                        }

                        if (Math.Abs(framerate) > Epsilon)
                        {
                            ApplyPhysics(ref retval, 1.0 / framerate, quantum);
                        }
                    }

                    ExecuteHooks(curr.GetPartFrame(lastFrame), -1);
                }
            }

            if (!advanceAnim)
            {
                return;
            }

            if (_hookObj is not null && _head != _firstCyclic)
            {
                AddAnimHook(_hookObj, _animDoneHook);
            }

            AdvanceToNextAnimation(quantum, ref currAnim, ref frameNumber, ref retval, hasFrame);
            // non-retail: from a started animation each pass uses at least one frame's time, so the time left shrinks; when
            // it does not (a frame shorter than the quantum's precision) the rest of the step is dropped rather than loop
            // without end. The first pass may start mid-range (a frame number from before a change) and is not checked.
            if (advanced && !(Math.Abs(timeLeft) < Math.Abs(quantum)))
            {
                return;
            }

            advanced = true;
            quantum = timeLeft;
        }

        if (hasFrame && Math.Abs(quantum) > Epsilon)
        {
            ApplyPhysics(ref retval, quantum, quantum);
        }
    }

    /// <summary>
    /// Moves on from the animation that ended to the next one (forwards in time) or the previous one (backwards), looping
    /// to the first cyclic animation past the end or to the last past the start, and squares the root motion: the ended
    /// animation's last frame is taken back when it played against the direction of time, and the new animation's first
    /// frame is applied when it plays with it.
    /// </summary>
    // retail: CSequence::advance_to_next_animation (acclient.c:340472)
    internal void AdvanceToNextAnimation(double quantum, ref AnimSequenceNode? currAnim, ref double frameNumber, ref Frame retval, bool hasFrame)
    {
        AnimSequenceNode curr = currAnim!;
        if (quantum < 0.0)
        {
            if (curr.GetFramerate() >= 0.0 && hasFrame)
            {
                if (curr.TryGetPosFrame(frameNumber, out AFrame pos))
                {
                    AFrame.Subtract1(ref retval, pos);
                }

                if (Math.Abs((double)curr.GetFramerate()) > Epsilon)
                {
                    ApplyPhysics(ref retval, 1.0 / curr.GetFramerate(), quantum);
                }
            }

            curr = curr.GetPrev() ?? _tail!;
            currAnim = curr;
            frameNumber = curr.GetEndingFrame();
            if (curr.GetFramerate() < 0.0 && hasFrame)
            {
                if (curr.TryGetPosFrame(frameNumber, out AFrame pos))
                {
                    AFrame.Combine(ref retval, pos);
                }

                if (Math.Abs((double)curr.GetFramerate()) > Epsilon)
                {
                    ApplyPhysics(ref retval, 1.0 / curr.GetFramerate(), quantum);
                }
            }
        }
        else
        {
            if (curr.GetFramerate() < 0.0 && hasFrame)
            {
                if (curr.TryGetPosFrame(frameNumber, out AFrame pos))
                {
                    AFrame.Subtract1(ref retval, pos);
                }

                if (Math.Abs((double)curr.GetFramerate()) > Epsilon)
                {
                    ApplyPhysics(ref retval, 1.0 / curr.GetFramerate(), quantum);
                }
            }

            curr = curr.GetNext() ?? _firstCyclic!;
            currAnim = curr;
            frameNumber = curr.GetStartingFrame();
            if (curr.GetFramerate() > 0.0 && hasFrame)
            {
                if (curr.TryGetPosFrame(frameNumber, out AFrame pos))
                {
                    AFrame.Combine(ref retval, pos);
                }

                if (Math.Abs((double)curr.GetFramerate()) > Epsilon)
                {
                    ApplyPhysics(ref retval, 1.0 / curr.GetFramerate(), quantum);
                }
            }
        }
    }

    /// <summary>
    /// Moves <paramref name="frame"/> by |<paramref name="quantum"/>| seconds of the sequence's velocity and omega (in the
    /// frame's local axes), negated when <paramref name="sign"/> is negative.
    /// </summary>
    /// <remarks>The y and z displacements are rounded to float before they are added (retail keeps them in a float
    /// temporary), the x one is not.</remarks>
    // retail: CSequence::apply_physics (acclient.c:339859)
    internal void ApplyPhysics(ref Frame frame, double quantum, double sign)
    {
        double s = Math.Abs(quantum);
        if (sign < 0.0)
        {
            s = -s;
        }

        // The origin is read and written a component at a time and omega·s handed on as components: no Vector3 packing (#38).
        double dx = s * _velocity.X;
        float dy = (float)(s * _velocity.Y);
        float dz = (float)(s * _velocity.Z);
        frame.Origin.X = (float)(dx + frame.Origin.X);
        frame.Origin.Y = (float)((double)dy + frame.Origin.Y);
        frame.Origin.Z = (float)((double)dz + frame.Origin.Z);
        float wx = (float)(s * _omega.X);
        float wy = (float)(s * _omega.Y);
        float wz = (float)(s * _omega.Z);
        frame.Rotate(wx, wy, wz, ref _rotation);
    }

    // The axis-angle rotation of the last omega step (Frame::grotate's first half), kept while its displacement repeats.
    private AxisAngleCache _rotation;

    /// <summary>Queues on the hook object each hook of <paramref name="animFrame"/> whose direction is both or
    /// <paramref name="dir"/>, in list order.</summary>
    // retail: CSequence::execute_hooks (acclient.c:339682)
    [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
    internal void ExecuteHooks(AnimFrame? animFrame, int dir)
    {
        PhysicsObj? obj = _hookObj;
        // non-retail: a frame outside the animation (retail's null AnimFrame, only from an animation without frames) has no
        // hooks
        if (obj is not null && animFrame is not null && animFrame.Hooks is not null)
        {
            QueueHooks(obj, animFrame.Hooks, dir);
        }
    }

    // execute_hooks' walk of the frame's hook list, out of line (#38): the update inlines only the tests above, which on
    // most frames (no hook object, or a frame without hooks) are all there is.
    private static void QueueHooks(PhysicsObj obj, AnimHook hooks, int dir)
    {
        for (AnimHook? i = hooks; i is not null; i = i.Next)
        {
            int d = (int)i.Direction;
            if (d == 0 || dir == d)
            {
                AddAnimHook(obj, i);
            }
        }
    }

    // CPhysicsObj::add_anim_hook; an object removed from its world takes no more hooks.
    private static void AddAnimHook(PhysicsObj obj, AnimHook hook)
    {
        if (!obj.RemovedFromWorld)
        {
            obj.AddAnimHook(hook);
        }
    }
}
