using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Terrain;

// The cell list of a set of spheres over the outdoor world.
public sealed partial class TerrainWorld
{
    /// <summary>
    /// Fills <paramref name="cellIds"/> with the cells that spheres centred at <paramref name="centers"/> (local to
    /// <paramref name="p"/>'s landblock) touch, and finds the current cell: the land cell whose triangles lie under the
    /// first centre — the last such cell in list order, as retail. Returns the number of ids written.
    /// </summary>
    /// <remarks>
    /// Outdoor half of retail's <c>find_cell_list</c>: an indoor <paramref name="p"/> contributes just its own id (and no
    /// current land cell); buildings' portal cells (<c>find_transit_cells</c>) are not added here: the sweep's own cell list adds them.
    /// Ids of cells whose landblock is not loaded are listed too (retail lists them with a null cell).
    /// </remarks>
    /// <exception cref="ArgumentException">See <see cref="LandCell.AddAllOutsideCells"/>.</exception>
    // retail: CObjCell::find_cell_list (acclient.c:346960)
    public int FindCellList(in Position p, ReadOnlySpan<Vector3> centers, ReadOnlySpan<float> radii, Span<uint> cellIds, out LandCell? currentCell)
    {
        currentCell = null;
        if (LandDefs.IsEnvCell(p.ObjCellId))
        {
            if (cellIds.Length < 1)
            {
                throw new ArgumentException("The cell id buffer is empty.", nameof(cellIds));
            }

            cellIds[0] = p.ObjCellId;
            return 1;
        }

        int count = LandCell.AddAllOutsideCells(p, centers, radii, cellIds, 0);
        if (centers.Length == 0 || GetLandCell(p.ObjCellId) is null)
        {
            return count;
        }

        Vector3 c0 = centers[0];
        for (int i = 0; i < count; i++)
        {
            LandCell? cell = GetLandCell(cellIds[i]);
            if (cell is null)
            {
                continue;
            }

            Vector3 off = LandDefs.GetBlockOffset(p.ObjCellId, cell.Id);
            var local = new Vector3(c0.X - off.X, c0.Y - off.Y, c0.Z - off.Z);
            if (cell.PointInCell(local))
            {
                currentCell = cell;
            }
        }

        return count;
    }
}
