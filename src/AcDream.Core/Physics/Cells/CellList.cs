using System;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

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
            AddAllOutsideCellsOneByOne(cells, p, spheres, cellArray);
            return;
        }

        if (!cellArray.ReferencePaths && TryInteriorCells(p.ObjCellId, spheres, out uint id0, out uint id1))
        {
            cellArray.AddCell(id0, cells.GetVisible(id0));
            if (id1 != 0)
            {
                cellArray.AddCell(id1, cells.GetVisible(id1));
            }

            return;
        }

        AddAllOutsideCellsGeneral(cells, p, spheres, cellArray);
    }

    // More spheres than a sweep carries (an object's cylinder spheres, up to 10): retail's loop runs over all of them, one
    // sphere at a time, stopping at the first centre past the world edge. Same cells and order as the batch of the general
    // path (each sphere appends its cells; the array keeps the first of a duplicate).
    // retail: CLandCell::add_all_outside_cells (acclient.c:355345)
    private static void AddAllOutsideCellsOneByOne(ICellSource cells, in Position p, ReadOnlySpan<Sphere> spheres, CellArray cellArray)
    {
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
    }

    // The general path of AddAllOutsideCells for up to SpherePath.MaxSpheres spheres (kept apart so that the shortcut does
    // not pay for its stack buffers).
    // retail: CLandCell::add_all_outside_cells (acclient.c:355345)
    private static void AddAllOutsideCellsGeneral(ICellSource cells, in Position p, ReadOnlySpan<Sphere> spheres, CellArray cellArray)
    {
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

    /// <summary>
    /// The common case of <see cref="AddAllOutsideCells"/> computed directly: every sphere centre lies inside
    /// <paramref name="cellId"/>'s landblock (x and y in [EPSILON, 192)) and at least its radius from each edge of the
    /// outdoor cell that holds it, so that each sphere adds its own cell and no neighbour. Gives the ids
    /// <see cref="LandCell.AddAllOutsideCells"/> would give, in its order (<paramref name="id1"/> = 0 when one cell), with
    /// the same arithmetic: within the landblock <c>adjust_to_outside</c> leaves the centre as it is (no snap, no wrap), so
    /// the cell is the landblock's cell at floor(x / 24), floor(y / 24) and the edge tests compare the same floats. False
    /// (nothing computed) for anything else: an indoor or invalid id, no sphere, a centre outside the landblock or near a
    /// cell edge, a NaN or a bad radius (the general path then handles or refuses it).
    /// </summary>
    // non-retail: a shortcut of CLandCell::add_all_outside_cells (acclient.c:355345) for spheres inside one landblock's
    // cells; the same cells in the same order (shown against the general path by ReferencePathsEquivalenceTests)
    internal static bool TryInteriorCells(uint cellId, ReadOnlySpan<Sphere> spheres, out uint id0, out uint id1)
    {
        id0 = 0;
        id1 = 0;
        uint c = cellId & 0xFFFF;
        if (spheres.Length == 0 || c < 1 || c > 0x40 || !LandDefs.BlockIdToLCoord(cellId, out int bx, out int by))
        {
            return false;
        }

        for (int i = 0; i < spheres.Length; i++)
        {
            Vector3 center = spheres[i].Center;
            float radius = spheres[i].Radius;
            if (!(center.X >= PhysicsGlobals.Epsilon && center.X < LandDefs.BlockLength
                  && center.Y >= PhysicsGlobals.Epsilon && center.Y < LandDefs.BlockLength)
                || !float.IsFinite(center.Z) || !(radius >= 0f) || float.IsInfinity(radius))
            {
                return false;
            }

            int xc = CellIndex(center.X);
            int yc = CellIndex(center.Y);
            float ptX = (float)(center.X - xc * 24.0);
            float ptY = (float)(center.Y - yc * 24.0);
            float maxRad = (float)(24.0 - radius);
            if (ptX > maxRad || ptX < radius || ptY > maxRad || ptY < radius)
            {
                return false;
            }

            uint id = LandDefs.LCoordToGid(bx + xc, by + yc);
            if (id == 0)
            {
                return false;
            }

            if (id0 == 0)
            {
                id0 = id;
            }
            else if (id != id0)
            {
                id1 = id;
            }
        }

        return true;
    }

    // floor(v / 24.0) for a float v in [0, 192) without the division: the k with 24k <= v < 24(k + 1). The same value,
    // since for a float v the double quotient v / 24.0 rounds to k or above exactly when v >= 24k (24k is exact, and a float
    // below it falls short of it by far more than the quotient's rounding).
    private static int CellIndex(float v)
    {
        int k = (int)(v * (1f / 24f));
        if (k * 24f > v)
        {
            k--;
        }
        else if ((k + 1) * 24f <= v)
        {
            k++;
        }

        return k;
    }
}
