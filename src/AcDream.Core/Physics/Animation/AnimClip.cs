using System;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Animation;

/// <summary>
/// An animation read from a data file entry (type 0x03; retail <c>CAnimation</c>, CAnim.c): per frame, each part's frame
/// and the frame's hooks, and optionally a root-motion step per frame (<see cref="PosFrames"/>) that a playing
/// <see cref="AnimSequence"/> applies to the object as it crosses the frame. Immutable; one instance is shared by every
/// object that plays it.
/// </summary>
public sealed class AnimClip
{
    private readonly AFrame[]? _posFrames;
    private readonly AnimFrame[] _partFrames;
    private readonly Frame[]? _posFromIdentity;

    // retail: CAnimation::CAnimation (acclient.c:333676)
    internal AnimClip(uint id, int numParts, AFrame[]? posFrames, AnimFrame[] partFrames, bool hasHooks)
    {
        Id = id;
        NumParts = numParts;
        _posFrames = posFrames;
        _partFrames = partFrames;
        HasHooks = hasHooks;
        _posFromIdentity = CombineFromIdentity(posFrames);
    }

    /// <summary>The animation's data id (the entry's first word, retail <c>m_DID</c>).</summary>
    public uint Id { get; }

    /// <summary>Number of parts each frame moves (retail <c>num_parts</c>).</summary>
    public int NumParts { get; }

    /// <summary>Number of frames (retail <c>num_frames</c>).</summary>
    public int NumFrames => _partFrames.Length;

    /// <summary>The data's "has hooks" flag (bit 1 of the entry's flags; retail <c>has_hooks</c>).</summary>
    public bool HasHooks { get; }

    /// <summary>True when the animation carries a root-motion step per frame (retail <c>pos_frames</c> not null).</summary>
    public bool HasPosFrames => _posFrames is not null;

    /// <summary>The root-motion step of each frame (empty when <see cref="HasPosFrames"/> is false).</summary>
    public ReadOnlySpan<AFrame> PosFrames => _posFrames;

    /// <summary>Each frame's part frames and hooks (retail <c>part_frames</c>).</summary>
    public ReadOnlySpan<AnimFrame> PartFrames => _partFrames;

    internal AFrame[]? PosFramesArray => _posFrames;

    internal AnimFrame[] PartFramesArray => _partFrames;

    /// <summary>
    /// For each root-motion frame, <see cref="Frame.Identity"/> combined with it (CSequence's <c>Frame::combine</c>,
    /// <see cref="AFrame.Combine"/>): what the first frame an update crosses gives, since every update starts from an
    /// identity offset frame (<c>CPhysicsObj::UpdatePositionInternal</c>). Null when there are no root-motion frames or one
    /// is not finite (a NaN's payload is not promised to come out of the arithmetic the same way twice).
    /// </summary>
    internal Frame[]? PosFromIdentityArray => _posFromIdentity;

    // non-retail (#38): the combine of an identity frame with each root-motion frame, worked out once by the same code that
    // would work it out on every update, so the shortcut is bit-identical by construction.
    private static Frame[]? CombineFromIdentity(AFrame[]? posFrames)
    {
        if (posFrames is null || posFrames.Length == 0)
        {
            return null;
        }

        var combined = new Frame[posFrames.Length];
        for (int i = 0; i < posFrames.Length; i++)
        {
            AFrame p = posFrames[i];
            if (!VectorMath.IsFinite(p.Origin) || !VectorMath.IsFinite(p.Rotation))
            {
                return null;
            }

            Frame f = Frame.Identity;
            AFrame.Combine(ref f, p);
            combined[i] = f;
        }

        return combined;
    }

    /// <summary>
    /// Reads an animation from a data-file entry's bytes (after the dat container): the entry's data id, then retail
    /// <c>CAnimation::UnPack</c>: flags (bit 0: root-motion frames present, bit 1: has hooks), the part count, the frame
    /// count, the root-motion frames when present, then each frame's part frames and hooks.
    /// </summary>
    /// <param name="entry">The entry's bytes. Bytes after the animation are ignored, as retail ignores them.</param>
    /// <exception cref="RetailDataFormatException">Truncated or inconsistent bytes: a count larger than the bytes left, a frame
    /// that is not finite or not a unit quaternion, an unknown hook type, a hook value outside its domain. Nothing is returned
    /// half-built.</exception>
    public static AnimClip UnPack(ReadOnlySpan<byte> entry)
    {
        var reader = new RetailDataReader(entry, "CAnimation");
        uint id = reader.ReadUInt32("CAnimation id");
        return UnPack(ref reader, id);
    }

    // retail: CAnimation::UnPack (acclient.c:334085)
    internal static AnimClip UnPack(ref RetailDataReader reader, uint id)
    {
        uint flags = reader.ReadUInt32("CAnimation flags");
        uint numPartsWord = reader.ReadUInt32("CAnimation num_parts");
        int countAt = reader.Offset;
        uint numFramesWord = reader.ReadUInt32("CAnimation num_frames");
        bool hasPos = (flags & 1) != 0;

        // Every frame needs at least its part frames (28 bytes each) and its hook count; with root motion, 28 bytes more.
        // Compared by division: the product of two 32-bit counts can pass any integer type.
        long perFrame = 4L + 28L * numPartsWord + (hasPos ? 28L : 0L);
        if (numFramesWord != 0 && numFramesWord > reader.Remaining / perFrame)
        {
            throw reader.ErrorAt(countAt, $"CAnimation num_frames {numFramesWord} × {perFrame} bytes exceeds the {reader.Remaining} bytes left");
        }

        if (numPartsWord > int.MaxValue)
        {
            throw reader.ErrorAt(countAt - 4, $"CAnimation num_parts {numPartsWord} is not a count");
        }

        int numParts = (int)numPartsWord;
        int numFrames = (int)numFramesWord;
        AFrame[]? posFrames = null;
        if (hasPos)
        {
            posFrames = numFrames == 0 ? Array.Empty<AFrame>() : new AFrame[numFrames];
            for (int i = 0; i < numFrames; i++)
            {
                posFrames[i] = reader.ReadAFrame("CAnimation pos_frame");
            }
        }

        bool hasHooks = ((flags >> 1) & 1) != 0;
        AnimFrame[] partFrames = numFrames == 0 ? Array.Empty<AnimFrame>() : new AnimFrame[numFrames];
        for (int i = 0; i < numFrames; i++)
        {
            partFrames[i] = AnimFrame.UnPack(ref reader, numParts, countAt - 4);
        }

        return new AnimClip(id, numParts, posFrames, partFrames, hasHooks);
    }
}
