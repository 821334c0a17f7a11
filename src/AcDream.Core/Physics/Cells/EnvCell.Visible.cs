using System;
using System.Numerics;

namespace AcDream.Core.Physics.Cells;

// Finding the indoor cell that contains a point, from a starting cell.
public sealed partial class EnvCell
{
    /// <summary>
    /// This cell when it contains the landblock-local <paramref name="origin"/>, else the first loaded portal neighbour
    /// that does, else null. This is retail's portal mode (<c>bSearchCells == 0</c>); its other mode, used by
    /// <c>CPhysicsObj::AdjustPosition</c>, searches the cell's stab list of visible cells, which this port does not hold —
    /// the portal mode stands in for it.
    /// </summary>
    // retail: CEnvCell::find_visible_child_cell (acclient.c:349697), bSearchCells == 0
    internal EnvCell? FindVisibleChildCell(ICellSource cells, Vector3 origin)
    {
        ArgumentNullException.ThrowIfNull(cells);
        if (PointInCell(origin))
        {
            return this;
        }

        for (int i = 0; i < _portals.Length; i++)
        {
            if (cells.GetVisible(_portals[i].OtherCellId) is EnvCell other && other.PointInCell(origin))
            {
                return other;
            }
        }

        return null;
    }
}
