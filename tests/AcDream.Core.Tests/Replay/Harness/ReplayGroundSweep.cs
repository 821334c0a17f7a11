using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Tests.Replay.Harness;

/// <summary>
/// A test <see cref="CollisionSweep"/>: endless flat outdoor ground at z = 0. A sweep ends where it was asked to, re-homed
/// to the outdoor cell under it; at or below <see cref="ContactHeight"/> it is clamped to the ground with a z-up contact
/// plane (CONTACT and ON_WALKABLE follow), above it the object is airborne. Placements do the same and can be made to fail.
/// </summary>
/// <remarks>Stands in for the collision module, which the manager tests do not exercise. Allocation-free.</remarks>
public sealed class ReplayGroundSweep : CollisionSweep
{
    /// <summary>Height under which a sweep or placement lands on the ground, metres.</summary>
    public const float ContactHeight = 0.02f;

    /// <summary>When true, <see cref="SetPosition"/> fails with <see cref="SetPositionError.NoValidPosition"/> and changes nothing.</summary>
    public bool FailPlacements { get; set; }

    /// <summary>Number of placements (successful or not) since creation.</summary>
    public int PlacementCount { get; private set; }

    /// <summary>Flags of the last placement.</summary>
    public SetPositionFlags LastPlacementFlags { get; private set; }

    /// <inheritdoc />
    public override bool SweepObject(PhysicsObj obj, in Position oldPos, in Position newPos, bool adminMove, ref TransitionResult result)
    {
        result = Land(newPos);
        return true;
    }

    /// <inheritdoc />
    public override SetPositionError SetPosition(PhysicsObj obj, in Position pos, SetPositionFlags flags)
    {
        PlacementCount++;
        LastPlacementFlags = flags;
        if (FailPlacements)
        {
            return SetPositionError.NoValidPosition;
        }

        obj.CommitTransition(Land(pos));
        return SetPositionError.Ok;
    }

    private static TransitionResult Land(in Position pos)
    {
        Position p = pos;
        if ((p.ObjCellId & 0xFFFFu) < 0x100u)
        {
            p.TryAdjustToOutside();
        }

        TransitionResult r = TransitionResult.FreeSpace(p);
        if (p.Frame.Origin.Z <= ContactHeight)
        {
            r.CurrentPosition.Frame.Origin.Z = 0f;
            r.ContactPlaneValid = true;
            r.ContactPlaneNormal = new Vector3(0f, 0f, 1f);
            r.ContactPlaneD = 0f;
            r.ContactPlaneCellId = p.ObjCellId;
        }

        return r;
    }
}
