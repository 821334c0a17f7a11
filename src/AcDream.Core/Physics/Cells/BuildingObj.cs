using System;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Objects.Parts;

namespace AcDream.Core.Physics.Cells;

/// <summary>
/// A building standing on outdoor cells: its shell (a physics part with a BSP) and its doors into indoor cells.
/// Retail: <c>CBuildingObj</c> (PORTAL/cphysobj/CBuildingObj.c), the collision half of it. Attach it to every land cell
/// it stands on (<see cref="LandCell.Building"/>), as retail's stab lists do.
/// </summary>
public sealed class BuildingObj
{
    private readonly BldPortal[] _portals;

    /// <summary>Creates a building.</summary>
    /// <param name="part">The shell: its graphics object's physics BSP placed at the building's position.</param>
    /// <param name="portals">The doors into indoor cells.</param>
    /// <exception cref="ArgumentNullException">An argument is null.</exception>
    public BuildingObj(PhysicsPart part, BldPortal[] portals)
    {
        ArgumentNullException.ThrowIfNull(part);
        ArgumentNullException.ThrowIfNull(portals);
        Part = part;
        _portals = (BldPortal[])portals.Clone();
    }

    // A building made from its data id: its part 0 may have no physics BSP (nothing of it collides; its doors still lead in).
    internal BuildingObj(PhysicsPart? part, BldPortal[] portals, uint numLeaves)
    {
        Part = part;
        _portals = portals;
        NumLeaves = numLeaves;
    }

    /// <summary>The shell part (retail: <c>part_array->parts[0]</c>, the only part a building collides through), or null when
    /// that part's GfxObj has no physics BSP (a building made from its data id; nothing of it collides).</summary>
    public PhysicsPart? Part { get; }

    /// <summary>Retail <c>num_leaves</c>: the size of the renderer's leaf-cell array (<c>leaf_cells</c>). Physics never uses it:
    /// a building hangs on the one land cell under its origin.</summary>
    public uint NumLeaves { get; }

    /// <summary>The land cell the building hangs on (0 until placed). Retail: <c>set_cell_id</c> in
    /// <c>CBuildingObj::add_to_cell</c>.</summary>
    public uint CellId { get; private set; }

    /// <summary>Hangs the building on <paramref name="cell"/>: the cell keeps it unless it already holds one (the first
    /// wins); the building records the cell either way.</summary>
    // retail: CBuildingObj::add_to_cell (acclient.c:719256)
    internal void AddToCell(LandCell cell)
    {
        cell.AddBuilding(this);
        CellId = cell.Id;
    }

    /// <summary>Takes the building off its cell: the cell's building is cleared (whichever it was) and the building's cell
    /// id reset.</summary>
    // retail: CBuildingObj::remove (acclient.c:719056) -> CSortCell::remove_building (acclient.c:356080)
    internal void Remove(LandCell? cell)
    {
        if (cell is not null)
        {
            cell.Building = null;
        }

        CellId = 0;
    }

    /// <summary>The doors. Retail: <c>portals</c>.</summary>
    public ReadOnlySpan<BldPortal> Portals => _portals;

    /// <summary>
    /// The shell against the check spheres, with the path's building flag raised for the call (placement then ignores
    /// solid leaves once the path has reached an interior cell). A blocked airborne object records an environment
    /// collision.
    /// </summary>
    // retail: CBuildingObj::find_building_collisions (acclient.c:719115)
    internal TransitionState FindBuildingCollisions(Transition transition)
    {
        ArgumentNullException.ThrowIfNull(transition);
        if (Part is null)
        {
            // retail: CPhysicsPart::find_obj_collisions answers OK for a part without a physics BSP
            return TransitionState.Ok;
        }

        transition.SpherePath.BldgCheck = true;
        TransitionState ts = Part.FindObjCollisions(transition);
        transition.SpherePath.BldgCheck = false;
        if (ts != TransitionState.Ok && (transition.ObjectInfo.State & ObjectInfoState.Contact) == 0)
        {
            transition.CollisionInfo.CollidedWithEnvironment = true;
        }

        return ts;
    }

    /// <summary>Adds the indoor cells behind the doors that the spheres reach.</summary>
    // retail: CBuildingObj::find_building_transit_cells (acclient.c:719067)
    internal void FindBuildingTransitCells(ICellSource cells, ReadOnlySpan<Sphere> spheres, CellArray cellArray, SpherePath? path)
    {
        ArgumentNullException.ThrowIfNull(cells);
        for (int i = 0; i < _portals.Length; i++)
        {
            if (cells.GetVisible(_portals[i].OtherCellId) is EnvCell other)
            {
                other.CheckBuildingTransit(_portals[i].OtherPortalId, spheres, cellArray, path);
            }
        }
    }

    /// <summary>Adds the indoor cells behind the doors that the parts' bounding boxes reach.</summary>
    // retail: CBuildingObj::find_building_transit_cells(parts) (acclient.c:719091)
    internal void FindBuildingTransitCellsForParts(ICellSource cells, ReadOnlySpan<PlacedPartBox> parts, CellArray cellArray)
    {
        for (int i = 0; i < _portals.Length; i++)
        {
            if (cells.GetVisible(_portals[i].OtherCellId) is EnvCell other)
            {
                other.CheckBuildingTransitForParts(cells, _portals[i].OtherPortalId, parts, cellArray);
            }
        }
    }
}
