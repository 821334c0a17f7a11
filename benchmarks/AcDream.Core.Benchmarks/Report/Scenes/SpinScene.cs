using System;
using System.Globalization;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// Constant spin at 2 rad/s about +Z (free space, no gravity, at rest) through <c>combine</c> and <c>grotate</c> every step.
/// Reference: the closed-form rotation <see cref="ClosedForms.SpinAboutZ"/> at the consumed physics time. Error: the
/// rotation angle between simulated and reference orientation at the end, degrees; the note gives the quaternion's norm drift.
/// </summary>
internal sealed class SpinScene : WorldSim
{
    public const string Name = "constant spin 2 rad/s";
    public const string Reference = "closed form q(t) = (cos t, 0, 0, sin t)";
    private const double Omega = 2.0;
    private readonly PhysicsObj _obj;
    private readonly double _t0;
    private double _err;
    private double _drift;

    public SpinScene(PhysicsProfile profile, Pacing pacing, double seconds)
        : base(new PhysicsWorld(0.0, profile), pacing, seconds)
    {
        PhysicsObj obj = World.CreateObject(1);
        obj.PartArray = new SimplePartArray(1, 1) { Radius = 0.5f };
        obj.SetState((PhysicsState)PhysicsGlobals.DefaultState & ~PhysicsState.Gravity);
        if (!obj.EnterWorld(new Position(SceneKit.Cell, new Vector3(12f, 12f, 50f))))
        {
            throw new InvalidOperationException("spin object could not enter the world");
        }

        obj.SetOmega(new Vector3(0f, 0f, (float)Omega));
        obj.SetActive(true);
        _obj = obj;
        _t0 = obj.UpdateTime;
    }

    public override double Error => _err;

    public override string Note => string.Create(CultureInfo.InvariantCulture, $"|q|²-1 = {_drift:G3}");

    public override void Sample(int i)
    {
        if (i != Frames - 1)
        {
            return;
        }

        Frame f = _obj.Position.Frame;
        _err = ClosedForms.AngleDegrees((f.Qw, f.Qx, f.Qy, f.Qz), ClosedForms.SpinAboutZ(Omega, _obj.UpdateTime - _t0));
        _drift = f.QuaternionNorm2 - 1.0;
    }
}
