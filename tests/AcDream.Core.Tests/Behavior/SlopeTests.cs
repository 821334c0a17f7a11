using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class SlopeTests
{
    // A landblock rising along +x: vertex (vx, vy) at index base + rise * vx (one metre per index), so every triangle
    // lies in the plane z = base + (rise / 24) x. Its normal is (-k, 0, 1) / sqrt(1 + k²) with k = rise / 24.
    // floor_z = 0.66417414 allows k up to sqrt(1 / 0.66417414² - 1) = 1.12594 (48.38 degrees):
    //   rise 27 m: k = 1.125,   N.z = 1 / sqrt(2.265625) = 0.664364  (walkable, just)
    //   rise 28 m: k = 1.16667, N.z = 1 / sqrt(2.361111) = 0.650791  (too steep, just)
    private const int Base = 10;

    private static double NormalZ(int rise)
    {
        double k = rise / 24.0;
        return 1.0 / Math.Sqrt(1.0 + k * k);
    }

    [Fact]
    public void SlopeNormals_StraddleFloorZ()
    {
        Assert.True(NormalZ(27) >= PhysicsGlobals.FloorZ);
        Assert.True(NormalZ(28) < PhysicsGlobals.FloorZ);
    }

    [Theory]
    [InlineData(1)]
    [InlineData(-1)]
    public void Walking_UpAndDown_SlopeJustUnderFloorZ_KeepsContactOnThePlane(int direction)
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (vx, _) => Base + 27 * vx);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 3, 4);
        float x0 = 84f;
        float ground0 = (float)(Base + 27.0 / 24.0 * x0);
        // Heading 90 walks +x (uphill), heading 270 walks -x (downhill).
        PhysicsObj obj = SweepScene.Walker(world, new Position(cell, Frame.FromHeading(new Vector3(x0, 108f, ground0 + 0.5f), direction > 0 ? 90f : 270f)));
        Assert.True((obj.TransientState & TransientState.OnWalkable) != 0);
        SweepScene.SetWalk(obj, new Vector3(0f, 3.12f, 0f));

        double nz = NormalZ(27);
        // Retail's terrain test (OBJECTINFO::validate_walkable) puts the sphere's LOWEST point (centre - r z) on the plane,
        // not the sphere's surface: on a slope the origin (r below the centre) sits exactly on the ground under it.
        SweepScene.Run(world, 100, _ =>
        {
            Vector3 o = obj.Position.Frame.Origin;
            double ground = Base + 27.0 / 24.0 * o.X;
            Assert.Equal(ground, o.Z, 3);
            Assert.True((obj.TransientState & TransientState.Contact) != 0);
            Assert.True((obj.TransientState & TransientState.OnWalkable) != 0);
        });

        // adjust_offset: uphill the 0.156 m step (3.12 m/s * 0.05 s) points into the plane (step·N < 0) and is projected onto
        // it: step - N (step·N) has x = 0.156 (1 - N.x²) = 0.156 N.z² = 0.068856 m per tick. Downhill (step·N > 0) it is
        // snapped onto the plane along z (snap_to_plane), keeping x: 0.156 m per tick.
        double perTick = direction > 0 ? 0.156 * nz * nz : 0.156;
        Assert.Equal(x0 + direction * 100 * perTick, obj.Position.Frame.Origin.X, 2);
    }

    [Fact]
    public void Walking_IntoSlopeJustOverFloorZ_StopsTheWalkerAtItsFoot()
    {
        // Flat at index Base for vx <= 4 (x <= 96), then rising 28 m per 24 m: too steep to walk.
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (vx, _) => vx <= 4 ? Base : Base + 28 * (vx - 4));
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 3, 4);
        PhysicsObj obj = SweepScene.Walker(world, new Position(cell, Frame.FromHeading(new Vector3(90f, 108f, Base), 90f)));
        SweepScene.SetWalk(obj, new Vector3(0f, 3.12f, 0f));
        SweepScene.Run(world, 200);

        // 200 ticks at 0.156 m (3.12 m/s * 0.05 s) would carry it 31.2 m on flat ground. The terrain test uses the sphere's
        // lowest point (directly under the origin): the first step whose low point lies over the steep cell (x > 96) finds a
        // plane with N.z = 0.6508 < floor_z, the step down fails, and the edge slide (EDGE_SLIDE is in the default state)
        // cliff-slides it back. Steps land at 90 + 0.156 n: n = 38 gives 95.928 (over flat ground), n = 39 would give
        // 96.084 (over the slope). The walker stays at 95.928 on the flat part, sliding along the crease normal (-1, 0, 0).
        Vector3 o = obj.Position.Frame.Origin;
        Assert.Equal(90.0 + 38 * 0.156, o.X, 3);
        Assert.Equal(108f, o.Y);
        Assert.Equal(Base, o.Z);
        Assert.Equal(new Vector3(-1f, 0f, 0f), obj.SlidingNormal);
        Assert.True((obj.TransientState & TransientState.Sliding) != 0);
        Assert.True((obj.TransientState & TransientState.Contact) != 0);
    }

    [Fact]
    public void Standing_OnWalkableSlope_DoesNotCreep()
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (vx, _) => Base + 27 * vx);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 3, 4);
        float x0 = 84f;
        PhysicsObj obj = SweepScene.Walker(world, new Position(cell, new Vector3(x0, 108f, (float)(Base + 27.0 / 24.0 * x0) + 0.5f)));
        Position start = obj.Position;
        // On walkable ground in contact, calc_acceleration zeroes gravity: no velocity, no root motion, nothing moves.
        SweepScene.Run(world, 1000);
        Assert.Equal(start.Frame.Origin, obj.Position.Frame.Origin);
        Assert.Equal(start.ObjCellId, obj.Position.ObjCellId);
        Assert.True((obj.TransientState & TransientState.OnWalkable) != 0);
    }
}
