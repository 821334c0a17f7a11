using System;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Terrain;

/// <summary>
/// The 256-entry table that maps a landblock vertex's height index (0..255) to metres. Retail:
/// <c>LandDefs::Land_Height_Table</c>, loaded from the region description (portal.dat 0x13000000) through
/// <c>LandDefs::set_height_table</c>. It is data, never hard-wired: pass it in.
/// </summary>
/// <remarks>Retail accepts an entry only when <c>0 &lt;= h &lt;= 1000 - 200</c> (sky height minus max object height,
/// 800 m) and stops at the first bad entry after copying the ones before it. This port validates the whole table first
/// and rejects it without any partial state.</remarks>
public sealed class LandHeightTable
{
    /// <summary>The number of entries (256).</summary>
    public const int Count = 256;

    /// <summary>The largest accepted height, in metres: <c>1000 - 200</c> (retail sky_height - max_obj_height).</summary>
    public const float MaxHeight = LandDefs.SkyHeight - LandDefs.MaxObjHeight;

    private readonly float[] _heights;

    /// <summary>Creates the table from 256 heights in metres.</summary>
    /// <exception cref="ArgumentException">Not exactly 256 entries, or an entry is NaN, negative or above 800 m.</exception>
    // retail: LandDefs::set_height_table (acclient.c:467321)
    public LandHeightTable(ReadOnlySpan<float> heights)
    {
        if (heights.Length != Count)
        {
            throw new ArgumentException($"The land height table has {Count} entries; got {heights.Length}.", nameof(heights));
        }

        for (int i = 0; i < Count; i++)
        {
            float h = heights[i];
            if (!(h >= 0f && MaxHeight >= h))
            {
                throw new ArgumentException($"Land height table entry {i} ({h}) is outside 0..{MaxHeight} m.", nameof(heights));
            }
        }

        _heights = heights.ToArray();
    }

    /// <summary>The height, in metres, of height index <paramref name="index"/>.</summary>
    public float this[byte index] => _heights[index];

    /// <summary>All 256 heights, in metres.</summary>
    public ReadOnlySpan<float> Heights => _heights;
}
