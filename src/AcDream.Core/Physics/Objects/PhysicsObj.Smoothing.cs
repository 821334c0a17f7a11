using System.Numerics;
using AcDream.Core.Physics.Math;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Objects;

// The non-retail remote-smoothing modes of PhysicsProfile.RemoteSmoothing: snapping to each report and plain linear
// extrapolation. Under the retail default none of this runs.
public sealed partial class PhysicsObj
{
    private Position _lastReport;
    private double _lastReportTime = double.NaN;
    private Vector3 _extrapolationVelocity;
    private bool _extrapolating;

    /// <summary>Velocity (world axes, m/s) used by <see cref="RemoteSmoothing.LinearExtrapolation"/> since the last report;
    /// zero otherwise.</summary>
    public Vector3 ExtrapolationVelocity => _extrapolating ? _extrapolationVelocity : Vector3.Zero;

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
            double now = World.CurrentTime;
            double span = now - _lastReportTime;
            if (span > PhysicsGlobals.Epsilon)
            {
                Vector3 d = _lastReport.GetOffset(p);
                double inv = 1.0 / span;
                _extrapolationVelocity = new Vector3((float)(d.X * inv), (float)(d.Y * inv), (float)(d.Z * inv));
                _extrapolating = true;
            }

            _lastReport = p;
            _lastReportTime = now;
        }

        placed = SetPositionSimple(p, true);
        return false;
    }

    // LinearExtrapolation: replaces the step's offset origin (root motion) by the extrapolation velocity × quantum.
    private void ApplyExtrapolation(ref Frame offset, float quantum)
    {
        if (!_extrapolating || World.Profile.RemoteSmoothing != RemoteSmoothing.LinearExtrapolation)
        {
            return;
        }

        Vector3 v = _extrapolationVelocity;
        offset.Origin = _position.Frame.GlobalToLocalVec(new Vector3(v.X * quantum, v.Y * quantum, v.Z * quantum));
    }
}
