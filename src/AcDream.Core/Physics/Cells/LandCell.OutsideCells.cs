using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Cells;

// Gathering the outdoor cells a set of spheres touches (the outdoor half of retail's cell list), into a caller-owned
// buffer of cell ids with retail's CELLARRAY::add_cell semantics: an id is appended only when absent, so the order is
// insertion order.
public sealed partial class LandCell
{
    /// <summary>
    /// The most cells one sphere can add: its own cell and its eight neighbours (a radius above 12 m can reach both sides).
    /// Size a buffer as <c>count + MaxCellsPerSphere * sphereCount</c>.
    /// </summary>
    internal const int MaxCellsPerSphere = 9;

    /// <summary>
    /// Appends the outdoor cell at global cell coordinates (<paramref name="x"/>, <paramref name="y"/>) to
    /// <c>cellIds[0..count)</c> unless it is already there; cells past the world edge (outside 0..2039) are skipped.
    /// </summary>
    /// <exception cref="ArgumentException">The cell is new and the buffer is full (nothing is written).</exception>
    // retail: CLandCell::add_outside_cell (acclient.c:354974) with CELLARRAY::add_cell (acclient.c:718895)
    internal static void AddOutsideCell(int x, int y, Span<uint> cellIds, ref int count)
    {
        if (!LandDefs.InBounds(x, y))
        {
            return;
        }

        AddCellId(LandDefs.LCoordToGid(x, y), cellIds, ref count);
    }

    /// <summary>
    /// Appends <paramref name="cellId"/> to <c>cellIds[0..count)</c> unless it is already there.
    /// </summary>
    /// <exception cref="ArgumentException">The id is new and the buffer is full (nothing is written).</exception>
    // retail: CELLARRAY::add_cell (acclient.c:718895)
    internal static void AddCellId(uint cellId, Span<uint> cellIds, ref int count)
    {
        for (int i = 0; i < count; i++)
        {
            if (cellIds[i] == cellId)
            {
                return;
            }
        }

        if (count >= cellIds.Length)
        {
            throw new ArgumentException("The cell id buffer is full.", nameof(cellIds));
        }

        cellIds[count++] = cellId;
    }

    /// <summary>
    /// Adds the neighbours of global cell (<paramref name="x"/>, <paramref name="y"/>) that a sphere reaches, given its
    /// centre's offset <paramref name="ptX"/>, <paramref name="ptY"/> inside the cell (0..24): a neighbour across an edge
    /// when the offset is beyond <paramref name="incellMax"/> (24 - r) or below <paramref name="incellMin"/> (r), and the
    /// diagonal neighbour when both axes are.
    /// </summary>
    // retail: CLandCell::check_add_cell_boundary (acclient.c:355161)
    internal static void CheckAddCellBoundary(float ptX, float ptY, int x, int y, float incellMax, float incellMin, Span<uint> cellIds, ref int count)
    {
        if (ptX > incellMax)
        {
            AddOutsideCell(x + 1, y, cellIds, ref count);
            if (ptY > incellMax)
            {
                AddOutsideCell(x + 1, y + 1, cellIds, ref count);
            }

            if (ptY < incellMin)
            {
                AddOutsideCell(x + 1, y - 1, cellIds, ref count);
            }
        }

        if (ptX < incellMin)
        {
            AddOutsideCell(x - 1, y, cellIds, ref count);
            if (ptY > incellMax)
            {
                AddOutsideCell(x - 1, y + 1, cellIds, ref count);
            }

            if (ptY < incellMin)
            {
                AddOutsideCell(x - 1, y - 1, cellIds, ref count);
            }
        }

        if (ptY > incellMax)
        {
            AddOutsideCell(x, y + 1, cellIds, ref count);
        }

        if (ptY < incellMin)
        {
            AddOutsideCell(x, y - 1, cellIds, ref count);
        }
    }

