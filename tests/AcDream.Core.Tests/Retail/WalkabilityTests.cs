using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class WalkabilityTests
{
    [Fact]
    public void IsWalkable_AtAndAroundFloorZ()
    {
        // floor_z = (float)cos(3437.746770784939) = 0.66417414 (bits 0x3F2A0751); the test is >=.
        Assert.True(Walkability.IsWalkable(new Vector3(0f, 0f, PhysicsGlobals.FloorZ)));
        Assert.False(Walkability.IsWalkable(new Vector3(0f, 0f, System.MathF.BitDecrement(PhysicsGlobals.FloorZ))));
        Assert.True(Walkability.IsWalkable(Vector3.UnitZ));
    }

    [Fact]
    public void IsLandable_AtLandingZ_AndSteeperThanFloor()
    {
        // z_for_landing = 0.0871557f (bits 0x3DB27EB0). A 60-degree slope (N.z = 0.5) is landable but not walkable.
        Assert.True(Walkability.IsLandable(new Vector3(0f, 0f, 0.0871557f)));
        Assert.False(Walkability.IsLandable(new Vector3(0f, 0f, 0.087f)));
        Assert.True(Walkability.IsLandable(new Vector3(0.866f, 0f, 0.5f)));
        Assert.False(Walkability.IsWalkable(new Vector3(0.866f, 0f, 0.5f)));
    }

    [Fact]
    public void WalkableAllowance_FloorWhenOnWalkable_LandingOtherwise()
    {
        Assert.Equal(PhysicsGlobals.FloorZ, Walkability.WalkableAllowance(true));
        Assert.Equal(PhysicsGlobals.LandingZ, Walkability.WalkableAllowance(false));
    }

    [Fact]
    public void TerrainTriangle_SteeperThanFloorZ_IsNotWalkable()
    {
        // Rise 30 m over 24 m: N = (-30, 0, 24)/sqrt(1476); N.z = 24 / 38.42 = 0.6247 < 0.6642.
        var steep = new Polygon(0, [new(0f, 0f, 0f), new(24f, 0f, 30f), new(24f, 24f, 30f)], [0, 1, 2]);
        Assert.False(Walkability.IsWalkable(steep));
        // Rise 20 m over 24 m: N.z = 24 / sqrt(976) = 0.7682 >= 0.6642.
        var gentle = new Polygon(0, [new(0f, 0f, 0f), new(24f, 0f, 20f), new(24f, 24f, 20f)], [0, 1, 2]);
        Assert.True(Walkability.IsWalkable(gentle));
    }
}
