using System;
using System.Diagnostics.CodeAnalysis;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Terrain;

// Point queries for clients: the triangle, height and water under a position.
public sealed partial class TerrainWorld
{
    /// <summary>The world's side, in metres: 255 landblocks × 192 m = 48,960 m.</summary>
    public const double WorldLength = LandDefs.LandblocksPerSide * (double)LandDefs.BlockLength;

    /// <summary>
    /// Finds the land cell and terrain triangle under <paramref name="p"/>'s origin (x, y only). The position may name any
    /// cell of any landblock and lie outside it; it is first re-homed with <see cref="LandDefs.AdjustToOutside"/>.
    /// Returns false when the point lies past the world edge or its landblock is not loaded. <paramref name="local"/> is
    /// the origin local to the found cell's landblock.
    /// </summary>
    /// <exception cref="ArgumentException">The origin has a NaN or infinite component.</exception>
    // retail: LandDefs::adjust_to_outside (acclient.c:467433), LScape::get_landcell (acclient.c:307511),
    //         CLandCell::find_terrain_poly (acclient.c:354858)
    public bool TryFindTerrainPoly(in Position p, [NotNullWhen(true)] out LandCell? cell, [NotNullWhen(true)] out Polygon? polygon, out Vector3 local)
    {
        if (!VectorMath.IsFinite(p.Frame.Origin))
        {
            throw new ArgumentException("The position's origin must be finite.", nameof(p));
        }

        uint id = p.ObjCellId;
        local = p.Frame.Origin;
        polygon = null;
        cell = null;
        if (!LandDefs.AdjustToOutside(ref id, ref local))
        {
            return false;
        }

        cell = GetLandCell(id);
        if (cell is null || !cell.FindTerrainPoly(local, out polygon))
        {
            cell = null;
            return false;
        }

        return true;
    }

    /// <summary>
    /// The terrain height, in metres, under <paramref name="p"/>'s origin: the triangle's plane evaluated at its x, y
    /// (retail's <c>find_terrain_poly</c> + <c>Plane::set_height</c>). Returns false past the world edge or over a
    /// landblock that is not loaded.
    /// </summary>
    /// <exception cref="ArgumentException">The origin has a NaN or infinite component.</exception>
    // retail: Plane::set_height (acclient.c:351337) after CLandCell::find_terrain_poly (acclient.c:354858)
    public bool TryGetTerrainHeight(in Position p, out float z)
    {
        if (TryFindTerrainPoly(p, out _, out Polygon? poly, out Vector3 local) && poly.Plane.SetHeight(ref local))
        {
            z = local.Z;
            return true;
        }

        z = 0f;
        return false;
    }

    /// <summary>
    /// The terrain height, in metres, at global coordinates (<paramref name="globalX"/>, <paramref name="globalY"/>):
    /// metres east and north of the world's south-west corner, so landblock (bx, by) spans
    /// <c>[bx * 192, bx * 192 + 192)</c>. Returns false outside <c>[0, 48960)</c> or over an unloaded landblock.
    /// </summary>
    /// <exception cref="ArgumentException">A coordinate is NaN or infinite.</exception>
    public bool TryGetTerrainHeight(double globalX, double globalY, out float z)
    {
        if (!double.IsFinite(globalX) || !double.IsFinite(globalY))
        {
            throw new ArgumentException("Global coordinates must be finite.", nameof(globalX));
        }

        z = 0f;
        if (!(globalX >= 0.0 && globalX < WorldLength && globalY >= 0.0 && globalY < WorldLength))
        {
            return false;
        }

        int bx = Math.Min((int)(globalX / LandDefs.BlockLength), LandDefs.LandblocksPerSide - 1);
        int by = Math.Min((int)(globalY / LandDefs.BlockLength), LandDefs.LandblocksPerSide - 1);
        var local = new Vector3((float)(globalX - bx * (double)LandDefs.BlockLength), (float)(globalY - by * (double)LandDefs.BlockLength), 0f);

        // Cell 1 of the block; AdjustToOutside then picks the right cell (and the next block if the float rounded to 192).
        var p = new Position(LandDefs.LCoordToGid(bx * LandDefs.BlockSide, by * LandDefs.BlockSide), local);
        return TryGetTerrainHeight(p, out z);
    }

    /// <summary>The terrain height, in metres, at global coordinates (see <see cref="TryGetTerrainHeight(double, double, out float)"/>).</summary>
    /// <exception cref="ArgumentException">A coordinate is NaN or infinite, outside the world, or over an unloaded landblock.</exception>
    public float GetTerrainHeight(double globalX, double globalY)
    {
        if (!TryGetTerrainHeight(globalX, globalY, out float z))
        {
            throw new ArgumentException(
                string.Create(System.Globalization.CultureInfo.InvariantCulture, $"No loaded terrain at ({globalX}, {globalY})."),
                nameof(globalX));
        }

        return z;
    }

    /// <summary>
    /// The water depth, in metres, at <paramref name="p"/>'s origin (0, 0.1, 0.45 or 0.9; see
    /// <see cref="LandCell.GetWaterDepth"/>). Returns false past the world edge or over an unloaded landblock.
    /// </summary>
    /// <exception cref="ArgumentException">The origin has a NaN or infinite component.</exception>
    // retail: CObjCell::get_water_depth (acclient.c:347232)
    public bool TryGetWaterDepth(in Position p, out float depth)
    {
        if (TryFindTerrainPoly(p, out LandCell? cell, out _, out Vector3 local))
        {
            depth = cell.GetWaterDepth(local);
            return true;
        }

        depth = 0f;
        return false;
    }
}
