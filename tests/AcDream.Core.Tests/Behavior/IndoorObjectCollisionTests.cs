using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class IndoorObjectCollisionTests
{
    [Fact]
    public void CreaturesInsideARoom_AreShadowedInTheIndoorCell_AndCollide()
    {
        WorldCells cells = BspScene.FlatWorld();
        RoomScene.Build(cells);
        PhysicsWorld world = BspScene.Physics(cells);
        // The first creature walks in through the door: from local (3, -3) north for 60 ticks of 0.1 m to local (3, 3),
        // inside the room (cell 0x80800100), and stops there.
        Vector3 start = RoomScene.Origin + new Vector3(3f, -3f, 0f);
        PhysicsObj a = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(start.X, start.Y), Frame.FromHeading(start, 0f)), id: 1);
        SweepScene.SetWalk(a, new Vector3(0f, 2f, 0f));
        SweepScene.Run(world, 60);
        SweepScene.SetWalk(a, Vector3.Zero);
        SweepScene.Run(world, 2);
        Assert.Equal(RoomScene.Room, a.Position.ObjCellId);
        Assert.Equal(103f, a.Position.Frame.Origin.Y, 2);
        // Its shadow is in the room's cell.
        Assert.True(ObjectScene.CellLists(cells.GetVisible(RoomScene.Room)!, a));

        // The second follows the same way and is stopped by the first with the gap at the sum of the radii (1.0): at local
        // y = 2, i.e. y = 102 (the step to 102.1 comes within 0.9 of the first creature).
        Vector3 start2 = RoomScene.Origin + new Vector3(3f, -5f, 0f);
        PhysicsObj b = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(start2.X, start2.Y), Frame.FromHeading(start2, 0f)), id: 2);
        SweepScene.SetWalk(b, new Vector3(0f, 2f, 0f));
        SweepScene.Run(world, 100);

        Assert.Equal(RoomScene.Room, b.Position.ObjCellId);
        Assert.Equal(102f, b.Position.Frame.Origin.Y, 2);
        Assert.Equal(103f, a.Position.Frame.Origin.Y, 2);
        Assert.Contains(b.CollisionRecords.ToArray(), r => r.ObjectId == a.Id);
    }
}
