using System;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Core.Physics.Cells;

// The land cell as a collision cell of the sweep (retail's CLandCell virtual functions).
public sealed partial class LandCell : ObjCell
{
    /// <summary>
    /// The terrain, then the building (<see cref="Building"/>), then objects against the check spheres.
    /// </summary>
    // retail: CLandCell::find_collisions (acclient.c:354886)
    internal override TransitionState FindCollisions(Transition transition)
    {
        TransitionState ts = FindEnvCollisions(transition);
        if (ts == TransitionState.Ok)
        {
            ts = FindBuildingCollisions(transition);
        }

        if (ts == TransitionState.Ok)
        {
            ts = FindObjCollisions(transition);
        }

        return ts;
    }

    /// <summary>
    /// The terrain triangle under the path's low point against the first check sphere: a cell of a landblock that is
    /// entirely water refuses walkers; otherwise <see cref="ObjectInfo.ValidateWalkable"/> pushes the sphere out of the
    /// ground (sunk by the water depth) and records the contact plane.
    /// </summary>
    // retail: CLandCell::find_env_collisions (acclient.c:354991)
    internal override TransitionState FindEnvCollisions(Transition transition)
    {
        TransitionState ts = CheckEntryRestrictions(transition);
        if (ts != TransitionState.Ok)
        {
            return ts;
        }

        SpherePath path = transition.SpherePath;
        Vector3 off = LandDefs.GetBlockOffset(path.CheckPos.ObjCellId, Id);
        Vector3 low = path.GlobalLowPoint;
        var local = new Vector3((float)((double)low.X - off.X), (float)((double)low.Y - off.Y), (float)((double)low.Z - off.Z));
        if (!FindTerrainPoly(local, out Polygon? walkable))
        {
            return ts;
        }

        ObjectInfo oi = transition.ObjectInfo;
        if (BlockWaterType == WaterType.EntirelyWater
            && (oi.State & ObjectInfoState.IsViewer) == 0
            && (oi.Object!.State & PhysicsState.Missile) == 0)
        {
            return TransitionState.Collided;
        }

        float waterDepth = GetWaterDepth(local);
        Sphere g = path.GlobalSphere[0];
        var check = new Sphere(
            new Vector3(g.Center.X - off.X, g.Center.Y - off.Y, g.Center.Z - off.Z),
            g.Radius);
        return oi.ValidateWalkable(check, walkable.Plane, WaterType != WaterType.NotWater, waterDepth, path, transition.CollisionInfo, Id);
    }

    /// <summary>The outdoor cells around the spheres (added once per list) and the indoor cells behind the building's doors.</summary>
    // retail: CLandCell::find_transit_cells (acclient.c:355422)
    internal override void FindTransitCells(ICellSource cells, in Position p, ReadOnlySpan<Sphere> spheres, CellArray cellArray, SpherePath? path)
    {
        CellList.AddAllOutsideCells(cells, p, spheres, cellArray);

        // retail: CSortCell::find_transit_cells (acclient.c:356086) -> CBuildingObj::find_building_transit_cells
        Building?.FindBuildingTransitCells(cells, spheres, cellArray, path);
    }
}
