using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Replay.Harness;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// A body sliding at 10 m/s on level walkable ground (friction 0.95f, <see cref="FlatFloorSeam"/>) for 1 s, before the
/// small-velocity stop. Reference: the closed form distance <see cref="ClosedForms.FrictionDistance"/> at the consumed
/// physics time. Error: largest |x - x_ref| over the run, m.
/// </summary>
internal sealed class FrictionScene : WorldSim
{
    public const string Name = "friction decay 10 m/s, 1 s";
    public const string Reference = "closed form v0 (1 - e^(-λt)) / λ";
    private const float X0 = 2f;
    private readonly PhysicsObj _obj;
    private readonly double _t0;
    private double _max;

    public FrictionScene(PhysicsProfile profile, Pacing pacing, double seconds)
        : base(new PhysicsWorld(0.0, profile) { Sweep = new ReplayGroundSweep() }, pacing, seconds)
    {
        _obj = SceneKit.Ball(World, new Vector3(X0, 12f, 0f));
        _obj.SetVelocity(new Vector3(10f, 0f, 0f));
        _t0 = _obj.UpdateTime;
    }

    public override double Error => _max;

    public override void Sample(int i)
    {
        double t = _obj.UpdateTime - _t0;
        double xRef = X0 + ClosedForms.FrictionDistance(10.0, _obj.Friction, t);
        Position basis = new(SceneKit.Cell, Vector3.Zero);
        double x = basis.GetOffset(_obj.Position).X;
        _max = Math.Max(_max, Math.Abs(x - xRef));
    }
}
