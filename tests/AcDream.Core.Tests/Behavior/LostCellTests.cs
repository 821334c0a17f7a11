using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// Retail's lost cells (<c>CObjectMaint::GotoLostCell</c> 309732, <c>InitObjCell</c> 309758, <c>RemoveFromLostCell</c>
/// 309545; <c>CPhysicsObj::leave_visibility</c> 321417, <c>reenter_visibility</c> 323395): an object whose cell goes away
/// waits under its position's cell id and is placed again where it was when that cell is loaded again.
/// </summary>
public class LostCellTests
{
    private static (PhysicsWorld World, WorldCells Cells, LandBlock Block) FlatBlock()
    {
        PhysicsWorld world = WorldSceneEntries.World(out WorldCells cells);
        var height = new byte[81];
        System.Array.Fill(height, (byte)BspScene.Ground);
        LandBlock block = cells.Terrain.AddLandBlock(0x8080FFFFu, height, new ushort[81]);
        return (world, cells, block);
    }

    [Fact]
    public void AnObjectWhoseBlockIsRemoved_WaitsInItsLostCell_AndComesBackWhenTheBlockIsAddedAgain()
    {
        (PhysicsWorld world, WorldCells cells, LandBlock block) = FlatBlock();
        PhysicsObj a = SweepScene.Walker(world, ObjectScene.At(30f, 40f), id: 1);
        PhysicsObj b = SweepScene.Walker(world, ObjectScene.At(31.5f, 40f), id: 2);
        uint cell = a.CellId;
        Assert.Equal(cell, b.CellId);
        Vector3 atA = a.Position.Frame.Origin, atB = b.Position.Frame.Origin;

        cells.Terrain.RemoveLandBlock(0x8080FFFFu);
        Assert.Equal((0u, 0u), (a.CellId, b.CellId));
        Assert.Equal(2, world.LostObjectCount);
        Assert.True(world.IsInLostCell(a));

        cells.Terrain.AddLandBlock(block);
        Assert.Equal((cell, cell), (a.CellId, b.CellId));
        Assert.Equal((atA, atB), (a.Position.Frame.Origin, b.Position.Frame.Origin));
        Assert.Equal(0, world.LostObjectCount);
        // Both are back in the cell's object list.
        Assert.Equal(2, cells.Terrain.GetLandCell(cell)!.NumObjects);
    }

    [Fact]
    public void ALostObjectPlacedElsewhere_OrRemoved_LeavesItsLostCell()
    {
        (PhysicsWorld world, WorldCells cells, LandBlock block) = FlatBlock();
        PhysicsObj a = SweepScene.Walker(world, ObjectScene.At(30f, 40f), id: 1);
        PhysicsObj b = SweepScene.Walker(world, ObjectScene.At(60f, 40f), id: 2);
        cells.Terrain.RemoveLandBlock(0x8080FFFFu);
        Assert.Equal(2, world.LostObjectCount);

        world.RemoveObject(b);
        Assert.Equal(1, world.LostObjectCount);
        cells.Terrain.AddLandBlock(block);
        Assert.Equal(0, world.LostObjectCount);
        Assert.True(b.IsRemoved);
        Assert.Equal(0u, b.CellId);
        Assert.NotEqual(0u, a.CellId);
    }

    [Fact]
    public void AnObjectLostTwice_IsListedOnce_UnderItsLatestCell()
    {
        (PhysicsWorld world, WorldCells cells, _) = FlatBlock();
        PhysicsObj a = SweepScene.Walker(world, ObjectScene.At(30f, 40f), id: 1);
        cells.Terrain.RemoveLandBlock(0x8080FFFFu);
        a.GoToLostCell(ObjectScene.At(100f, 100f));
        Assert.Equal(1, world.LostObjectCount);
        Assert.Equal(ObjectScene.At(100f, 100f).ObjCellId, a.Position.ObjCellId);
        Assert.True(world.IsInLostCell(a));
    }
}
