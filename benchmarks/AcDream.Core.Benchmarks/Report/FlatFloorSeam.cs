using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// A sweep stand-in for the closed-form friction scene: every move succeeds on a level walkable floor (normal +Z) at the
/// requested position. Isolates the integration from the sweep, so the reference is the closed form.
/// </summary>
internal sealed class FlatFloorSeam : TransitionSeam
{
    public override bool FindTransitionalPosition(PhysicsObj obj, in Position oldPos, in Position newPos, bool adminMove, ref TransitionResult result)
    {
        result = Floor(newPos);
        return true;
    }

    public override SetPositionError SetPosition(PhysicsObj obj, in Position pos, SetPositionFlags flags)
    {
        obj.CommitTransition(Floor(pos));
        return SetPositionError.Ok;
    }

    private static TransitionResult Floor(in Position pos)
    {
        Position p = pos;
        p.TryAdjustToOutside();
        p.Frame.Origin = new Vector3(p.Frame.Origin.X, p.Frame.Origin.Y, 0f);
        TransitionResult r = TransitionResult.FreeSpace(p);
        r.ContactPlaneValid = true;
        r.ContactPlaneNormal = new Vector3(0f, 0f, 1f);
        r.ContactPlaneD = 0f;
        r.ContactPlaneCellId = p.ObjCellId;
        return r;
    }
}
