using System;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Core.Physics.Scenery;

// The road test of the scenery: sixteen cases of the four corners' road bits.
public static partial class SceneryGenerator
{
    /// <summary>The road half-width, metres: <c>LandDefs::road_width</c>, compiled in (<c>LandDefs::get_vars</c>,
    /// acclient.c:467308; the region's copy is read and discarded).</summary>
    public const float RoadWidth = 5f;

    /// <summary>
    /// True when the block-local point (<paramref name="x"/>, <paramref name="y"/>) lies on a road, by the road bits (0–1)
    /// of the four corners of its land cell: A south-west, B north-west, C south-east, D north-east; with <c>dx</c>, <c>dy</c>
    /// the offsets in the cell, <c>W = 5</c> and <c>F = 24 − 5 = 19</c>:
    /// <list type="bullet">
    /// <item>no corner: false; all four: true;</item>
    /// <item>two on an edge: the strip along it, A B <c>dx &lt; W</c>, A C <c>dy &lt; W</c>, C D <c>dx &gt; F</c>, B D
    /// <c>dy &gt; F</c>;</item>
    /// <item>three: the two strips, A B C <c>dx &lt; W ∨ dy &lt; W</c>, A B D <c>dx &lt; W ∨ dy &gt; F</c>, A C D
    /// <c>dx &gt; F ∨ dy &lt; W</c>, B C D <c>dx &gt; F ∨ dy &gt; F</c>;</item>
    /// <item>two on a diagonal: the band along it, A D <c>|dx − dy| &lt; W</c>, B C <c>|dx + dy − 24| &lt; W</c>;</item>
    /// <item>one: the corner's triangle, A <c>dx + dy &lt; W</c>, B <c>dy − dx &gt; F</c>, C <c>dx − dy &gt; F</c>, D
    /// <c>dx + dy &gt; 48 − W</c>.</item>
    /// </list>
    /// The decompilation keeps the first ten cases; the x87 compares of the last six (diagonals and single corners) are
    /// lost, and they are reconstructed from the geometry of the ten (see docs/divergences.md, "Procedural scenery").
    /// </summary>
    /// <param name="terrain">The landblock's 81 terrain words (index <c>x · 9 + y</c>).</param>
    /// <param name="x">Block-local x, metres, in [0, 192).</param>
    /// <param name="y">Block-local y, metres, in [0, 192).</param>
    /// <exception cref="ArgumentException"><paramref name="terrain"/> is not 81 long.</exception>
    /// <exception cref="ArgumentOutOfRangeException">A coordinate is outside [0, 192) or NaN.</exception>
    // retail: CLandBlock::on_road (acclient.c:352237)
    public static bool OnRoad(ReadOnlySpan<ushort> terrain, float x, float y)
    {
        if (terrain.Length != LandBlock.VertexCount)
        {
            throw new ArgumentException($"A landblock has {LandBlock.VertexCount} terrain words.", nameof(terrain));
        }

        if (!(x >= 0f && x < LandDefs.BlockLength))
        {
            throw new ArgumentOutOfRangeException(nameof(x), x, "A block-local coordinate lies in [0, 192).");
        }

        if (!(y >= 0f && y < LandDefs.BlockLength))
        {
            throw new ArgumentOutOfRangeException(nameof(y), y, "A block-local coordinate lies in [0, 192).");
        }

        return OnRoadUnchecked(terrain, x, y);
    }

    // retail: CLandBlock::on_road (acclient.c:352237)
    internal static bool OnRoadUnchecked(ReadOnlySpan<ushort> terrain, float x, float y)
    {
        const double cell = 24.0;
        const float far = (float)(cell - RoadWidth); // rmax = 24.0 - 5.0
        int ix = unchecked((int)(long)Math.Floor(x / cell));
        int iy = unchecked((int)(long)Math.Floor(y / cell));
        int c = ix + iy + 8 * ix;
        bool a = (terrain[c] & 3) != 0, b = (terrain[c + 1] & 3) != 0, sc = (terrain[c + 9] & 3) != 0, d = (terrain[c + 10] & 3) != 0;
        if (!a && !b && !sc && !d)
        {
            return false;
        }

        double dx = x - ix * cell;       // kept on the x87 stack
        float dy = (float)(y - iy * cell); // stored to a float
        int corners = (a ? 1 : 0) | (b ? 2 : 0) | (sc ? 4 : 0) | (d ? 8 : 0);
        return corners switch
        {
            0b1111 => true,
            0b0111 => dx < RoadWidth || dy < RoadWidth,     // A B C
            0b1011 => dx < RoadWidth || dy > far,           // A B D
            0b1101 => dx > far || dy < RoadWidth,           // A C D
            0b1110 => dx > far || dy > far,                 // B C D
            0b0011 => dx < RoadWidth,                       // A B
            0b0101 => dy < RoadWidth,                       // A C
            0b1100 => dx > far,                             // C D
            0b1010 => dy > far,                             // B D
            // The six cases below are reconstructed: the decompiler lost their compares (docs/divergences.md).
            0b1001 => Math.Abs(dx - dy) < RoadWidth,        // A D
            0b0110 => Math.Abs(dx + dy - cell) < RoadWidth, // B C
            0b0001 => dx + dy < RoadWidth,                  // A
            0b0010 => dy - dx > far,                        // B
            0b0100 => dx - dy > far,                        // C
            _ => dx + dy > 2 * cell - RoadWidth,            // D
        };
    }
}
