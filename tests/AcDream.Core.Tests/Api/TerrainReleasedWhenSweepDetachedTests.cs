using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// The cells of a <see cref="TerrainWorld"/> (or <see cref="WorldCells"/>) hold the shadows of one world's objects, so they serve
/// one <see cref="PhysicsWorld"/> at a time. When that world takes another sweep (the free-space sweep, or a retail sweep over
/// other cells), its objects' shadows leave the cells and the cells are released: another world may then take them, and its
/// objects meet none of the first world's.
/// </summary>
public class TerrainReleasedWhenSweepDetachedTests
{
    private static TerrainWorld FlatTerrain()
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20); // flat, z = 20
        return terrain;
    }

    private static PhysicsObj Boulder(PhysicsWorld world) =>
        ObjectScene.Obstacle(world, 10, ObjectScene.At(100f, 100f), spheres: new[] { new Sphere(new Vector3(0f, 0f, 1f), 1f) });

    [Fact]
    public void SwitchedToFreeSpace_TerrainGoesToAnotherWorld_WithoutTheFirstWorldsShadows()
    {
        TerrainWorld terrain = FlatTerrain();
        var first = new PhysicsWorld(0.0) { Sweep = new RetailSweep(terrain) };
        PhysicsObj boulder = Boulder(first);
        ObjCell cell = terrain.GetVisible(ObjectScene.Cell(100f, 100f))!;
        Assert.True(ObjectScene.CellLists(cell, boulder));

        first.Sweep = FreeSpaceSweep.Instance;

        Assert.False(ObjectScene.CellLists(cell, boulder));
        Assert.Equal(0, boulder.NumShadowObjects);
        var second = new PhysicsWorld(0.0);
        second.Sweep = new RetailSweep(terrain); // refused before the release
        // A walker of the second world goes straight through where the first world's boulder stands: from x = 97 east at
        // 2 m/s, 40 ticks of 0.05 s = 4 m, to x = 101.
        PhysicsObj walker = ObjectScene.Creature(second, 1, ObjectScene.At(97f, 100f, heading: 90f));
        SweepScene.SetWalk(walker, new Vector3(0f, 2f, 0f));
        SweepScene.Run(second, 40);
        Assert.Equal(101f, walker.Position.Frame.Origin.X, 3);
        // The first world still ticks (in free space).
        first.Tick(1.0);
    }

    [Fact]
    public void SwitchedToOtherCells_WorldCellsAndTheirTerrainAreReleased()
    {
        TerrainWorld terrain = FlatTerrain();
        var cells = new WorldCells(terrain);
        var first = new PhysicsWorld(0.0) { Sweep = new RetailSweep(cells) };
        Boulder(first);

        first.Sweep = new RetailSweep(FlatTerrain());

        var second = new PhysicsWorld(0.0);
        second.Sweep = new RetailSweep(cells);
        var third = new PhysicsWorld(0.0);
        Assert.Throws<ArgumentException>(() => third.Sweep = new RetailSweep(terrain)); // now the second world's
    }

    [Fact]
    public void TheSameSweepAgain_KeepsTheShadows()
    {
        TerrainWorld terrain = FlatTerrain();
        var sweep = new RetailSweep(terrain);
        var world = new PhysicsWorld(0.0) { Sweep = sweep };
        PhysicsObj boulder = Boulder(world);

        world.Sweep = sweep;

        Assert.True(ObjectScene.CellLists(terrain.GetVisible(ObjectScene.Cell(100f, 100f))!, boulder));
        Assert.Throws<ArgumentException>(() => new PhysicsWorld(0.0).Sweep = new RetailSweep(terrain));
    }
}
