using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Debug;

/// <summary>
/// Where <see cref="PhysicsDebugDraw"/> looks and the frame it answers in (library addition). <b>The frame</b>: the one
/// landblock frame of <see cref="FrameCellId"/>'s landblock (x east, y north, z up, its south-west corner at the origin), the
/// frame every position in that landblock is local to; shapes of other landblocks are moved into it by their block offset
/// (retail <c>LandDefs::get_block_offset</c>). Frame cell 0 is the world's south-west corner, so its frame is the global one
/// (but a float's resolution at 40 km is 4 mm: a renderer near the player asks in the player's landblock). <b>The box</b>, when
/// given, is in that frame (x and y; z is not tested): land cells whose 24 m square overlaps it, the buildings hung on them (a
/// building is drawn with the one cell it hangs on), indoor cells whose walls' and portals' x-y bounds overlap it, and objects whose origin lies in it (edges included).
/// </summary>
public readonly struct DebugDrawRegion
{
    private DebugDrawRegion(uint frameCellId, bool hasBox, Vector2 min, Vector2 max)
    {
        FrameCellId = frameCellId;
        HasBox = hasBox;
        Min = min;
        Max = max;
    }

    /// <summary>Every loaded cell and object, in the frame of <paramref name="frameCellId"/>'s landblock (0: global).</summary>
    /// <param name="frameCellId">Any cell or landblock id <c>0xXXYY....</c> of the frame's landblock, or 0.</param>
    /// <exception cref="ArgumentException">The landblock lies outside the world (a column or row above 254).</exception>
    public static DebugDrawRegion Everything(uint frameCellId = 0)
    {
        ThrowIfOutside(frameCellId);
        return new DebugDrawRegion(frameCellId, false, default, default);
    }

    /// <summary>The cells and objects within the box <paramref name="min"/>..<paramref name="max"/> (x, y metres in the frame
    /// of <paramref name="frameCellId"/>'s landblock).</summary>
    /// <param name="frameCellId">Any cell or landblock id of the frame's landblock, or 0 (global).</param>
    /// <param name="min">The box's south-west corner: finite.</param>
    /// <param name="max">The box's north-east corner: finite, at least <paramref name="min"/> in x and y.</param>
    /// <exception cref="ArgumentException">A corner is not finite, <paramref name="max"/> is below <paramref name="min"/>, or
    /// the landblock lies outside the world.</exception>
    public static DebugDrawRegion Box(uint frameCellId, Vector2 min, Vector2 max)
    {
        ThrowIfOutside(frameCellId);
        if (!float.IsFinite(min.X) || !float.IsFinite(min.Y) || !float.IsFinite(max.X) || !float.IsFinite(max.Y)
            || max.X < min.X || max.Y < min.Y)
        {
            throw new ArgumentException("The box needs finite corners with max >= min in x and y.", nameof(max));
        }

        return new DebugDrawRegion(frameCellId, true, min, max);
    }

    /// <summary>A cell id of the frame's landblock (0: the global frame).</summary>
    public uint FrameCellId { get; }

    /// <summary>True when the region is a box; false for everything loaded.</summary>
    public bool HasBox { get; }

    /// <summary>The box's south-west corner in the frame (when <see cref="HasBox"/>).</summary>
    public Vector2 Min { get; }

    /// <summary>The box's north-east corner in the frame (when <see cref="HasBox"/>).</summary>
    public Vector2 Max { get; }

    private static void ThrowIfOutside(uint frameCellId)
    {
        if ((frameCellId >> 24) >= LandDefs.LandblocksPerSide || ((frameCellId >> 16) & 0xFF) >= LandDefs.LandblocksPerSide)
        {
            throw new ArgumentException($"Cell 0x{frameCellId:X8} lies outside the world.", nameof(frameCellId));
        }
    }

    // The x-y box [min, max] overlaps this region.
    internal bool Overlaps(float minX, float minY, float maxX, float maxY) =>
        !HasBox || (maxX >= Min.X && minX <= Max.X && maxY >= Min.Y && minY <= Max.Y);

    internal bool Contains(Vector3 p) => !HasBox || (p.X >= Min.X && p.X <= Max.X && p.Y >= Min.Y && p.Y <= Max.Y);
}
