// PhysicsObj — the object's obstacle summary in the cells that list its shadows (not retail: ObstacleSummary).
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Objects.Parts;

namespace AcDream.Core.Physics.Objects;

// The summary a cell's object loop reads to pass over this object without reading it, and its upkeep: every change of an
// input (frame, cell id, scale, part array, its spheres, the HAS_PHYSICS_BSP bit, the parent) calls SyncObstacleSummary.
public sealed partial class PhysicsObj
{
    /// <summary>
    /// The object's <see cref="ObstacleSummary"/> as it stands: parented (never tested), decided from the object (a
    /// physics BSP, or a part array other than <see cref="SimplePartArray"/>, or one whose
    /// <see cref="SimplePartArray.ObstacleReach"/> is not ≥ 0: cylinder spheres), or its reach |scale| · ObstacleReach rounded
    /// up to a float (<see cref="IsOutOfReach"/> tests the exact one).
    /// </summary>
    // non-retail: the inputs of IsOutOfReach, packed (ObstacleSummary)
    internal ObstacleSummary ComputeObstacleSummary()
    {
        ObstacleSummary s;
        s.X = _position.Frame.Origin.X;
        s.Y = _position.Frame.Origin.Y;
        s.Z = _position.Frame.Origin.Z;
        s.CellId = _position.ObjCellId;
        if (Parent is not null)
        {
            s.Reach = ObstacleSummary.Parented;
        }
        else if (TryGetSphereReach(out float bound))
        {
            s.Reach = ObstacleSummary.RoundUpReach(Scale, bound);
        }
        else
        {
            s.Reach = ObstacleSummary.TestFully;
        }

        return s;
    }

    /// <summary>Writes the object's summary into every cell that lists one of its shadows. Called after every change of an
    /// input of <see cref="ComputeObstacleSummary"/>; a cell that lists a shadow later computes it when the shadow is added.</summary>
    // non-retail: keeps ObstacleSummary in step
    internal void SyncObstacleSummary()
    {
        int n = NumShadowObjects;
        if (n == 0)
        {
            return;
        }

        ObstacleSummary s = ComputeObstacleSummary();
        ShadowObj[] shadows = _shadowObjects;
        for (int i = 0; i < n; i++)
        {
            ShadowObj shadow = shadows[i];
            shadow.Cell?.SetObstacleSummary(shadow, s);
        }
    }
}
