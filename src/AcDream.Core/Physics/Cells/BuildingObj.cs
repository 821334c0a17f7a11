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

    /// <summary>The shell part (retail: <c>part_array->parts[0]</c>).</summary>
    public PhysicsPart Part { get; }

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
}
