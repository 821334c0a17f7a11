using System;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Animation;

/// <summary>
/// One frame of an animation: a frame per part (relative to the object) and the hooks fired when the frame is crossed
/// (retail <c>AnimFrame</c>, CAnim.c). Also a setup's placement frame.
/// </summary>
public sealed class AnimFrame
{
    private readonly AFrame[] _frames;

    internal AnimFrame(AFrame[] frames, AnimHook? hooks, int numFrameHooks)
    {
        _frames = frames;
        Hooks = hooks;
        NumFrameHooks = numFrameHooks;
    }

    /// <summary>Each part's frame relative to the object (retail <c>frame</c>, <c>num_parts</c> of them).</summary>
    public ReadOnlySpan<AFrame> Frames => _frames;

    /// <summary>Number of parts (retail <c>num_parts</c>).</summary>
    public int NumParts => _frames.Length;

    /// <summary>The first of the frame's hooks, in data order (follow <see cref="AnimHook.Next"/>), or null (retail <c>hooks</c>).</summary>
    public AnimHook? Hooks { get; }

    /// <summary>Number of hooks (retail <c>num_frame_hooks</c>).</summary>
    public int NumFrameHooks { get; }

    /// <summary>
    /// Reads one animation frame of <paramref name="numParts"/> parts: the part frames, the hook count and the hooks
    /// (retail <c>AnimFrame::UnPack</c>).
    /// </summary>
    /// <exception cref="RetailDataFormatException">Truncated, a count larger than the bytes left, or a bad frame or hook.</exception>
    // retail: AnimFrame::UnPack (acclient.c:333869)
    internal static AnimFrame UnPack(ref RetailDataReader reader, int numParts, int numPartsAt)
    {
        // Each part frame is 28 bytes: checked before the array is sized by the count.
        reader.CheckCount((uint)numParts, "AnimFrame part frames", 28, numPartsAt);
        AFrame[] frames = numParts == 0 ? Array.Empty<AFrame>() : new AFrame[numParts];
        for (int i = 0; i < numParts; i++)
        {
            frames[i] = reader.ReadAFrame("AnimFrame part frame");
        }

        // Each hook is at least its type and direction words.
        int numHooks = reader.ReadCount("AnimFrame num_frame_hooks", 8);
        AnimHook? hooks = null;
        for (int i = 0; i < numHooks; i++)
        {
            AnimHook hook = AnimHook.UnPackHook(ref reader);
            hook.AddToList(ref hooks);
        }

        return new AnimFrame(frames, hooks, numHooks);
    }
}
