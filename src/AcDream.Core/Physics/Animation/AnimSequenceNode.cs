using System;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Animation;

/// <summary>
/// One queued animation of an <see cref="AnimSequence"/>: the animation, its frame range and framerate, linked to its
/// neighbours (retail <c>AnimSequenceNode</c>, CSeqPrim.c, a <c>DLListData</c>). Nodes are pooled by their sequence.
/// </summary>
internal sealed class AnimSequenceNode
{
    // retail: AnimSequenceNode::AnimSequenceNode (acclient.c:341071)
    internal AnimSequenceNode()
    {
        Reset();
    }

    /// <summary>The next node (retail <c>dllist_next</c>); in the pool, the next free node.</summary>
    internal AnimSequenceNode? Next;

    /// <summary>The previous node (retail <c>dllist_prev</c>).</summary>
    internal AnimSequenceNode? Prev;

    /// <summary>The animation (retail <c>anim</c>), or null.</summary>
    internal AnimClip? Anim;

    /// <summary>Frames per second, negative backwards (retail <c>framerate</c>).</summary>
    internal float Framerate;

    /// <summary>First frame (retail <c>low_frame</c>).</summary>
    internal int LowFrame;

    /// <summary>Last frame (retail <c>high_frame</c>).</summary>
    internal int HighFrame;

    // The default node's fields (the constructor's: no animation, 30 frames per second, frames -1 to -1).
    internal void Reset()
    {
        Next = null;
        Prev = null;
        Anim = null;
        Framerate = AnimData.DefaultFramerate;
        LowFrame = -1;
        HighFrame = -1;
    }

    /// <summary>Sets the node from <paramref name="data"/> and resolves its animation through <paramref name="source"/>.</summary>
    // retail: AnimSequenceNode::AnimSequenceNode (acclient.c:341288)
    internal void Init(in AnimData data, IAnimationSource? source)
    {
        Next = null;
        Prev = null;
        Anim = null;
        Framerate = data.Framerate;
        LowFrame = data.LowFrame;
        HighFrame = data.HighFrame;
        SetAnimationId(data.AnimId, source);
    }

    /// <summary>Looks the animation up and clamps the frame range to it: a negative high frame means the last frame; each end
    /// at most the last frame (compared unsigned, so a negative low frame also becomes the last); high at least low.</summary>
    // retail: AnimSequenceNode::set_animation_id (acclient.c:341084)
    internal void SetAnimationId(uint id, IAnimationSource? source)
    {
        Anim = id != 0 ? source?.GetAnimation(id) : null;
        AnimClip? anim = Anim;
        if (anim is not null)
        {
            uint numFrames = (uint)anim.NumFrames;
            if (HighFrame < 0)
            {
                HighFrame = (int)(numFrames - 1);
            }

            if ((uint)LowFrame >= numFrames)
            {
                LowFrame = (int)(numFrames - 1);
            }

            if ((uint)HighFrame >= numFrames)
            {
                HighFrame = (int)(numFrames - 1);
            }

            if (LowFrame > HighFrame)
            {
                HighFrame = LowFrame;
            }
        }
    }

    /// <summary>True when the node has an animation.</summary>
    // retail: AnimSequenceNode::has_anim (acclient.c:341009)
    internal bool HasAnim() => Anim is not null;

    /// <summary>The framerate (retail's accessor, folded with <c>MD_Data_Fade::GetDuration</c>).</summary>
    // retail: MD_Data_Fade::GetDuration (acclient.c:694301)
    internal float GetFramerate() => Framerate;

    /// <summary>The last frame.</summary>
    // retail: AnimSequenceNode::get_high_frame (acclient.c:285663)
    internal int GetHighFrame() => HighFrame;

    /// <summary>The first frame (retail's accessor, folded with <c>PhysicsDesc::get_animframe_id</c>).</summary>
    // retail: PhysicsDesc::get_animframe_id (acclient.c:286428)
    internal int GetLowFrame() => LowFrame;

    /// <summary>Multiplies the framerate; a negative multiplier also swaps the low and high frames.</summary>
    // retail: AnimSequenceNode::multiply_framerate (acclient.c:340967)
    internal void MultiplyFramerate(float multiplier)
    {
        if (multiplier < 0.0)
        {
            (LowFrame, HighFrame) = (HighFrame, LowFrame);
        }

        float framerate = multiplier * Framerate;
        // non-retail: the product stays within the framerate domain (a NaN multiplier leaves it unchanged), so that one
        // update crosses a bounded number of frames
        if (!float.IsNaN(framerate))
        {
            Framerate = Math.Clamp(framerate, -AnimData.MaxFramerate, AnimData.MaxFramerate);
        }
    }

