using System;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Cells;

// Which cells a sphere reaches from an indoor cell, through its portals.
public sealed partial class EnvCell
{
    /// <summary>
    /// Adds the cells the spheres reach through this cell's portals: a loaded neighbour whose region a sphere meets; an
    /// unloaded neighbour (listed without a cell) when a sphere is on its side of the portal; and, when a sphere is
    /// within its radius of an outdoor portal's plane, the outdoor cells around the spheres.
    /// </summary>
    /// <remarks>The sphere centres are in <paramref name="p"/>'s landblock, which retail assumes is the cell's own (no
    /// block offset is applied, as in retail).</remarks>
    // retail: CEnvCell::find_transit_cells (acclient.c:348249)
    internal override void FindTransitCells(ICellSource cells, in Position p, ReadOnlySpan<Sphere> spheres, CellArray cellArray, SpherePath? path)
    {
        ArgumentNullException.ThrowIfNull(cells);
        ArgumentNullException.ThrowIfNull(cellArray);
        bool checkOutside = false;
        ref readonly Frame f = ref _pos.Frame;
        for (int i = 0; i < _portals.Length; i++)
        {
            ref readonly CellPortal portal = ref _portals[i];
            if (portal.IsOutside)
            {
                CollisionPlane pl = portal.Portal.Plane;
                for (int s = 0; s < spheres.Length; s++)
                {
                    Vector3 c = spheres[s].Center;
                    double dx = (double)c.X - f.Origin.X;
                    double dy = (double)c.Y - f.Origin.Y;
                    double dz = (double)c.Z - f.Origin.Z;
                    float lx = (float)(dx * f.M11 + dz * f.M13 + dy * f.M12);
                    float ly = (float)(dx * f.M21 + dz * f.M23 + dy * f.M22);
                    float ia = (float)(spheres[s].Radius + (double)PhysicsGlobals.Epsilon);
                    double d = (dz * f.M33 + dy * f.M32 + dx * f.M31) * pl.N.Z + (double)ly * pl.N.Y + (double)lx * pl.N.X + pl.D;
                    if (d > -ia && d < ia)
                    {
                        checkOutside = true;
                        break;
                    }
                }

                continue;
            }

            if (cells.GetVisible(portal.OtherCellId) is EnvCell other)
            {
                for (int s = 0; s < spheres.Length; s++)
                {
                    var local = new Sphere(other._pos.Frame.GlobalToLocal(spheres[s].Center), spheres[s].Radius);
                    if (other.Structure.SphereIntersectsCell(local) != CellBspSphere.Outside)
                    {
                        cellArray.AddCell(other.CellId, other);
                        break;
                    }
                }

                continue;
            }

            CollisionPlane pp = portal.Portal.Plane;
            for (int s = 0; s < spheres.Length; s++)
            {
                Vector3 lc = f.GlobalToLocal(spheres[s].Center);
                double rr = spheres[s].Radius + (double)PhysicsGlobals.Epsilon;
                double d = (double)lc.Y * pp.N.Y + (double)lc.Z * pp.N.Z + (double)lc.X * pp.N.X + pp.D;
                if ((d > -rr && portal.PortalSide == 1) || (d < rr && portal.PortalSide == 0))
                {
                    cellArray.AddCell(portal.OtherCellId, null);
                    break;
                }
            }
        }

        if (checkOutside)
        {
            CellList.AddAllOutsideCells(cells, p, spheres, cellArray);
        }
    }

    /// <summary>
    /// A building's door reaches this cell: when a sphere meets the cell's region, the path learns it touches an
    /// interior cell and the cell joins the list.
    /// </summary>
    // retail: CEnvCell::check_building_transit (acclient.c:348109)
    internal void CheckBuildingTransit(int portalId, ReadOnlySpan<Sphere> spheres, CellArray cellArray, SpherePath? path)
    {
        ArgumentNullException.ThrowIfNull(cellArray);
        if (portalId < 0)
        {
            return;
        }

        for (int s = 0; s < spheres.Length; s++)
        {
            var local = new Sphere(_pos.Frame.GlobalToLocal(spheres[s].Center), spheres[s].Radius);
            if (Structure.SphereIntersectsCell(local) != CellBspSphere.Outside)
            {
                if (path is not null)
                {
                    path.HitsInteriorCell = true;
                }

                cellArray.AddCell(CellId, this);
                return;
            }
        }
    }
}
