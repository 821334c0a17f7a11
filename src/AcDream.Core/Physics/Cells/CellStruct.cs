using System;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;

namespace AcDream.Core.Physics.Cells;

/// <summary>
/// The geometry of an indoor cell, in cell-local space: the physics BSP (its walls, floors and ceilings), the cell
/// BSP (the region the cell occupies) and the portal polygons. Retail: <c>CCellStruct</c> (acclient.h:32275,
/// PORTAL/ccell/CCellStruct.c) — the collision half of it.
/// </summary>
public sealed class CellStruct
{
    private readonly Polygon[] _portals;

    /// <summary>Creates a cell structure.</summary>
    /// <param name="physicsBsp">The collision geometry, or null for a cell without walls.</param>
    /// <param name="cellBsp">The cell's region (see <see cref="BspBuilder.BuildCell"/>).</param>
    /// <param name="portals">The portal polygons (retail looks them up by <see cref="Polygon.PolyId"/>).</param>
    /// <exception cref="ArgumentNullException"><paramref name="cellBsp"/> or <paramref name="portals"/> is null.</exception>
    public CellStruct(BspTree? physicsBsp, BspTree cellBsp, Polygon[] portals)
    {
        ArgumentNullException.ThrowIfNull(cellBsp);
        ArgumentNullException.ThrowIfNull(portals);
        PhysicsBsp = physicsBsp;
        CellBsp = cellBsp;
        _portals = (Polygon[])portals.Clone();
    }

    /// <summary>The collision geometry. Retail: <c>physics_bsp</c>.</summary>
    public BspTree? PhysicsBsp { get; }

    /// <summary>The cell's region. Retail: <c>cell_bsp</c>.</summary>
    public BspTree CellBsp { get; }

    /// <summary>The portal polygons. Retail: <c>portals</c>.</summary>
    public ReadOnlySpan<Polygon> Portals => _portals;

    /// <summary>The portal polygon with id <paramref name="polyId"/>, or null.</summary>
    // retail: CCellStruct::get_portal (acclient.c:355463)
    public Polygon? GetPortal(short polyId)
    {
        for (int i = 0; i < _portals.Length; i++)
        {
            if (_portals[i].PolyId == polyId)
            {
                return _portals[i];
            }
        }

        return null;
    }

    /// <summary>True when the cell-local point is in the cell's region.</summary>
    // retail: CCellStruct::point_in_cell (acclient.c:355495)
    public bool PointInCell(System.Numerics.Vector3 origin) => CellBsp.PointInsideCellBsp(origin);

    /// <summary>How the cell-local sphere lies against the cell's region.</summary>
    // retail: CCellStruct::sphere_intersects_cell (acclient.c:355501)
    public CellBspSphere SphereIntersectsCell(in Sphere sphere) => CellBsp.SphereIntersectsCellBsp(sphere);

    /// <summary>False when the cell-local axis-aligned box lies wholly outside the cell's region.</summary>
    // retail: CCellStruct::box_intersects_cell (acclient.c:355507)
    internal bool BoxIntersectsCell(System.Numerics.Vector3 min, System.Numerics.Vector3 max) => CellBsp.BoxIntersectsCellBsp(min, max);
}