    /// <summary>The root-motion step of frame <paramref name="fn"/>, or false when there is no animation or the frame is out
    /// of range (retail returns a null pointer).</summary>
    // retail: AnimSequenceNode::get_pos_frame (acclient.c:340981)
    [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)] // #38
    internal bool TryGetPosFrame(int fn, out AFrame frame)
    {
        AnimClip? anim = Anim;
        AFrame[]? pos = anim?.PosFramesArray;
        if (anim is not null && pos is not null && fn >= 0 && fn < anim.NumFrames)
        {
            frame = pos[fn];
            return true;
        }

        frame = default;
        return false;
    }

    /// <summary>
    /// Combines frame <paramref name="fn"/>'s root motion into <paramref name="retval"/> (CSequence's <c>Frame::combine</c>
    /// of <c>get_pos_frame</c>), nothing when there is none. An identity <paramref name="retval"/> (every update's first
    /// frame crossed) takes the combine worked out when the animation was read.
    /// </summary>
    // non-retail (#38): the shortcut of AnimClip.PosFromIdentityArray, bit-identical to AFrame.Combine
    [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
    internal void CombinePosFrame(int fn, ref Frame retval)
    {
        AnimClip? anim = Anim;
        AFrame[]? pos = anim?.PosFramesArray;
        if (anim is not null && pos is not null && fn >= 0 && fn < anim.NumFrames)
        {
            Frame[]? fromIdentity = anim.PosFromIdentityArray;
            if (fromIdentity is not null && retval.HasIdentityBits())
            {
                retval = fromIdentity[fn];
            }
            else
            {
                AFrame.Combine(ref retval, pos[fn]);
            }
        }
    }

    /// <summary>get_pos_frame at a fractional frame number: its floor.</summary>
    // retail: AnimSequenceNode::get_pos_frame (acclient.c:339640)
    internal bool TryGetPosFrame(double frameNumber, out AFrame frame) => TryGetPosFrame(FloorToFrame(frameNumber), out frame);

    /// <summary>Frame <paramref name="fn"/>'s part frames and hooks, or null when there is no animation or it is out of range.</summary>
    // retail: AnimSequenceNode::get_part_frame (acclient.c:340995)
    internal AnimFrame? GetPartFrame(int fn)
    {
        AnimClip? anim = Anim;
        if (anim is not null && fn >= 0 && fn < anim.NumFrames)
        {
            return anim.PartFramesArray[fn];
        }

        return null;
    }

    /// <summary>Where playback starts: the low frame, or just below high + 1 when playing backwards (high + 1 − EPSILON, the float
    /// 0.0002f widened to double: for high frame 9, 0x4023FFE5C91D2000).</summary>
    // retail: AnimSequenceNode::get_starting_frame (acclient.c:341015)
    internal double GetStartingFrame()
    {
        if (Framerate < 0.0)
        {
            return (double)(HighFrame + 1) - (double)PhysicsGlobals.Epsilon;
        }

        return LowFrame;
    }

    /// <summary>Where playback ends: just below high + 1, or the low frame when playing backwards.</summary>
    // retail: AnimSequenceNode::get_ending_frame (acclient.c:341027)
    internal double GetEndingFrame()
    {
        if (Framerate < 0.0)
        {
            return LowFrame;
        }

        return (double)(HighFrame + 1) - (double)PhysicsGlobals.Epsilon;
    }

    /// <summary>The next node, or null.</summary>
    // retail: AnimSequenceNode::GetNext (acclient.c:341126)
    internal AnimSequenceNode? GetNext() => Next;

    /// <summary>The previous node, or null.</summary>
    // retail: AnimSequenceNode::GetPrev (acclient.c:341140)
    internal AnimSequenceNode? GetPrev() => Prev;

    /// <summary>Reads a node: animation id, low frame, high frame, framerate, then resolves the animation.</summary>
    /// <exception cref="RetailDataFormatException">Fewer than 16 bytes remain, or the framerate is outside the domain.</exception>
    // retail: AnimSequenceNode::UnPack (acclient.c:341256)
    internal void UnPack(ref RetailDataReader reader, IAnimationSource? source)
    {
        AnimData data = AnimData.UnPack(ref reader);
        Framerate = data.Framerate;
        LowFrame = data.LowFrame;
        HighFrame = data.HighFrame;
        SetAnimationId(data.AnimId, source);
    }

    // The frame index retail passes on: floor, converted to a 64-bit integer and truncated to 32 bits. Out of that range (or
    // NaN) it is a frame no animation has.
    internal static int FloorToFrame(double frameNumber)
    {
        double f = Math.Floor(frameNumber);
        return f >= int.MinValue && f <= int.MaxValue ? (int)f : -1;
    }
}
