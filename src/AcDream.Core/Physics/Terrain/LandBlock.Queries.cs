using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Terrain;

// Per-point terrain queries: water depth and terrain type by nearest corner.
public sealed partial class LandBlock
{
    /// <summary>Water depth, in metres, in a partly-water cell whose nearest corner is water. Retail: 0.44999999 (0.45f).</summary>
    public const float PartialWaterDepthWaterCorner = 0.45f;

    /// <summary>Water depth, in metres, in a partly-water cell whose nearest corner is solid. Retail: 0.1.</summary>
    public const float PartialWaterDepthSolidCorner = 0.1f;

    /// <summary>
    /// The water depth used for a point in a partly-water cell: <see cref="PartialWaterDepthWaterCorner"/> (0.45 m) when
    /// the cell corner nearest to <paramref name="point"/> is water, else <see cref="PartialWaterDepthSolidCorner"/> (0.1 m).
    /// </summary>
    /// <param name="cellId">An outdoor cell id; only its low word (the cell within the block) is used, as in retail.</param>
    /// <param name="point">A landblock-local point (metres); only x and y are used.</param>
    /// <exception cref="ArgumentException">The id is not an outdoor cell id (low word 1..64).</exception>
    // retail: CLandBlockStruct::calc_water_depth (acclient.c:353645)
    public float CalcWaterDepth(uint cellId, Vector3 point)
    {
        ushort word = NearestCornerTerrain(cellId, point);
        return TerrainTypes.IsWater(word) ? PartialWaterDepthWaterCorner : PartialWaterDepthSolidCorner;
    }

    /// <summary>
    /// The terrain type (0..31) of the corner of cell <paramref name="cellId"/> nearest to <paramref name="point"/>
    /// (landblock-local).
    /// </summary>
    /// <exception cref="ArgumentException">The id is not an outdoor cell id (low word 1..64).</exception>
    // retail: CLandBlock::get_terrain (acclient.c:352008)
    public int GetTerrain(uint cellId, Vector3 point) => TerrainTypes.TypeOf(NearestCornerTerrain(cellId, point));

    // The corner is chosen by quadrant: west when x <= the cell's centre line (2x + 1) * 12, south when y <= (2y + 1) * 12.
    // The x comparison survives in get_terrain (acclient.c:352008); the y comparison was lost by the decompiler in both
    // functions — its flag pattern reads as "point.y <= centre", so ties go to the lower corner on both axes
    // (docs/divergences.md, "Water depth: nearest corner on the centre line").
    private ushort NearestCornerTerrain(uint cellId, Vector3 point)
    {
        if (!LandDefs.IsOutdoorCell(cellId))
        {
            throw new ArgumentException($"0x{cellId:X8} is not an outdoor cell id.", nameof(cellId));
        }

        int c = (int)(cellId & 0xFFFF) - 1;
        int x = c >> 3;
        int y = c & 7;
        double centreX = ((double)x + x + 1.0) * LandDefs.HalfCellLength;
        double centreY = ((double)y + y + 1.0) * LandDefs.HalfCellLength;
        int vx = centreX >= point.X ? x : x + 1;
        int vy = centreY >= point.Y ? y : y + 1;
        return _terrain[vx * SideVertexCount + vy];
    }
}
