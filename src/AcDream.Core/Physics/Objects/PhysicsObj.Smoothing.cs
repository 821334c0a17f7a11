using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Objects;

// The non-retail remote-smoothing modes of PhysicsProfile.RemoteSmoothing: snapping to each report and plain linear
// extrapolation. Under the retail default none of this runs.
public sealed partial class PhysicsObj
{
    /// <summary>Velocity (world axes, m/s) used by <see cref="RemoteSmoothing.LinearExtrapolation"/> since the last report;
    /// zero otherwise.</summary>
    public Vector3 ExtrapolationVelocity => _rare?.Extrapolation is { Extrapolating: true } e ? e.Velocity : Vector3.Zero;

    // The in-range branch of MoveOrTeleport under the world's profile: retail interpolates (true); the other modes place the
    // body (false, with the placement's result).
    private bool FollowRemoteReport(in Position p, out SetPositionError placed)
    {
        RemoteSmoothing mode = World.Profile.RemoteSmoothing;
        placed = SetPositionError.Ok;
        if (mode == RemoteSmoothing.Retail)
        {
            InterpolateTo(p, IsMovingTo());
            return true;
        }

        PositionManager?.StopInterpolating();
        if (mode == RemoteSmoothing.LinearExtrapolation)
        {
            // Created at the object's first report in this mode (a network event, never inside the object's own update).
            RareComponents rare = Rare(create: true)!;
            Extrapolation e = rare.Extrapolation ??= new Extrapolation();
            double now = World.CurrentTime;
            double span = now - e.LastReportTime;
            if (span > PhysicsGlobals.Epsilon)
            {
                Vector3 d = e.LastReport.GetOffset(p);
                double inv = 1.0 / span;
                e.Velocity = new Vector3((float)(d.X * inv), (float)(d.Y * inv), (float)(d.Z * inv));
                e.Extrapolating = true;
            }

            e.LastReport = p;
            e.LastReportTime = now;
        }

        placed = SetPositionSimple(p, true);
        return false;
    }

    // LinearExtrapolation: replaces the step's offset origin (root motion) by the extrapolation velocity × quantum.
    private void ApplyExtrapolation(ref Frame offset, float quantum)
    {
        Extrapolation? e = _rare?.Extrapolation;
        if (e is null || !e.Extrapolating || World.Profile.RemoteSmoothing != RemoteSmoothing.LinearExtrapolation)
        {
            return;
        }

        Vector3 v = e.Velocity;
        offset.Origin = _position.Frame.GlobalToLocalVec(new Vector3(v.X * quantum, v.Y * quantum, v.Z * quantum));
    }

    // LinearExtrapolation's state: the last report, its time (NaN before the first) and the velocity the last two gave.
    private sealed class Extrapolation
    {
        public Position LastReport;
        public double LastReportTime = double.NaN;
        public Vector3 Velocity;
        public bool Extrapolating;
    }
}
