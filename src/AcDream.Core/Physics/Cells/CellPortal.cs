using System;
using AcDream.Core.Physics.Collision.Primitives;

namespace AcDream.Core.Physics.Cells;

/// <summary>
/// A portal of an indoor cell: the opening polygon (in the cell's local space) and the cell behind it.
/// Retail: <c>CCellPortal</c> (acclient.h:32300, PORTAL/cgeometry/CCellPortal.c).
/// </summary>
public readonly struct CellPortal
{
    /// <summary>The id retail stores for a portal that opens to the outdoors (flag 4 of the packed portal: -1).
    /// Retail: <c>CCellPortal::UnPack</c> (acclient.c:362346).</summary>
    public const uint OutsideCellId = 0xFFFFFFFF;

    /// <summary>Creates a portal.</summary>
    /// <param name="otherCellId">The full id of the cell behind the portal, or <see cref="OutsideCellId"/>.</param>
    /// <param name="portal">The opening polygon, cell-local.</param>
    /// <param name="portalSide">Which side of the polygon's plane the other cell is on (retail 0 = positive side counts, 1 = negative).</param>
    /// <param name="otherPortalId">The matching portal's index in the other cell (-1 when none).</param>
    /// <param name="exactMatch">Retail <c>exact_match</c>.</param>
    /// <exception cref="ArgumentNullException"><paramref name="portal"/> is null.</exception>
    public CellPortal(uint otherCellId, Polygon portal, int portalSide, int otherPortalId = -1, bool exactMatch = true)
    {
        ArgumentNullException.ThrowIfNull(portal);
        OtherCellId = otherCellId;
        Portal = portal;
        PortalSide = portalSide;
        OtherPortalId = otherPortalId;
        ExactMatch = exactMatch;
    }

    /// <summary>The cell behind the portal. Retail: <c>other_cell_id</c>.</summary>
    public uint OtherCellId { get; }

    /// <summary>The opening polygon, cell-local. Retail: <c>portal</c>.</summary>
    public Polygon Portal { get; }

    /// <summary>Retail: <c>portal_side</c> (1 means the other cell lies on the polygon's positive side, 0 the negative side,
    /// as <c>CEnvCell::find_transit_cells</c> tests it).</summary>
    public int PortalSide { get; }

    /// <summary>Retail: <c>other_portal_id</c>.</summary>
    public int OtherPortalId { get; }

    /// <summary>Retail: <c>exact_match</c>.</summary>
    public bool ExactMatch { get; }

    /// <summary>True for a portal to the outdoors.</summary>
    public bool IsOutside => OtherCellId == OutsideCellId;
}
