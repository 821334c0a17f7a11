using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// Root motion is the part array's (retail <c>CPartArray::Update</c> → <c>CSequence::update</c>); animation data or a
/// client part array can hand back any offset. The object tick bounds it so that no accepted part array makes a later
/// <c>Tick</c> throw: a non-finite offset is dropped, one longer than <see cref="PhysicsGlobals.MaxVelocity"/> ×
/// <see cref="PhysicsGlobals.MaxQuantum"/> (50 m/s × 0.2 s = 10 m per step) is shortened to that length along its
/// direction. Before the bound, a 1,000 m step reached the sweep's 192 m refusal and Tick threw.
/// </summary>
public class RootMotionBoundTests
{

    private sealed class WildPartArray(Vector3 step) : IPartArray
    {
        private readonly SimplePartArray _inner = new(numParts: 1, numSpheres: 1);

        public int NumSpheres => _inner.NumSpheres;
        public ReadOnlySpan<Sphere> Spheres => _inner.Spheres;
        public int NumParts => _inner.NumParts;
        public float Radius => _inner.Radius;
        public float Height => _inner.Height;
        public float StepUpHeight => _inner.StepUpHeight;
        public float StepDownHeight => _inner.StepDownHeight;
        public void Update(float quantum, ref Frame offsetFrame) => offsetFrame.Origin = step;
        public void SetFrame(in Frame frame) => _inner.SetFrame(frame);
        public void SetCellId(uint cellId) => _inner.SetCellId(cellId);
        public void HandleMovement() => _inner.HandleMovement();
        public void HandleEnterWorld() => _inner.HandleEnterWorld();
        public Frame GetPartFrame(int index) => _inner.GetPartFrame(index);
        public void SetScale(float scale) => _inner.SetScale(scale);
        public void SetTranslucency(float translucency) => _inner.SetTranslucency(translucency);
        public void SetPartTranslucency(uint part, float translucency) => _inner.SetPartTranslucency(part, translucency);
        public void SetLuminosity(float luminosity) => _inner.SetLuminosity(luminosity);
        public void SetPartLuminosity(uint part, float luminosity) => _inner.SetPartLuminosity(part, luminosity);
        public void SetDiffusion(float diffusion) => _inner.SetDiffusion(diffusion);
        public void SetPartDiffusion(uint part, float diffusion) => _inner.SetPartDiffusion(part, diffusion);
    }

    [Fact]
    public void TheBound_IsMaxVelocityTimesMaxQuantum()
    {
        // 50 × 0.2 in float = 10.000000149... rounds to 10f (0x41200000).
        Assert.Equal(10f, PhysicsObj.MaxRootMotionPerStep);
        Assert.Equal(0x41200000u, BitConverter.SingleToUInt32Bits(PhysicsObj.MaxRootMotionPerStep));
    }

    [Theory]
    [InlineData(1000f, 0f, 0f)]
    [InlineData(float.NaN, 0f, 0f)]
    [InlineData(float.PositiveInfinity, 1f, 0f)]
    [InlineData(3e38f, 3e38f, 0f)]
    public void WildRootMotion_OnTheGround_NeverMakesTickThrow(float x, float y, float z)
    {
        var terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        PhysicsObj obj = world.CreateObject(1);
        obj.PartArray = new WildPartArray(new Vector3(x, y, z));
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4);
        Assert.True(obj.EnterWorld(new Position(cell, new Vector3(100f, 100f, 20f))));

        SweepScene.Run(world, 20); // a second of 0.05 s ticks, each one step of root motion
        Assert.True(VectorMath.IsFinite(obj.Position.Frame.Origin));
    }

    [Fact]
    public void LongRootMotion_IsShortenedAlongItsDirection()
    {
        Vector3 offset = new(30f, 40f, 0f); // length 50: scaled by 10/50 to (6, 8, 0)
        Vector3 bounded = PhysicsObj.BoundRootMotion(offset);
        Assert.Equal(new Vector3(6f, 8f, 0f), bounded);
        Assert.Equal(Vector3.Zero, PhysicsObj.BoundRootMotion(new Vector3(float.NaN, 0f, 0f)));
        Vector3 small = new(0.475f, 0f, 0f);
        Assert.Equal(small, PhysicsObj.BoundRootMotion(small));
    }
}
