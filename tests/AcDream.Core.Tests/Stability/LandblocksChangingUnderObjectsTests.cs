using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// Landblocks loaded and unloaded under a world's objects (docs/stability.md, "Landblocks changing under objects"): a block
/// replaced by <see cref="TerrainWorld.AddLandBlock(LandBlock)"/> re-homes its objects' shadows into the new cells (others still
/// collide with them); a block taken away by <see cref="TerrainWorld.RemoveLandBlock"/> sends the objects standing in it out of
/// the world (cell 0, no shadows, listed to the caller) and takes the neighbours' shadows out of its cells.
/// </summary>
public class LandblocksChangingUnderObjectsTests
{
    private static readonly int EastX = SweepScene.BlockX + 1;

    private static PhysicsWorld TwoBlocks(out TerrainWorld terrain, out RetailSweep sweep)
    {
        terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20); // flat, z = 20
        SweepScene.AddBlock(terrain, EastX, SweepScene.BlockY, (_, _) => 20);
        return SweepScene.Physics(terrain, out sweep);
    }

    // (x, 100, 20) local to landblock 0x8180, x in 0..24 or 96..120 (cell column 0 or 4; row 4).
    private static Position InEastBlock(float x) =>
        new(SweepScene.CellId(EastX, SweepScene.BlockY, (int)(x / 24f), 4), Frame.FromHeading(new Vector3(x, 100f, 20f), 0f));

    private static PhysicsObj Boulder(PhysicsWorld world, uint id, float x) =>
        ObjectScene.Obstacle(world, id, ObjectScene.At(x, 100f), spheres: new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) });

    private static PhysicsObj Walker(PhysicsWorld world, uint id, float x)
    {
        PhysicsObj w = ObjectScene.Creature(world, id, ObjectScene.At(x, 100f, heading: 90f)); // facing east
        SweepScene.SetWalk(w, new Vector3(0f, 2f, 0f));                                          // 0.1 m per 0.05 s tick
        return w;
    }

    [Fact]
    public void ReplacedBlock_ObjectsAreRehomed_OthersStillCollideWithThem()
    {
        PhysicsWorld world = TwoBlocks(out TerrainWorld terrain, out _);
        PhysicsObj boulder = Boulder(world, 2, 100f);
        ObjCell oldCell = terrain.GetVisible(ObjectScene.Cell(100f, 100f))!;

        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20); // the same terrain, new cells

        ObjCell newCell = terrain.GetVisible(ObjectScene.Cell(100f, 100f))!;
        Assert.NotSame(oldCell, newCell);
        Assert.False(ObjectScene.CellLists(oldCell, boulder));
        Assert.True(ObjectScene.CellLists(newCell, boulder));
        Assert.Equal(ObjectScene.Cell(100f, 100f), boulder.CellId);

        // A walker from x = 97 east meets the boulder as before the reload: the spheres (r 0.5 + 0.5) touch at a centre
        // distance of 1 - EPSILON, so it stops at x = 99 (within 1e-3 m), never past it.
        PhysicsObj walker = Walker(world, 1, 97f);
        SweepScene.Run(world, 60);
        Assert.InRange(walker.Position.Frame.Origin.X, 98.99f, 99.001f);
    }

    [Fact]
    public void RemovedBlock_ObjectsInItLeaveTheWorld_AndAreListed()
    {
        PhysicsWorld world = TwoBlocks(out TerrainWorld terrain, out _);
        PhysicsObj boulder = Boulder(world, 2, 100f);
        PhysicsObj walker = Walker(world, 3, 50f);
        PhysicsObj eastern = ObjectScene.Obstacle(world, 4, InEastBlock(100f), spheres: new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) });
        ObjCell oldCell = terrain.GetVisible(ObjectScene.Cell(100f, 100f))!;
        var left = new List<PhysicsObj>();

        Assert.True(terrain.RemoveLandBlock(ObjectScene.Cell(100f, 100f), left));

        Assert.Equal(new[] { boulder, walker }, left.ToArray()); // in the world's order (ascending id)
        foreach (PhysicsObj o in left)
        {
            Assert.Equal(0u, o.CellId);
            Assert.Equal(0, o.NumShadowObjects);
        }

        Assert.False(ObjectScene.CellLists(oldCell, boulder));
        Assert.NotEqual(0u, eastern.CellId);
        Assert.Equal(3, world.ObjectCount); // still the world's objects, out of every cell: not simulated
        Vector3 walkerAt = walker.Position.Frame.Origin;
        SweepScene.Run(world, 30);
        Assert.Equal(walkerAt, walker.Position.Frame.Origin);
        Assert.False(terrain.RemoveLandBlock(ObjectScene.Cell(100f, 100f), left));
    }

    [Fact]
    public void RemovedBlock_NeighboursShadowsLeaveItsCells()
    {
        PhysicsWorld world = TwoBlocks(out TerrainWorld terrain, out _);
        // A boulder in 0x8180 whose sphere (r 0.5) reaches 0.3 m over the west edge into 0x8080's cell (7, 4).
        PhysicsObj eastern = ObjectScene.Obstacle(world, 4, InEastBlock(0.2f), spheres: new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) });
        uint westCell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 7, 4);
        ObjCell west = terrain.GetVisible(westCell)!;
        bool listedBefore = ObjectScene.CellLists(west, eastern);

        Assert.True(terrain.RemoveLandBlock(westCell));

        Assert.True(listedBefore);
        Assert.False(ObjectScene.CellLists(west, eastern));
        Assert.NotEqual(0u, eastern.CellId);
        foreach (ShadowObj s in eastern.ShadowObjects)
        {
            Assert.True(s.Cell is null || s.Cell.Id >> 16 == (uint)((EastX << 8) | SweepScene.BlockY));
        }

        // Loaded again: the boulder's shadow returns to the new west cell (re-homed like a replacement).
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        Assert.True(ObjectScene.CellLists(terrain.GetVisible(westCell)!, eastern));
    }

    private sealed class BlockChanger : IStepObserver
    {
        private readonly TerrainWorld _terrain;

        public BlockChanger(TerrainWorld terrain) => _terrain = terrain;

        public int Refusals { get; private set; }

        public void OnStep(PhysicsObj obj, float quantum, double physicsTime)
        {
            try
            {
                _terrain.RemoveLandBlock(obj.CellId);
            }
            catch (System.InvalidOperationException)
            {
                Refusals++;
            }
        }
    }

    [Fact]
    public void ChangingABlockFromInsideTheTick_IsRefused_NothingChanges()
    {
        PhysicsWorld world = TwoBlocks(out TerrainWorld terrain, out _);
        PhysicsObj walker = Walker(world, 1, 50f);
        var changer = new BlockChanger(terrain);
        world.StepObserver = changer;

        SweepScene.Run(world, 1);

        Assert.Equal(1, changer.Refusals);
        Assert.Equal(2, terrain.LandBlockCount);
        Assert.NotEqual(0u, walker.CellId);
        world.StepObserver = null;
        Assert.True(terrain.RemoveLandBlock(walker.CellId)); // between ticks: fine
    }
}
