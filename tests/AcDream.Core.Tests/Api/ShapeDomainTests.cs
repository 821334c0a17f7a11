using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// Collision shapes and step heights have a domain (<see cref="InputLimits.MaxShapeReach"/>,
/// <see cref="InputLimits.MaxStepHeight"/>): a 1e7 m sphere used to be accepted, then lifted its object 1e7 m out of the ground
/// in one step, beyond <see cref="InputLimits.MaxCoordinate"/>, and every later Tick threw from the sweep. A shape at the
/// bound ticks (at scale 1 and at <see cref="InputLimits.MaxScale"/>); one past it is refused with nothing changed.
/// </summary>
public sealed class ShapeDomainTests
{
    private const int Bx = 0x80;
    private const int By = 0x80;

    // The float after 192: 192 + 2^-16 (192 = 1.5 × 2^7, ulp 2^(7-23)).
    private static readonly float PastReach = MathF.BitIncrement(192f);

    private static (PhysicsWorld World, PhysicsObj Obj, SimplePartArray Parts) Scene()
    {
        TerrainWorld terrain = SyntheticTerrain.Metres();
        SyntheticTerrain.AddBlock(terrain, Bx, By, (_, _) => 10); // flat ground at z = 10
        var world = new PhysicsWorld(terrain);
        PhysicsObj obj = world.CreateObject(1);
        var parts = new SimplePartArray(1, 0);
        parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) });
        obj.PartArray = parts;
        obj.Movement = new AcDream.Core.Physics.Objects.Seams.BasicMovementManager();
        Assert.True(obj.EnterWorld(SyntheticTerrain.OnGround(terrain, SyntheticTerrain.CellId(Bx, By, 4, 4), 100f, 100f)));
        return (world, obj, parts);
    }

    private static void TickOneSecond(PhysicsWorld world, PhysicsObj obj)
    {
        obj.SetVelocity(new Vector3(1f, 0f, 0f));
        for (int k = 1; k <= 20; k++)
        {
            world.Tick(world.CurrentTime + 0.05);
        }
    }

    [Fact]
    public void Constants_ArePinned()
    {
        // One landblock, 192 m: float 0x43400000 (1.5 × 2^7).
        Assert.Equal(192f, InputLimits.MaxShapeReach);
        Assert.Equal(0x43400000, BitConverter.SingleToInt32Bits(InputLimits.MaxShapeReach));
        Assert.Equal(192f, InputLimits.MaxStepHeight);
        Assert.Equal(0x43400000, BitConverter.SingleToInt32Bits(InputLimits.MaxStepHeight));
        // At the reach bound and the largest scale the sweep's push-out stays far inside the coordinate bound.
        Assert.True(InputLimits.MaxScale * InputLimits.MaxShapeReach + 10f < InputLimits.MaxCoordinate);
    }

    [Fact]
    public void SphereOf1e7m_IsRefused_NothingChanged_AndTheWorldTicks()
    {
        (PhysicsWorld world, PhysicsObj obj, SimplePartArray parts) = Scene();

        var e = Assert.Throws<ArgumentException>(() => parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 1e7f) }));

        Assert.Equal("spheres", e.ParamName);
        Assert.Contains("Sphere 0", e.Message, StringComparison.Ordinal);
        Assert.Equal(new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f), parts.Spheres[0]);
        TickOneSecond(world, obj);
        Assert.True(obj.Position.Frame.Origin.Z < 11f);
    }

    [Theory]
    [InlineData(1f)]
    [InlineData(100f)] // InputLimits.MaxScale: the object is lifted 100 × 192 = 19,200 m, inside ±65,536 m
    public void SphereAtTheBound_Ticks(float scale)
    {
        (PhysicsWorld world, PhysicsObj obj, SimplePartArray parts) = Scene();
        // |centre| + radius = 0.5 + 191.5 = 192 exactly.
        parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 191.5f) });
        obj.SetScaleStatic(scale);

        TickOneSecond(world, obj);

        // The sphere, pushed out of the ground, rests on it: origin at 10 + scale × (191.5 - 0.5).
        Assert.InRange(obj.Position.Frame.Origin.Z, 10f + scale * 191f - 0.05f * scale, 10f + scale * 191f + 0.05f * scale);
    }

    [Fact]
    public void SpherePastTheBound_IsRefused_NothingChanged()
    {
        (_, _, SimplePartArray parts) = Scene();
        Sphere before = parts.Spheres[0];

        Assert.Throws<ArgumentException>(() => parts.SetSpheres(new[] { new Sphere(Vector3.Zero, PastReach) }));
        // The second sphere reaches 100 + 92.5 = 192.5 m: refused, naming index 1.
        var e = Assert.Throws<ArgumentException>(() => parts.SetSpheres(new[]
        {
            new Sphere(Vector3.Zero, 1f), new Sphere(new Vector3(0f, 100f, 0f), 92.5f),
        }));

        Assert.Contains("Sphere 1", e.Message, StringComparison.Ordinal);
        Assert.Equal(1, parts.NumSpheres);
        Assert.Equal(before, parts.Spheres[0]);
        parts.SetSpheres(new[] { new Sphere(Vector3.Zero, 192f) });
    }

    [Fact]
    public void CylinderAtTheBound_IsAccepted_AndTicks_PastIt_IsRefused()
    {
        (PhysicsWorld world, PhysicsObj obj, SimplePartArray parts) = Scene();
        // |low point| + radius + height = 0 + 96 + 96 = 192.
        parts.SetCylSpheres(new[] { new CylSphere(Vector3.Zero, 96f, 96f) });
        TickOneSecond(world, obj);

        var e = Assert.Throws<ArgumentException>(() => parts.SetCylSpheres(new[] { new CylSphere(new Vector3(0f, 0f, 1f), 96f, 96f) }));

        Assert.Equal("cylSpheres", e.ParamName);
        Assert.Contains("Cylinder sphere 0", e.Message, StringComparison.Ordinal);
        Assert.Equal(new CylSphere(Vector3.Zero, 96f, 96f), parts.CylSpheres[0]);
    }

    [Fact]
    public void StepHeights_AtTheBound_AreAccepted_PastIt_Refused()
    {
        var parts = new SimplePartArray(1, 1) { StepUpHeight = 192f, StepDownHeight = 0f };
        Assert.Equal(192f, parts.StepUpHeight);

        Assert.Throws<ArgumentException>(() => parts.StepUpHeight = PastReach);
        Assert.Throws<ArgumentException>(() => parts.StepDownHeight = -0.01f);
        Assert.Throws<ArgumentException>(() => parts.StepDownHeight = 1e7f);

        Assert.Equal(192f, parts.StepUpHeight);
        Assert.Equal(0f, parts.StepDownHeight);
    }

    [Fact]
    public void SetupPhysics_RefusesShapesAndStepHeightsPastTheBound()
    {
        Sphere[] ok = { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) };
        Assert.Throws<ArgumentException>(() => new SetupPhysics(new[] { new Sphere(Vector3.Zero, 1e7f) }, default, 1f, 2f, 0.6f, 1.5f));
        Assert.Throws<ArgumentException>(() => new SetupPhysics(ok, new[] { new CylSphere(Vector3.Zero, 100f, 100f) }, 1f, 2f, 0.6f, 1.5f));
        Assert.Throws<ArgumentException>(() => new SetupPhysics(ok, default, 1f, 2f, PastReach, 1.5f));
        Assert.Throws<ArgumentException>(() => new SetupPhysics(ok, default, 1f, 2f, 0.6f, PastReach));
        var atBound = new SetupPhysics(new[] { new Sphere(Vector3.Zero, 192f) }, new[] { new CylSphere(Vector3.Zero, 96f, 96f) }, 1f, 2f, 192f, 192f);
        Assert.Equal(192f, atBound.StepDownHeight);
    }
}
