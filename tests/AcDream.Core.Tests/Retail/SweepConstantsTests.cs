using System;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class SweepConstantsTests
{
    [Fact]
    public void NotWalkingStepHeight_Is0Point04_Bits3D23D70A()
    {
        Assert.Equal(0.039999999f, Transition.NotWalkingStepHeight);
        Assert.Equal(0x3D23D70A, BitConverter.SingleToInt32Bits(Transition.NotWalkingStepHeight));
    }

    [Fact]
    public void PlacementConstants_MatchRetailLiterals()
    {
        Assert.Equal(0x40800000, BitConverter.SingleToInt32Bits(Transition.PlacementSearchDistance)); // 4.0
        Assert.Equal(0x40000000, BitConverter.SingleToInt32Bits(Transition.PlacementSmallSearchDistance)); // 2.0
        Assert.Equal(0x3E000000, BitConverter.SingleToInt32Bits(Transition.PlacementSmallRadius)); // 0.125
        Assert.Equal(0x3EF5C28F, BitConverter.SingleToInt32Bits(Transition.PlacementMinRadius)); // 0.47999999
        Assert.Equal(0x40490FF9, BitConverter.SingleToInt32Bits(Transition.PlacementPi)); // 3.1415999
        Assert.Equal(0x3D4CCCCD, BitConverter.SingleToInt32Bits(RetailSweep.PlacementTolerance)); // 0.050000001
    }

    [Fact]
    public void PoolAndPathSizes_MatchRetail()
    {
        Assert.Equal(10, TransitionPool.Capacity);
        Assert.Equal(2, SpherePath.MaxSpheres);
        Assert.Equal(8, CellArray.InitialCapacity);
        Assert.Equal(3, Transition.StationaryFallFrames);
    }

    [Fact]
    public void DummySphere_RadiusAndCentre_0Point1()
    {
        Sphere s = Sphere.Dummy;
        Assert.Equal(0x3DCCCCCD, BitConverter.SingleToInt32Bits(s.Radius));
        Assert.Equal(new System.Numerics.Vector3(0f, 0f, 0.1f), s.Center);
    }

    [Fact]
    public void TransitionStateAndFlagValues_MatchAcclientH()
    {
        Assert.Equal(0, (int)TransitionState.Invalid);
        Assert.Equal(1, (int)TransitionState.Ok);
        Assert.Equal(2, (int)TransitionState.Collided);
        Assert.Equal(3, (int)TransitionState.Adjusted);
        Assert.Equal(4, (int)TransitionState.Slid);
        Assert.Equal(0x1u, (uint)ObjectInfoState.Contact);
        Assert.Equal(0x2u, (uint)ObjectInfoState.OnWalkable);
        Assert.Equal(0x4u, (uint)ObjectInfoState.IsViewer);
        Assert.Equal(0x8u, (uint)ObjectInfoState.PathClipped);
        Assert.Equal(0x10u, (uint)ObjectInfoState.FreeRotate);
        Assert.Equal(0x200u, (uint)ObjectInfoState.EdgeSlide);
        Assert.Equal(0, (int)InsertType.Transition);
        Assert.Equal(1, (int)InsertType.Placement);
        Assert.Equal(2, (int)InsertType.InitialPlacement);
    }
}
