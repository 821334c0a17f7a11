using System;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>Pins every retail constant of <see cref="PhysicsGlobals"/> and <see cref="LandDefs"/> to its value and bit pattern.</summary>
public class PhysicsGlobalsTests
{
    private static int Bits(float f) => BitConverter.SingleToInt32Bits(f);

    private static long Bits(double d) => BitConverter.DoubleToInt64Bits(d);

    [Fact]
    public void Epsilon_IsRetailFloat0Point0002_Bits3951B717()
    {
        // acclient.c: 0.0002f is 0x3951B717; 0x3949A18A, sometimes quoted for it, is 0.000192f.
        Assert.Equal(0x3951B717, Bits(PhysicsGlobals.Epsilon));
        Assert.NotEqual(0x3949A18A, Bits(PhysicsGlobals.Epsilon));
    }

    [Fact]
    public void Quanta_AreRetailDoubles_MinOneThirtieth_MaxOneFifth_HugeTwo()
    {
        // MIN_QUANTUM = 1.0/30.0 and MAX_QUANTUM = 1.0/5.0 are long double (64-bit) in retail (acclient.c:784226, 784232).
        Assert.Equal(0x3FA1111111111111L, Bits(PhysicsGlobals.MinQuantum));
        Assert.Equal(0x3FC999999999999AL, Bits(PhysicsGlobals.MaxQuantum));
        Assert.Equal(2.0, PhysicsGlobals.HugeQuantum);
        // Their float32 roundings, as a client storing them in float would see: 1/30 -> 0x3D088889, 0.2 -> 0x3E4CCCCD.
        Assert.Equal(0x3D088889, Bits((float)PhysicsGlobals.MinQuantum));
        Assert.Equal(0x3E4CCCCD, Bits((float)PhysicsGlobals.MaxQuantum));
        // ACE's slice is 0.1 s, not retail.
        Assert.Equal(0.1, PhysicsGlobals.AceMaxQuantum);
    }

    [Fact]
    public void Gravity_IsMinus9Point8_BitsC11CCCCD()
    {
        Assert.Equal(unchecked((int)0xC11CCCCD), Bits(PhysicsGlobals.Gravity));
    }

    [Fact]
    public void FloorZ_IsCosOf3437Point7Radians_0Point66417_Bits3F2A0751()
    {
        // cos(3437.746770784939 rad): 3437.7467... = 60 * 57.2957795 (degrees-to-degrees bug). 3437.7468 - 547 * 2pi
        // = 3437.7468 - 3436.8581 = 0.8887 rad; cos(0.8887) = 0.66417.
        Assert.Equal(0x3F2A0751, Bits(PhysicsGlobals.FloorZ));
        Assert.Equal(0.66417414f, PhysicsGlobals.FloorZ);
    }

    [Fact]
    public void LandingZ_IsCos85Degrees_Bits3DB27EB0()
    {
        Assert.Equal(0x3DB27EB0, Bits(PhysicsGlobals.LandingZ));
        Assert.True(Math.Abs(Math.Cos(85.0 * Math.PI / 180.0) - PhysicsGlobals.LandingZ) < 1e-6);
    }

    [Fact]
    public void Velocities_Max50_Small0Point25()
    {
        Assert.Equal(0x42480000, Bits(PhysicsGlobals.MaxVelocity));
        Assert.Equal(2500f, PhysicsGlobals.MaxVelocitySquared);
        Assert.Equal(0x3E800000, Bits(PhysicsGlobals.SmallVelocity));
        Assert.Equal(0.0625f, PhysicsGlobals.SmallVelocitySquared);
    }

    [Fact]
    public void ObjectDefaults_MatchRetailConstructor()
    {
        Assert.Equal(0x3F733333, Bits(PhysicsGlobals.DefaultFriction));    // 0.94999999
        Assert.Equal(0x3D4CCCCD, Bits(PhysicsGlobals.DefaultElasticity));  // 0.050000001
        Assert.Equal(0, Bits(PhysicsGlobals.DefaultTranslucency));
        Assert.Equal(1.0f, PhysicsGlobals.DefaultMass);
        Assert.Equal(1.0f, PhysicsGlobals.DefaultScale);
        // 4197384 = 0x400C08 = EDGE_SLIDE 0x400000 | LIGHTING_ON 0x800 | GRAVITY 0x400 | REPORT_COLLISIONS 0x8.
        Assert.Equal(4197384u, PhysicsGlobals.DefaultState);
        Assert.Equal(0x400000u | 0x800u | 0x400u | 0x8u, PhysicsGlobals.DefaultState);
    }

    [Fact]
    public void DummySphere_Radius0Point1_Bits3DCCCCCD_AndOtherLiterals()
    {
        Assert.Equal(0x3DCCCCCD, Bits(PhysicsGlobals.DummySphereRadius));
        Assert.Equal(0x42C00000, Bits(PhysicsGlobals.PlayerActivityDistance)); // 96.0
        Assert.Equal(unchecked((long)0xBFF0000000000000UL), Bits(PhysicsGlobals.InitialPhysicsTime)); // -1.0
        // DEFAULT_VIEW_RADIUS is a float global (acclient_data.h:15710) set to EPSILON * 3.0 + 0.1 (acclient.c:784220):
        // 0.0002f = 0.000199999994947575 widened, * 3 + 0.1 = 0.100599999984843 in double, stored as the float
        // 0.100599996745586 = 0x3DCE075F.
        Assert.Equal(0x3DCE075F, Bits(PhysicsGlobals.DefaultViewRadius));
    }

    [Fact]
    public void LandDefs_Dimensions_AreRetail()
    {
        Assert.Equal(24.0f, LandDefs.CellLength);
        Assert.Equal(8, LandDefs.BlockSide);
        Assert.Equal(192.0f, LandDefs.BlockLength);
        Assert.Equal(0x43400000, Bits(LandDefs.BlockLength));
        Assert.Equal(12.0f, LandDefs.HalfCellLength);
        Assert.Equal(255, LandDefs.LandblocksPerSide);
        Assert.Equal(2040, LandDefs.LCoordLimit);
        Assert.Equal(64, LandDefs.CellsPerBlock);
        Assert.Equal(200.0f, LandDefs.MaxObjHeight);
        Assert.Equal(1000.0f, LandDefs.SkyHeight);
        Assert.Equal(5.0f, LandDefs.RoadWidth);
    }
}
