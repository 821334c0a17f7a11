using System;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Cells;

// Which cells a static object's parts reach from an indoor cell, through its portals (the part-based cell list of
// calc_cross_cells_static), and through a building's door into an indoor cell.
public sealed partial class EnvCell
{
    /// <summary>
    /// Adds the cells the parts reach through this cell's portals. For each portal, the first part whose sphere is not
    /// wholly on this cell's side of the portal's plane and whose bounding box is not either: an outdoor portal makes the
    /// outdoor cells the parts cover join once every portal is done; an unloaded neighbour is listed without a cell; a
    /// loaded neighbour is listed when that part's box meets its region (else the next part is tried).
    /// </summary>
    // retail: CEnvCell::find_transit_cells(parts) (acclient.c:348406)
    internal void FindTransitCellsForParts(ICellSource cells, ReadOnlySpan<PlacedPartBox> parts, CellArray cellArray)
    {
        bool checkOutside = false;
        for (int i = 0; i < _portals.Length; i++)
        {
            ref readonly CellPortal portal = ref _portals[i];
            for (int j = 0; j < parts.Length; j++)
            {
                ref readonly PlacedPartBox part = ref parts[j];
                if (part.PartSphere is not { } sphere)
                {
                    continue;
                }

                Vector3 center = _pos.LocalToLocal(part.Pos, sphere.Center);
                float radius = (float)(sphere.Radius + (double)PhysicsGlobals.Epsilon);
                float negRadius = -radius;
                int side = portal.PortalSide;
                CollisionPlane plane = portal.Portal.Plane;
                double d = (double)center.Y * plane.N.Y + (double)center.Z * plane.N.Z + (double)center.X * plane.N.X + plane.D;
                if (side != 0)
                {
                    if (side == 1 && d < negRadius)
                    {
                        continue;
                    }
                }
                else if (d > radius)
                {
                    continue;
                }

                part.BoxIn(_pos, out Vector3 min, out Vector3 max);
                if ((int)plane.IntersectBox(min, max) == side)
                {
                    continue;
                }

                if (portal.IsOutside)
                {
                    checkOutside = true;
                    break;
                }

                if (cells.GetVisible(portal.OtherCellId) is EnvCell other)
                {
                    part.BoxIn(other._pos, out Vector3 cellMin, out Vector3 cellMax);
                    if (other.Structure.BoxIntersectsCell(cellMin, cellMax))
                    {
                        cellArray.AddCell(other.CellId, other);
                        break;
                    }

                    continue;
                }

                cellArray.AddCell(portal.OtherCellId, null);
                break;
            }
        }

        if (checkOutside)
        {
            LandCell.AddAllOutsideCellsForParts(cells, parts, cellArray);
        }
    }

    /// <summary>
    /// A building's door (this cell's portal <paramref name="portalId"/>) reaches this cell: at the first part whose sphere
    /// is not wholly on the door's outside, whose bounding box crosses the door's plane or lies on this cell's side, and whose
    /// box meets the cell's region, the cell joins the list and lists the cells the parts reach from it.
    /// </summary>
    // retail: CEnvCell::check_building_transit(parts) (acclient.c:348153)
    internal void CheckBuildingTransitForParts(ICellSource cells, int portalId, ReadOnlySpan<PlacedPartBox> parts, CellArray cellArray)
    {
        if (portalId < 0)
        {
            return;
        }

        if (portalId >= _portals.Length)
        {
            // non-retail: a door naming a portal the cell does not have is inert (retail reads past the portal array)
            return;
        }

        ref readonly CellPortal portal = ref _portals[portalId];
        for (int j = 0; j < parts.Length; j++)
        {
            ref readonly PlacedPartBox part = ref parts[j];
            if (part.PartSphere is not { } sphere)
            {
                continue;
            }

            Vector3 center = _pos.LocalToLocal(part.Pos, sphere.Center);
            float radius = (float)(sphere.Radius + (double)PhysicsGlobals.Epsilon);
            float negRadius = -radius;
            int side = portal.PortalSide;
            CollisionPlane plane = portal.Portal.Plane;
            double d = (double)center.Y * plane.N.Y + (double)center.Z * plane.N.Z + (double)center.X * plane.N.X + plane.D;
            if (side == 1)
            {
                if (d > radius)
                {
                    continue;
                }
            }
            else if (side == 0 && d < negRadius)
            {
                continue;
            }

            part.BoxIn(_pos, out Vector3 min, out Vector3 max);
            Sidedness s = plane.IntersectBox(min, max);
            if ((s == Sidedness.Crossing || (int)s == side) && Structure.BoxIntersectsCell(min, max))
            {
                cellArray.AddCell(CellId, this);
                FindTransitCellsForParts(cells, parts, cellArray);
                return;
            }
        }
    }
}
