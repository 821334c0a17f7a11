using System;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Cells;

// The outdoor cells a static object's parts cover (the part-based cell list of calc_cross_cells_static).
public sealed partial class LandCell
{
    /// <summary>The cells the parts reach from this cell: the outdoor cells their boxes cover, then the indoor cells behind
    /// this cell's building's doors that their boxes reach.</summary>
    // retail: CLandCell::find_transit_cells(parts) (acclient.c:355432)
    internal void FindTransitCellsForParts(ICellSource cells, ReadOnlySpan<PlacedPartBox> parts, CellArray cellArray)
    {
        AddAllOutsideCellsForParts(cells, parts, cellArray);
        // retail: CSortCell::find_transit_cells(parts) (acclient.c:356096)
        Building?.FindBuildingTransitCellsForParts(cells, parts, cellArray);
    }

    /// <summary>
    /// Once per cell list: the rectangle of outdoor cells, counted from the cell under the first part's origin, that covers
    /// every part's bounding box (taken into that cell's landblock through its 8 corners), or, for a 2-D part, the square
    /// of its sphere's radius around its origin; the rectangle always holds that cell.
    /// </summary>
    // retail: CLandCell::add_all_outside_cells(parts) (acclient.c:355191)
    internal static void AddAllOutsideCellsForParts(ICellSource cells, ReadOnlySpan<PlacedPartBox> parts, CellArray cellArray)
    {
        if (cellArray.AddedOutside)
        {
            return;
        }

        cellArray.AddedOutside = true;
        if (parts.Length == 0)
        {
            return;
        }

        int minX = 0, minY = 0, maxX = 0, maxY = 0;
        uint cellId = parts[0].Pos.ObjCellId;
        Vector3 loc = parts[0].Pos.Frame.Origin;
        cellId = LandDefs.AdjustToOutside(ref cellId, ref loc) ? cellId : 0;
        if (cells.GetVisible(cellId) is not LandCell cell || !LandDefs.GidToLCoord(cellId, out int x, out int y))
        {
            return;
        }

        int lx = (int)(((cellId & 0xFFFF) - 1) >> 3);
        int ly = (int)((cellId - 1) & 7);
        var cellPos = new Position(cellId, new Frame(cell.Origin, Quaternion.Identity));
        for (int i = 0; i < parts.Length; i++)
        {
            PlacedPartBox part = parts[i];
            int x0, y0, x1, y1;
            if (part.Always2D)
            {
                float r = part.Radius;
                Vector3 o = part.Pos.Frame.Origin;
                x0 = Floor24(o.X - r);
                y0 = Floor24(o.Y - r);
                x1 = Floor24(o.X + r);
                y1 = Floor24(o.Y + r);
            }
            else
            {
                BoxToCell(cellPos, part, out Vector3 min, out Vector3 max);
                x0 = Floor24(min.X);
                y0 = Floor24(min.Y);
                x1 = Floor24(max.X);
                y1 = Floor24(max.Y);
            }

            minX = Math.Min(minX, x0 - lx);
            minY = Math.Min(minY, y0 - ly);
            maxX = Math.Max(maxX, x1 - lx);
            maxY = Math.Max(maxY, y1 - ly);
        }

        AddCellBlock(cells, minX + x, minY + y, x + maxX, y + maxY, cellArray);
    }

    // (int)floor(v / 24), as retail's _floor and truncation.
    private static int Floor24(double v) => unchecked((int)(long)Math.Floor(v / 24.0));

    // The part's box in the cell's landblock: each of its 8 corners through the part's frame, then their bounds.
    // retail: BBox::LocalToGlobal (acclient.c:476912)
    private static void BoxToCell(in Position cellPos, in PlacedPartBox part, out Vector3 min, out Vector3 max)
    {
        Vector3 a = part.Min, b = part.Max;
        min = cellPos.LocalToGlobal(part.Pos, a);
        max = min;
        Span<Vector3> corners = stackalloc Vector3[7]
        {
            b,
            new(b.X, b.Y, a.Z), new(b.X, a.Y, b.Z), new(a.X, b.Y, b.Z),
            new(a.X, b.Y, a.Z), new(b.X, a.Y, a.Z), new(a.X, a.Y, b.Z),
        };
        foreach (Vector3 c in corners)
        {
            Vector3 g = cellPos.LocalToGlobal(part.Pos, c);
            min = Vector3.Min(min, g);
            max = Vector3.Max(max, g);
        }
    }

    /// <summary>Every outdoor cell (global cell coordinates) of the rectangle that lies inside the world, loaded or not.</summary>
    // retail: CLandCell::add_cell_block (acclient.c:355139)
    internal static void AddCellBlock(ICellSource cells, int minX, int minY, int maxX, int maxY, CellArray cellArray)
    {
        for (int i = minX; i <= maxX; i++)
        {
            for (int j = minY; j <= maxY; j++)
            {
                if (i >= 0 && j >= 0 && i < LandDefs.LCoordLimit && j < LandDefs.LCoordLimit)
                {
                    uint id = LandDefs.LCoordToGid(i, j);
                    cellArray.AddCell(id, cells.GetVisible(id));
                }
            }
        }
    }
}
