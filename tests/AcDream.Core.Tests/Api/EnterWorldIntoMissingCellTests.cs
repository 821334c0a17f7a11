using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// <see cref="PhysicsObj.EnterWorld"/> into a cell that does not exist or is not loaded returns false and changes nothing: an
/// object out of the world stays out (cell 0, its stored position, inactive), one in the world stays where it was, shadows
/// included. (Retail's enter_world stores the position and sends the object to the lost cell: docs/divergences.md.)
/// </summary>
public class EnterWorldIntoMissingCellTests
{
    private static readonly uint UnloadedBlockCell = SweepScene.CellId(SweepScene.BlockX + 1, SweepScene.BlockY, 2, 2);

    private static PhysicsWorld Flat(out TerrainWorld terrain, out WorldCells cells)
    {
        terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20); // only 0x8080 is loaded
        cells = new WorldCells(terrain);
        return new PhysicsWorld(0.0) { Sweep = new RetailSweep(cells) };
    }

    private static string State(PhysicsObj o) =>
        $"{o.CellId:X8} {o.Position.ObjCellId:X8} {o.Position.Frame.Origin} {o.IsActive} {o.UpdateTime} {o.TransientState} {o.NumShadowObjects}";

    [Theory]
    [InlineData(0u)]                 // unloaded landblock 0x8180 (filled in below)
    [InlineData(0x80800100u)]        // indoor id of the loaded landblock, no such env cell
    [InlineData(0xFFFFFFFFu)]        // no landblock at all
    [InlineData(0x80800041u)]        // not a cell id (outdoor cells are 1..0x40)
    public void ObjectOutOfTheWorld_StaysOut(uint cellId)
    {
        if (cellId == 0u)
        {
            cellId = UnloadedBlockCell;
        }

        PhysicsWorld world = Flat(out _, out _);
        PhysicsObj o = world.CreateObject(1);
        o.PartArray = new SimplePartArray(1, 1);
        string before = State(o);

        Assert.False(o.EnterWorld(new Position(cellId, new Vector3(60f, 60f, 20f))));

        Assert.Equal(before, State(o));
        Assert.Equal(0u, o.CellId);
        world.Tick(0.05);
    }

    [Fact]
    public void ObjectInTheWorld_StaysWhereItWas_ShadowsIncluded()
    {
        PhysicsWorld world = Flat(out TerrainWorld terrain, out _);
        PhysicsObj o = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f));
        ObjCell cell = terrain.GetVisible(ObjectScene.Cell(100f, 100f))!;
        Assert.True(ObjectScene.CellLists(cell, o));
        string before = State(o);

        Assert.False(o.EnterWorld(new Position(UnloadedBlockCell, new Vector3(60f, 60f, 20f))));

        Assert.Equal(before, State(o));
        Assert.True(ObjectScene.CellLists(cell, o));
    }

    [Fact]
    public void FreeSpace_InvalidCellId_ReturnsFalse_NothingChanged()
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj o = world.CreateObject(1);
        o.PartArray = new SimplePartArray(1, 1);
        string before = State(o);

        Assert.False(o.EnterWorld(new Position(0u, new Vector3(10f, 10f, 0f))));
        Assert.False(o.EnterWorld(new Position(0x0000_0041u, new Vector3(10f, 10f, 0f))));

        Assert.Equal(before, State(o));
        // A valid cell still enters (free space has every landblock).
        Assert.True(o.EnterWorld(new Position(TickTestContext.OutdoorCell, new Vector3(10f, 10f, 0f))));
        Assert.Equal(TickTestContext.OutdoorCell, o.CellId);
    }

    [Fact]
    public void LoadedCell_StillEnters()
    {
        PhysicsWorld world = Flat(out _, out _);
        PhysicsObj o = world.CreateObject(1);
        o.PartArray = new SimplePartArray(1, 1);
        // (60, 60) lies in cell (2, 2) of 0x8080: cell index 2 * 8 + 2 + 1 = 19 = 0x13.
        Assert.True(o.EnterWorld(new Position(0x80800013u, new Vector3(60f, 60f, 20f))));
        Assert.Equal(0x80800013u, o.CellId);
    }
}
