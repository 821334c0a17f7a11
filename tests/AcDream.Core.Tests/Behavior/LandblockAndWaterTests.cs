using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class LandblockAndWaterTests
{
    [Fact]
    public void Walking_AcrossALandblockCorner_ChangesCellIdsAndRehomesThePosition()
    {
        TerrainWorld terrain = SweepScene.Terrain();
        const int bx = SweepScene.BlockX, by = SweepScene.BlockY;
        SweepScene.AddBlock(terrain, bx, by, (_, _) => 20);
        SweepScene.AddBlock(terrain, bx + 1, by, (_, _) => 20);
        SweepScene.AddBlock(terrain, bx, by + 1, (_, _) => 20);
        SweepScene.AddBlock(terrain, bx + 1, by + 1, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        // Start at (190, 190.5) in cell (7,7) of block (bx, by), heading 45 (north-east) at 3 m/s: 0.15 m per tick along the
        // diagonal. y reaches 192 first (when x = 191.5), so the walker passes through cell (7,0) of block (bx, by + 1)
        // before x reaches 192 and it enters cell (0,0) of block (bx + 1, by + 1).
        PhysicsObj obj = SweepScene.Walker(world, new Position(SweepScene.CellId(bx, by, 7, 7), Frame.FromHeading(new Vector3(190f, 190.5f, 20f), 45f)));
        SweepScene.SetWalk(obj, new Vector3(0f, 3f, 0f));
        var seen = new List<uint> { obj.Position.ObjCellId };
        SweepScene.Run(world, 40, _ =>
        {
            if (seen[^1] != obj.Position.ObjCellId)
            {
                seen.Add(obj.Position.ObjCellId);
            }

            Assert.Equal(20f, obj.Position.Frame.Origin.Z);
        });

        Assert.Equal(new[] { SweepScene.CellId(bx, by, 7, 7), SweepScene.CellId(bx, by + 1, 7, 0), SweepScene.CellId(bx + 1, by + 1, 0, 0) }, seen);
        // 40 ticks * 0.15 m = 6 m along the diagonal: (+4.2426, +4.2426) from (190, 190.5) = (194.2426, 194.7426) in the
        // first block's frame, i.e. (2.2426, 2.7426) local to block (bx + 1, by + 1).
        Vector3 o = obj.Position.Frame.Origin;
        Assert.Equal(2.2426, o.X, 2);
        Assert.Equal(2.7426, o.Y, 2);
    }

    [Theory]
    [InlineData(0f)]
    [InlineData(8f)]
    public void Sweeping50MetresPerSecond_IntoAHillside_NeverEndsBelowTheSurface(float dropHeight)
    {
        // Flat at 10 m up to x = 96, then a hill rising 40 m per 24 m cell (N.z = 0.51, a wall to walkers).
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (vx, _) => vx <= 4 ? 10 : 10 + 40 * (vx - 4));
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 3, 4);
        PhysicsObj obj = SweepScene.Walker(world, new Position(cell, new Vector3(80f, 108f, 10f + dropHeight)));
        // 50 m/s (retail's cap) is 2.5 m per tick: ceil(2.5 / 0.5) = 5 sweep steps per tick at r = 0.5.
        obj.SetVelocity(new Vector3(50f, 0f, -3f));
        SweepScene.Run(world, 60, _ =>
        {
            float ground = SweepScene.Ground(terrain, obj.Position);
            Assert.True(obj.Position.Frame.Origin.Z >= ground - 0.001f, $"origin {obj.Position.Frame.Origin} below ground {ground}");
        });
    }

    // One landblock at 20 m whose vertices (4,4), (5,4), (4,5), (5,5) are water (terrain type 17): cell (4,4) has four water
    // corners (ENTIRELY water), cell (3,4) two (PARTIALLY), and the block as a whole is PARTIALLY water.
    private static (TerrainWorld, PhysicsWorld) PondScene()
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20,
            (vx, vy) => vx >= 4 && vx <= 5 && vy >= 4 && vy <= 5 ? 17 : 1);
        return (terrain, SweepScene.Physics(terrain, out _));
    }

    [Theory]
    // Cell (4,4), all corners water: depth 0.9 (get_water_depth, ENTIRELY_WATER).
    [InlineData(4, 108f, 108f, 0.9f)]
    // Cell (3,4) (x 72..96, y 96..120), partly water: the nearest corner decides (calc_water_depth).
    // (76, 100): west and south half -> corner (3,4), solid -> 0.1.
    [InlineData(3, 76f, 100f, 0.1f)]
    // (90, 114): east and north half -> corner (4,5), water -> 0.45.
    [InlineData(3, 90f, 114f, 0.45f)]
    public void StandingInWater_SinksByTheWaterDepth_AndSetsWaterContact(int cellX, float x, float y, float depth)
    {
        var (_, world) = PondScene();
        PhysicsObj obj = SweepScene.Walker(world, new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, cellX, 4), new Vector3(x, y, 20f)));
        // validate_walkable adds the depth to the low point's distance above the plane, so the low point rests `depth` below
        // the surface: origin.z = 20 - depth. (The placement's step down is 0.6 m: a 0.9 m pond is reached by falling into it,
        // sqrt(2 * 0.9 / 9.8) = 0.43 s; 40 ticks of 0.05 s leave time to land and settle.)
        SweepScene.Run(world, 40);
        Assert.Equal(20f - depth, obj.Position.Frame.Origin.Z, 4);
        Assert.True((obj.TransientState & TransientState.WaterContact) != 0);
        Assert.True((obj.TransientState & TransientState.Contact) != 0);
    }

    [Fact]
    public void StandingOnDryGround_NextToWater_HasNoWaterContact()
    {
        var (_, world) = PondScene();
        // Cell (1,1): no water corner.
        PhysicsObj obj = SweepScene.Walker(world, new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 1, 1), new Vector3(36f, 36f, 20f)));
        Assert.Equal(20f, obj.Position.Frame.Origin.Z);
        Assert.True((obj.TransientState & TransientState.WaterContact) == 0);
    }

    [Fact]
    public void Placement_InALandblockEntirelyWater_FailsForAWalker()
    {
        // Every vertex water: every cell ENTIRELY water, so the block is too; find_env_collisions refuses non-missiles.
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20, (_, _) => 17);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        PhysicsObj obj = world.CreateObject(1);
        var parts = new SimplePartArray(1, 0);
        parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) });
        obj.PartArray = parts;
        Assert.False(obj.EnterWorld(new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4), new Vector3(108f, 108f, 20f))));
    }
}
