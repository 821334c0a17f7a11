namespace AcDream.Core.Physics.Cells;

/// <summary>
/// A building's door into its interior: the indoor cell behind it. Retail: <c>CBldPortal</c> (acclient.h:32094,
/// PORTAL/cgeometry/CBldPortal.c).
/// </summary>
/// <param name="OtherCellId">The full id of the indoor cell the portal leads into. Retail: <c>other_cell_id</c>.</param>
/// <param name="OtherPortalId">The portal's index in that cell (a negative id makes the portal inert, as retail's
/// <c>check_building_transit</c> tests). Retail: <c>other_portal_id</c>.</param>
/// <param name="PortalSide">Retail: <c>portal_side</c>.</param>
/// <param name="ExactMatch">Retail: <c>exact_match</c>.</param>
public readonly record struct BldPortal(uint OtherCellId, int OtherPortalId, int PortalSide = 0, bool ExactMatch = true);
