using System;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Math;

namespace AcDream.Core.Physics.Cells;

/// <summary>
/// Builds the list of cells a sphere path overlaps. Retail: <c>CObjCell::find_cell_list</c> (acclient.c:346960 and its
/// overloads 347315, 347321).
/// </summary>
internal static class CellList
{
    /// <summary>
    /// Fills <paramref name="cellArray"/> with the cells the path's check spheres overlap and, when
    /// <paramref name="findCell"/>, returns the cell that contains the first sphere's centre (for outdoor cells the last
    /// one in list order, as retail; an interior cell wins at once).
    /// </summary>
    // retail: CObjCell::find_cell_list (acclient.c:347315) -> (acclient.c:346960)
    public static ObjCell? FindCellList(ICellSource cells, CellArray cellArray, SpherePath path, bool findCell) =>
        FindCellList(cells, path.CheckPos, path.GlobalSphere.AsSpan(0, path.NumSphere), cellArray, findCell, path);

    /// <summary>
    /// Fills <paramref name="cellArray"/> with the cells that spheres centred in <paramref name="p"/>'s landblock
    /// overlap; see <see cref="FindCellList(ICellSource, CellArray, SpherePath, bool)"/>.
    /// </summary>
    // retail: CObjCell::find_cell_list (acclient.c:346960)
    public static ObjCell? FindCellList(ICellSource cells, in Position p, ReadOnlySpan<Sphere> spheres, CellArray cellArray,
        bool findCell, SpherePath? path)
    {
        cellArray.NumCells = 0;
        cellArray.AddedOutside = false;
        uint id = p.ObjCellId;
        ObjCell? own = id != 0 ? cells.GetVisible(id) : null;
        if (LandDefs.IsEnvCell(id))
        {
            if (path is not null)
            {
                path.HitsInteriorCell = true;
            }

            cellArray.AddCell(id, own);
        }
        else
        {
            AddAllOutsideCells(cells, p, spheres, cellArray);
        }

        if (own is null || spheres.Length == 0)
        {
            return null;
        }

        for (int i = 0; i < cellArray.NumCells; i++)
        {
            cellArray.CellAt(i)?.FindTransitCells(cells, p, spheres, cellArray, path);
        }

        if (!findCell)
        {
            return null;
        }

        ObjCell? curr = null;
        Vector3 c0 = spheres[0].Center;
        for (int i = 0; i < cellArray.NumCells; i++)
        {
            ObjCell? cell = cellArray.CellAt(i);
            if (cell is null)
            {
                continue;
            }

            Vector3 off = LandDefs.GetBlockOffset(p.ObjCellId, cell.Id);
            var local = new Vector3((float)((double)c0.X - off.X), (float)((double)c0.Y - off.Y), (float)((double)c0.Z - off.Z));
            if (cell.PointInCell(local))
            {
                curr = cell;
                if (LandDefs.IsEnvCell(cell.Id))
                {
                    if (path is not null)
                    {
                        path.HitsInteriorCell = true;
                    }

                    break;
                }
            }
        }

        // Retail's do_not_load_cells pruning applies to interior positions only.
        return curr;
    }

    /// <summary>
    /// Adds, once per list, every outdoor cell the spheres touch: each centre's cell and the neighbours within its radius
    /// of an edge (stopping at the first centre past the world edge); with no spheres, the cell under the origin.
    /// </summary>
    // retail: CLandCell::add_all_outside_cells (acclient.c:355345)
    public static void AddAllOutsideCells(ICellSource cells, in Position p, ReadOnlySpan<Sphere> spheres, CellArray cellArray)
    {
        if (cellArray.AddedOutside)
        {
            return;
        }

        cellArray.AddedOutside = true;
        if (spheres.Length > SpherePath.MaxSpheres)
        {
            // More spheres than a sweep carries (an object's cylinder spheres, up to 10): retail's loop runs over all of
            // them, one sphere at a time, stopping at the first centre past the world edge. Same cells and order as the
            // batch below (each sphere appends its cells; the array keeps the first of a duplicate).
            Span<uint> one = stackalloc uint[LandCell.MaxCellsPerSphere];
            for (int s = 0; s < spheres.Length; s++)
            {
                int k = 0;
                if (!LandCell.AddOutsideCellsForSphere(p.ObjCellId, spheres[s].Center, spheres[s].Radius, one, ref k))
                {
                    return;
                }

                for (int i = 0; i < k; i++)
                {
                    cellArray.AddCell(one[i], cells.GetVisible(one[i]));
                }
            }

            return;
        }

        int n = spheres.Length;
        Span<Vector3> centers = stackalloc Vector3[SpherePath.MaxSpheres];
        Span<float> radii = stackalloc float[SpherePath.MaxSpheres];
        for (int i = 0; i < n; i++)
        {
            centers[i] = spheres[i].Center;
            radii[i] = spheres[i].Radius;
        }

        Span<uint> ids = stackalloc uint[LandCell.MaxCellsPerSphere * SpherePath.MaxSpheres];
        int count = LandCell.AddAllOutsideCells(p, centers[..n], radii[..n], ids, 0);
        for (int i = 0; i < count; i++)
        {
            cellArray.AddCell(ids[i], cells.GetVisible(ids[i]));
        }
    }
}
