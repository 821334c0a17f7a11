using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// A projectile launched at (30, 0, 20) m/s from (10, 12, 100) in free space, for 3 s (it ends 100 m east). Reference: the
/// closed-form arc <see cref="ClosedForms.Projectile"/> at the consumed physics time. Error: largest distance, m.
/// </summary>
internal sealed class ProjectileScene : WorldSim
{
    public const string Name = "projectile arc 3 s";
    public const string Reference = "closed form p0 + v0 t + g t²/2";
    private static readonly Vector3 P0 = new(10f, 12f, 100f);
    private static readonly Vector3 V0 = new(30f, 0f, 20f);
    private readonly PhysicsObj _obj;
    private readonly double _t0;
    private double _max;

    public ProjectileScene(PhysicsProfile profile, Pacing pacing, double seconds)
        : base(new PhysicsWorld(0.0, profile), pacing, seconds)
    {
        _obj = SceneKit.Ball(World, P0);
        _obj.SetVelocity(V0);
        _t0 = _obj.UpdateTime;
    }

    public override double Error => _max;

    public override void Sample(int i)
    {
        var r = ClosedForms.Projectile(P0, V0, PhysicsGlobals.Gravity, _obj.UpdateTime - _t0);
        _max = Math.Max(_max, ClosedForms.Distance(_obj.Position.Frame.Origin, r));
    }
}
