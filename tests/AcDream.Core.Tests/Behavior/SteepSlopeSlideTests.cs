using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class SteepSlopeSlideTests
{
    [Fact]
    public void PlacedOnATooSteepSlope_SlidesDownAndStopsOnTheFlat()
    {
        // Flat at 10 m for vx <= 2 (x <= 48); from x = 48 to 96 the ground rises 40 m per 24 m (N.z = 0.51 < floor_z).
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (vx, _) => vx <= 2 ? 10 : 10 + 40 * Math.Min(vx - 2, 2));
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 2, 4);
        // At x = 60 the slope is 10 + 40 * 12 / 24 = 30 m high. A placement takes any contact plane (not walking):
        // in contact, but not on walkable ground, so gravity stays on and friction off (both need ON_WALKABLE).
        PhysicsObj obj = SweepScene.Walker(world, new Position(cell, new Vector3(60f, 108f, 30f)));
        Assert.True((obj.TransientState & TransientState.Contact) != 0);
        Assert.True((obj.TransientState & TransientState.OnWalkable) == 0);

        SweepScene.Run(world, 200, _ =>
            Assert.True(obj.Position.Frame.Origin.Z >= SweepScene.Ground(terrain, obj.Position) - 0.002f));

        // It slides down the slope (adjust_offset projects each step onto the plane), lands on the flat ground and stands:
        // walkable contact at z = 10, and friction plus the small-velocity stop end the slide.
        Vector3 o = obj.Position.Frame.Origin;
        Assert.True(o.X < 48f);
        Assert.Equal(10f, o.Z, 3);
        Assert.True((obj.TransientState & (TransientState.Contact | TransientState.OnWalkable)) == (TransientState.Contact | TransientState.OnWalkable));
        Assert.Equal(Vector3.Zero, obj.Velocity);
    }
}
