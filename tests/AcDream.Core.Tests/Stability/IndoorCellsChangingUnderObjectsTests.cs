using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// Indoor cells loaded and unloaded under a world's objects, as landblocks (docs/stability.md, "Landblocks changing under
/// objects"): a cell replaced by <see cref="WorldCells.AddEnvCell"/> re-homes its objects' shadows into the new cell; a cell
/// taken away by <see cref="WorldCells.RemoveEnvCell"/> sends the objects standing in it out of the world and lists them.
/// </summary>
public class IndoorCellsChangingUnderObjectsTests
{
    private static PhysicsObj InTheRoom(out WorldCells cells, out PhysicsWorld world)
    {
        cells = BspScene.FlatWorld();
        RoomScene.Build(cells);
        world = BspScene.Physics(cells);
        // Room-local (3, 3): the middle of the 6 m × 6 m room.
        Vector3 at = RoomScene.Origin + new Vector3(3f, 3f, 0f);
        PhysicsObj o = SweepScene.Walker(world, new Position(RoomScene.Room, Frame.FromHeading(at, 0f)), id: 1);
        Assert.Equal(RoomScene.Room, o.CellId);
        Assert.True(ObjectScene.CellLists(cells.GetVisible(RoomScene.Room)!, o));
        return o;
    }

    [Fact]
    public void ReplacedCell_ObjectsAreRehomed()
    {
        PhysicsObj o = InTheRoom(out WorldCells cells, out _);
        ObjCell old = cells.GetVisible(RoomScene.Room)!;
        WorldCells other = BspScene.FlatWorld();
        RoomScene.Build(other); // the same room, built again: a new EnvCell with the same id

        cells.AddEnvCell(other.GetEnvCell(RoomScene.Room)!);

        ObjCell now = cells.GetVisible(RoomScene.Room)!;
        Assert.NotSame(old, now);
        Assert.False(ObjectScene.CellLists(old, o));
        Assert.True(ObjectScene.CellLists(now, o));
        Assert.Equal(RoomScene.Room, o.CellId);
    }

    [Fact]
    public void RemovedCell_ObjectsInItLeaveTheWorld_AndAreListed()
    {
        PhysicsObj o = InTheRoom(out WorldCells cells, out PhysicsWorld world);
        ObjCell old = cells.GetVisible(RoomScene.Room)!;
        var left = new List<PhysicsObj>();

        Assert.True(cells.RemoveEnvCell(RoomScene.Room, left));

        Assert.Equal(new[] { o }, left.ToArray());
        Assert.Equal(0u, o.CellId);
        Assert.Equal(0, o.NumShadowObjects);
        Assert.False(ObjectScene.CellLists(old, o));
        SweepScene.Run(world, 10);
        Assert.Equal(0u, o.CellId);
    }
}
