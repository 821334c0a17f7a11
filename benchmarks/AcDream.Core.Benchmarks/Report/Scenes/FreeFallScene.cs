using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// Free fall from rest (one 0.5 m sphere, free space) for 5 s, just short of the 50 m/s clamp (5.1 s; past it retail's
/// integration keeps adding g q²/2 per step, which would dominate). Reference: the closed form
/// <see cref="ClosedForms.FreeFallZ"/> at the object's consumed physics time. Error: largest |z - z_ref| over the run, m.
/// </summary>
internal sealed class FreeFallScene : WorldSim
{
    public const string Name = "free fall 5 s";
    public const string Reference = "closed form z0 + g t²/2";
    private const float Z0 = 1000f;
    private readonly PhysicsObj _obj;
    private readonly double _t0;
    private double _max;

    public FreeFallScene(PhysicsProfile profile, Pacing pacing, double seconds)
        : base(new PhysicsWorld(0.0, profile), pacing, seconds)
    {
        _obj = SceneKit.Ball(World, new Vector3(12f, 12f, Z0));
        _t0 = _obj.UpdateTime;
    }

    public override double Error => _max;

    public override void Sample(int i)
    {
        double t = _obj.UpdateTime - _t0;
        double zRef = ClosedForms.FreeFallZ(Z0, PhysicsGlobals.Gravity, t);
        _max = Math.Max(_max, Math.Abs(_obj.Position.Frame.Origin.Z - zRef));
    }
}
