using System;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Animation;

/// <summary>
/// One animation to play: its data id, the frame range and the framerate (retail <c>AnimData</c>, CSeqPrim.c). A motion
/// table's motion data lists these; <see cref="AnimSequence"/> queues one per <c>append_animation</c>.
/// </summary>
/// <remarks>A negative framerate plays the range backwards. A high frame below zero means "the animation's last frame"
/// (resolved by <c>AnimSequenceNode::set_animation_id</c>).</remarks>
public readonly struct AnimData : IEquatable<AnimData>
{
    /// <summary>Retail's default framerate, 30 frames per second (the bits 0x41F00000 that <c>AnimData::AnimData</c> stores).</summary>
    public const float DefaultFramerate = 30f;

    /// <summary>The largest framerate magnitude accepted, frames per second (non-retail bound, see <see cref="Framerate"/>).</summary>
    public const float MaxFramerate = 10000f;

    /// <summary>Creates an AnimData (retail <c>AnimData</c> with its fields set).</summary>
    /// <param name="animId">The animation's data id (a 0x03 file id).</param>
    /// <param name="lowFrame">First frame of the range.</param>
    /// <param name="highFrame">Last frame of the range (below zero: the animation's last frame).</param>
    /// <param name="framerate">Frames per second: finite, |framerate| at most <see cref="MaxFramerate"/>; negative plays
    /// backwards.</param>
    /// <exception cref="ArgumentException">The framerate is NaN, infinite or beyond ±<see cref="MaxFramerate"/>.</exception>
    public AnimData(uint animId, int lowFrame, int highFrame, float framerate)
    {
        if (!IsFramerateInDomain(framerate))
        {
            throw new ArgumentException($"Framerate must be finite and within ±{MaxFramerate} frames per second.", nameof(framerate));
        }

        AnimId = animId;
        LowFrame = lowFrame;
        HighFrame = highFrame;
        Framerate = framerate;
    }

    /// <summary>The default AnimData: id 0, frames 0 to -1 (the whole animation), 30 frames per second.</summary>
    // retail: AnimData::AnimData (acclient.c:341039)
    public static AnimData Default => new(0u, 0, -1, DefaultFramerate);

    /// <summary>The animation's data id (retail <c>anim_id</c>).</summary>
    public uint AnimId { get; }

    /// <summary>First frame of the range (retail <c>low_frame</c>).</summary>
    public int LowFrame { get; }

    /// <summary>Last frame of the range; below zero the animation's last frame (retail <c>high_frame</c>).</summary>
    public int HighFrame { get; }

    /// <summary>Frames per second, negative to play backwards (retail <c>framerate</c>). Bounded by ±<see cref="MaxFramerate"/>
    /// (non-retail: a huge framerate made one update cross an unbounded number of animations).</summary>
    public float Framerate { get; }

    /// <summary>The same animation at <paramref name="scale"/> times the framerate.</summary>
    /// <exception cref="ArgumentException">The product is NaN, infinite or beyond ±<see cref="MaxFramerate"/>.</exception>
    // retail: operator* (acclient.c:341050)
    public static AnimData operator *(float scale, AnimData rhs)
    {
        float framerate = (float)((double)rhs.Framerate * scale);
        return new AnimData(rhs.AnimId, rhs.LowFrame, rhs.HighFrame, framerate);
    }

    /// <summary>Reads an AnimData (retail <c>AnimData::UnPack</c>: id, low frame, high frame, framerate; 16 bytes).</summary>
    /// <exception cref="RetailDataFormatException">Fewer than 16 bytes remain, or the framerate is outside the domain.</exception>
    // retail: AnimData::UnPack (acclient.c:341178)
    internal static AnimData UnPack(ref RetailDataReader reader)
    {
        if (reader.Remaining < 16)
        {
            throw reader.Error($"AnimData needs 16 bytes, {reader.Remaining} remain");
        }

        uint id = reader.ReadUInt32("AnimData anim_id");
        int low = reader.ReadInt32("AnimData low_frame");
        int high = reader.ReadInt32("AnimData high_frame");
        int at = reader.Offset;
        float framerate = reader.ReadSingle("AnimData framerate");
        if (!IsFramerateInDomain(framerate))
        {
            throw reader.ErrorAt(at, $"AnimData framerate {framerate} is not finite or beyond ±{MaxFramerate}");
        }

        return new AnimData(id, low, high, framerate);
    }

    internal static bool IsFramerateInDomain(float framerate) => float.IsFinite(framerate) && Math.Abs(framerate) <= MaxFramerate;

    /// <summary>Exact equality of the four fields (framerates compared as floats).</summary>
    public bool Equals(AnimData other) =>
        AnimId == other.AnimId && LowFrame == other.LowFrame && HighFrame == other.HighFrame && Framerate.Equals(other.Framerate);

    /// <inheritdoc />
    public override bool Equals(object? obj) => obj is AnimData other && Equals(other);

    /// <inheritdoc />
    public override int GetHashCode() => HashCode.Combine(AnimId, LowFrame, HighFrame, Framerate);

    /// <summary>Exact equality.</summary>
    public static bool operator ==(AnimData left, AnimData right) => left.Equals(right);

    /// <summary>Exact inequality.</summary>
    public static bool operator !=(AnimData left, AnimData right) => !left.Equals(right);
}
