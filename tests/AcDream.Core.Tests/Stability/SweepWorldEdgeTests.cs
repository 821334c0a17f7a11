using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

public class SweepWorldEdgeTests
{
    [Fact]
    public void WalkingIntoTheWestEdgeOfTheWorld_StopsAtIt()
    {
        // Landblock (0, 0x80) is on the world's west edge: x < 0 has no outdoor cell (lcoord -1). A step whose centre
        // leaves the world finds no cell, adjust_to_outside fails, and the step collides: the walker stays at x >= 0.
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, 0, SweepScene.BlockY, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        uint cell = SweepScene.CellId(0, SweepScene.BlockY, 0, 4);
        PhysicsObj obj = SweepScene.Walker(world, new Position(cell, Frame.FromHeading(new Vector3(3f, 100f, 20f), 270f)));
        SweepScene.SetWalk(obj, new Vector3(0f, 3f, 0f));
        SweepScene.Run(world, 100, _ =>
        {
            Assert.True(obj.Position.Frame.Origin.X >= 0f);
            Assert.Equal(cell, obj.Position.ObjCellId);
            Assert.Equal(20f, obj.Position.Frame.Origin.Z);
        });

        // 3 m at 0.15 m per tick reaches the edge in 20 ticks; it ends within one step of it.
        Assert.InRange(obj.Position.Frame.Origin.X, 0f, 0.15f);
    }

    [Fact]
    public void WalkingIntoAnUnloadedLandblock_GoesToTheLostCell()
    {
        // Only block (0x80, 0x80) is loaded. Walking east past x = 192 the check cell becomes null (the neighbour's cells
        // are not loaded), the position is re-homed by adjust_to_outside, and the sweep ends with no current cell:
        // SetPositionInternal sends the object to the lost cell (no cell, inactive) — retail's behaviour at an unloaded edge.
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        PhysicsObj obj = SweepScene.Walker(world, new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 7, 4), Frame.FromHeading(new Vector3(190f, 100f, 20f), 90f)));
        SweepScene.SetWalk(obj, new Vector3(0f, 3f, 0f));
        SweepScene.Run(world, 40);
        Assert.Equal(0u, obj.CellId);
        Assert.False(obj.IsActive);
    }
}

public class SweepBadInputTests
{
    [Fact]
    public void Transition_NaNTarget_Throws_AndLeavesThePoolFree()
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out RetailSweep sweep);
        PhysicsObj obj = SweepScene.Walker(world, new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4), new Vector3(100f, 100f, 20f)));
        Position bad = obj.Position;
        bad.Frame.Origin = new Vector3(float.NaN, 100f, 20f);
        Position before = obj.Position;
        Assert.Throws<System.ArgumentException>(() => sweep.RunTransition(obj, obj.Position, bad, false));
        Assert.Equal(0, sweep.Pool.Level);
        Assert.Equal(before, obj.Position);
    }

    [Fact]
    public void CellArray_RemoveOutOfRange_Throws()
    {
        var a = new CellArray();
        a.AddCell(1u, null);
        Assert.Throws<System.ArgumentOutOfRangeException>(() => a.RemoveCell(1));
        Assert.Equal(1, a.NumCells);
        a.RemoveCell(0);
        Assert.Equal(0, a.NumCells);
    }
}