    /// <summary>
    /// One sphere's step of <see cref="AddAllOutsideCells"/>: re-homes the centre (local to <paramref name="cellId"/>'s
    /// landblock) into the outdoor cell that contains it and adds that cell and the neighbours within
    /// <paramref name="radius"/> of its edges. Returns false, adding nothing, when the centre lies past the world edge
    /// or <paramref name="cellId"/> is not a cell id (retail then stops processing further spheres).
    /// </summary>
    /// <exception cref="ArgumentException">A NaN or infinite centre, a negative or non-finite radius, or fewer than
    /// <see cref="MaxCellsPerSphere"/> free slots in the buffer (nothing is written).</exception>
    // retail: CLandCell::add_all_outside_cells (acclient.c:355345), the body of its sphere loop
    internal static bool AddOutsideCellsForSphere(uint cellId, Vector3 center, float radius, Span<uint> cellIds, ref int count)
    {
        ValidateSphere(center, radius);
        if (cellIds.Length - count < MaxCellsPerSphere)
        {
            throw new ArgumentException($"The cell id buffer needs {MaxCellsPerSphere} free slots per sphere.", nameof(cellIds));
        }

        return AddForSphere(cellId, center, radius, cellIds, ref count);
    }

    /// <summary>
    /// Adds to <c>cellIds[0..count)</c> every outdoor cell the spheres touch: for each sphere (centres local to
    /// <paramref name="p"/>'s landblock), the cell containing its centre and the neighbours within its radius of an edge.
    /// Stops at the first sphere whose centre lies past the world edge, as retail does. With no spheres, adds the cell
    /// that contains <paramref name="p"/>'s origin. Returns the new count.
    /// </summary>
    /// <exception cref="ArgumentException">Mismatched span lengths, a NaN or infinite centre, a negative or non-finite
    /// radius, or a buffer with fewer than <see cref="MaxCellsPerSphere"/> free slots per sphere (nothing is written).</exception>
    // retail: CLandCell::add_all_outside_cells (acclient.c:355345)
    internal static int AddAllOutsideCells(in Position p, ReadOnlySpan<Vector3> centers, ReadOnlySpan<float> radii, Span<uint> cellIds, int count)
    {
        if (centers.Length != radii.Length)
        {
            throw new ArgumentException("One radius per sphere centre is required.", nameof(radii));
        }

        if ((uint)count > (uint)cellIds.Length)
        {
            throw new ArgumentException("The count exceeds the buffer.", nameof(count));
        }

        for (int i = 0; i < centers.Length; i++)
        {
            ValidateSphere(centers[i], radii[i]);
        }

        if (cellIds.Length - count < MaxCellsPerSphere * Math.Max(1, centers.Length))
        {
            throw new ArgumentException($"The cell id buffer needs {MaxCellsPerSphere} free slots per sphere.", nameof(cellIds));
        }

        if (centers.Length == 0)
        {
            uint id = p.ObjCellId;
            Vector3 o = p.Frame.Origin;
            if (LandDefs.AdjustToOutside(ref id, ref o) && LandDefs.GidToLCoord(id, out int x, out int y))
            {
                AddOutsideCell(x, y, cellIds, ref count);
            }

            return count;
        }

        for (int i = 0; i < centers.Length; i++)
        {
            if (!AddForSphere(p.ObjCellId, centers[i], radii[i], cellIds, ref count))
            {
                break;
            }
        }

        return count;
    }

    private static bool AddForSphere(uint cellId, Vector3 center, float radius, Span<uint> cellIds, ref int count)
    {
        uint ptCell = cellId;
        Vector3 point = center;
        if (!LandDefs.AdjustToOutside(ref ptCell, ref point))
        {
            return false;
        }

        int xc = unchecked((int)(long)Math.Floor(point.X / 24.0));
        int yc = unchecked((int)(long)Math.Floor(point.Y / 24.0));
        float ptX = (float)(point.X - xc * 24.0);
        float ptY = (float)(point.Y - yc * 24.0);
        float minRad = radius;
        float maxRad = (float)(24.0 - minRad);
        if (LandDefs.GidToLCoord(ptCell, out int x, out int y))
        {
            AddOutsideCell(x, y, cellIds, ref count);
            CheckAddCellBoundary(ptX, ptY, x, y, maxRad, minRad, cellIds, ref count);
        }

        return true;
    }

    private static void ValidateSphere(Vector3 center, float radius)
    {
        if (!VectorMath.IsFinite(center))
        {
            throw new ArgumentException("Sphere centres must be finite.", nameof(center));
        }

        if (!(radius >= 0f) || float.IsInfinity(radius))
        {
            throw new ArgumentException("Sphere radii must be finite and non-negative.", nameof(radius));
        }
    }
}
