using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>The fidelity switches of <see cref="PhysicsProfile"/>: every default is retail, and choosing the retail values
/// explicitly changes nothing.</summary>
public class FidelityDefaultsTests
{
    [Fact]
    public void BothNamedProfiles_HaveRetailFidelityDefaults()
    {
        foreach (PhysicsProfile p in new[] { PhysicsProfile.Retail, PhysicsProfile.AceCompatible })
        {
            Assert.Equal(ArithmeticMode.RetailDouble, p.Arithmetic);
            Assert.Equal(1, p.RenormaliseEvery);
            Assert.Equal(1f, p.SweepStepScale);
            Assert.Equal(0x3F800000, BitConverter.SingleToInt32Bits(p.SweepStepScale)); // exactly 1.0f: calc_num_steps' 1.0 * radius
            Assert.Equal(RemoteSmoothing.Retail, p.RemoteSmoothing);
            Assert.True(p.HasRetailFidelity);
        }

        Assert.Equal(0, (int)ArithmeticMode.RetailDouble);
        Assert.Equal(0, (int)RemoteSmoothing.Retail);
        Assert.Same(PhysicsProfile.Retail, new PhysicsWorld().Profile);
    }

    [Fact]
    public void With_ChangesOnlyTheNamedSwitch_AndKeepsTheTimeSlicing()
    {
        PhysicsProfile ace = PhysicsProfile.AceCompatible.With(arithmetic: ArithmeticMode.Float32);
        Assert.True(ace.AccumulateBelowMinQuantum);
        Assert.Equal(0.1, ace.MaxQuantum);
        Assert.Equal(1.0 / 30.0, ace.MinQuantum);
        Assert.Equal(ArithmeticMode.Float32, ace.Arithmetic);
        Assert.Equal(1, ace.RenormaliseEvery);
        Assert.False(ace.HasRetailFidelity);
        Assert.Equal("AceCompatible+Float32", ace.Name);

        PhysicsProfile r = PhysicsProfile.Retail.With(renormaliseEvery: 0, sweepStepScale: 2f, remoteSmoothing: RemoteSmoothing.Snap);
        Assert.False(r.AccumulateBelowMinQuantum);
        Assert.Equal(0.2, r.MaxQuantum);
        Assert.Equal(0, r.RenormaliseEvery);
        Assert.Equal(2f, r.SweepStepScale);
        Assert.Equal(RemoteSmoothing.Snap, r.RemoteSmoothing);
        Assert.Equal(ArithmeticMode.RetailDouble, r.Arithmetic);

        PhysicsProfile back = r.With(renormaliseEvery: 1, sweepStepScale: 1f, remoteSmoothing: RemoteSmoothing.Retail);
        Assert.True(back.HasRetailFidelity);
    }

    [Theory]
    [InlineData(-1, 1f)]
    [InlineData(1, 0f)]
    [InlineData(1, -2f)]
    [InlineData(1, float.NaN)]
    [InlineData(1, float.PositiveInfinity)]
    [InlineData(1, 1001f)]
    public void With_OutOfRange_Throws(int every, float scale)
    {
        Assert.Throws<ArgumentException>(() => PhysicsProfile.Retail.With(renormaliseEvery: every, sweepStepScale: scale));
    }

    [Fact]
    public void With_UndefinedEnum_Throws()
    {
        Assert.Throws<ArgumentException>(() => PhysicsProfile.Retail.With(arithmetic: (ArithmeticMode)7));
        Assert.Throws<ArgumentException>(() => PhysicsProfile.Retail.With(remoteSmoothing: (RemoteSmoothing)7));
    }

    [Fact]
    public void ExplicitRetailValues_GiveBitIdenticalTicks()
    {
        // Same scene under the default profile and under a derived profile that names every retail value: the frames and
        // velocities must be bitwise equal after 300 ticks of a spinning, flying body.
        PhysicsProfile explicitRetail = PhysicsProfile.Retail.With(ArithmeticMode.RetailDouble, 1, 1f, RemoteSmoothing.Retail, "explicit");
        PhysicsObj a = Thrown(new PhysicsWorld(0.0));
        PhysicsObj b = Thrown(new PhysicsWorld(0.0, explicitRetail));
        for (int n = 1; n <= 300; n++)
        {
            a.World.Tick(n / 30.0);
            b.World.Tick(n / 30.0);
        }

        Assert.True(a.Position.Frame.Equals(b.Position.Frame));
        Assert.Equal(a.Velocity, b.Velocity);
    }

    internal static PhysicsObj Thrown(PhysicsWorld world)
    {
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 500f));
        obj.SetVelocity(new Vector3(3f, 1f, 12f));
        obj.SetOmega(new Vector3(0.3f, 0.2f, 2f));
        return obj;
    }
}
