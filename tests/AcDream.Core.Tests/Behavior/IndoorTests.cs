using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class IndoorTests
{
    private const float R = 0.5f;

    private static PhysicsObj WalkerAt(PhysicsWorld world, Vector3 p) =>
        SweepScene.Walker(world, new Position(BspScene.OutdoorCell(p.X, p.Y), Frame.FromHeading(p, 0f)), R);

    [Fact]
    public void WalkingThroughADoorway_EntersTheIndoorCell_AndWalkingBackOut_ReturnsOutdoors()
    {
        WorldCells cells = BspScene.FlatWorld();
        RoomScene.Build(cells);
        PhysicsWorld world = BspScene.Physics(cells);
        // Start 5 m south of the door (local (3, -5); y = 95, inside outdoor cell (4, 3) and off its edges), facing north,
        // walking 2 m/s = 0.1 m per tick.
        PhysicsObj obj = WalkerAt(world, RoomScene.Origin + new Vector3(3f, -5f, 0f));
        uint outdoor = BspScene.OutdoorCell(103f, 95f);
        Assert.Equal(outdoor, obj.Position.ObjCellId);
        SweepScene.SetWalk(obj, new Vector3(0f, 2f, 0f));

        // 70 ticks: y from 95 to 102, i.e. local y 2: inside the room (its region starts at local y -0.2).
        SweepScene.Run(world, 70, _ => Assert.Equal(BspScene.Ground, obj.Position.Frame.Origin.Z, 3));
        Assert.Equal(RoomScene.Room, obj.Position.ObjCellId);
        Assert.Equal(102f, obj.Position.Frame.Origin.Y, 2);

        // Walk backwards 70 ticks: back to y = 95, outdoors again.
        SweepScene.SetWalk(obj, new Vector3(0f, -2f, 0f));
        SweepScene.Run(world, 70, _ => Assert.Equal(BspScene.Ground, obj.Position.Frame.Origin.Z, 3));
        Assert.Equal(outdoor, obj.Position.ObjCellId);
        Assert.Equal(95f, obj.Position.Frame.Origin.Y, 2);
    }

    [Fact]
    public void WalkingThroughTheRoomIntoTheCorridor_AndBackOut_VisitsEachCellInOrder()
    {
        WorldCells cells = BspScene.FlatWorld();
        RoomScene.Build(cells);
        PhysicsWorld world = BspScene.Physics(cells);
        PhysicsObj obj = WalkerAt(world, RoomScene.Origin + new Vector3(3f, -4f, 0f));
        SweepScene.SetWalk(obj, new Vector3(0f, 2f, 0f));

        // 130 ticks north: y 96 -> 109 (local 9: in the corridor, whose region is local y 6..12).
        SweepScene.Run(world, 130);
        Assert.Equal(RoomScene.Corridor, obj.Position.ObjCellId);

        // Further north the corridor's end wall (local y 12) stops it: centre y <= 12 - r.
        SweepScene.Run(world, 40, _ => Assert.True(obj.Position.Frame.Origin.Y <= 112f - R + 0.001f));
        Assert.Equal(RoomScene.Corridor, obj.Position.ObjCellId);

        // Back out: 180 ticks south (18 m) from y ~111.5 to ~93.5, through the room to the outdoors.
        SweepScene.SetWalk(obj, new Vector3(0f, -2f, 0f));
        bool sawRoom = false;
        SweepScene.Run(world, 180, _ => sawRoom |= obj.Position.ObjCellId == RoomScene.Room);
        Assert.True(sawRoom);
        Assert.False(LandDefs.IsEnvCell(obj.Position.ObjCellId));
    }

    [Fact]
    public void IndoorWalls_StopAWalkerInsideTheRoom()
    {
        WorldCells cells = BspScene.FlatWorld();
        RoomScene.Build(cells);
        PhysicsWorld world = BspScene.Physics(cells);
        PhysicsObj obj = WalkerAt(world, RoomScene.Origin + new Vector3(3f, -4f, 0f));
        SweepScene.SetWalk(obj, new Vector3(0f, 2f, 0f));
        SweepScene.Run(world, 60);
        Assert.Equal(RoomScene.Room, obj.Position.ObjCellId);

        // Turn east (walk sideways: local +x is east when facing north) into the east wall at local x 6: centre x <= 6 - r.
        SweepScene.SetWalk(obj, new Vector3(2f, 0f, 0f));
        SweepScene.Run(world, 60, _ => Assert.True(obj.Position.Frame.Origin.X <= 106f - R + 0.001f));
        Assert.True(obj.Position.Frame.Origin.X >= 106f - R - 0.1f - 0.001f);
        Assert.Equal(RoomScene.Room, obj.Position.ObjCellId);
    }

    [Fact]
    public void EnteringTheWorldInsideTheRoom_PlacesTheObjectInTheIndoorCell()
    {
        WorldCells cells = BspScene.FlatWorld();
        RoomScene.Build(cells);
        PhysicsWorld world = BspScene.Physics(cells);
        // Requested in the room's cell at local (3, 3): placed there, standing on the room's floor (z = 20).
        var p = new Position(RoomScene.Room, Frame.FromHeading(RoomScene.Origin + new Vector3(3f, 3f, 0f), 0f));
        PhysicsObj obj = SweepScene.Walker(world, p, R);
        Assert.Equal(RoomScene.Room, obj.Position.ObjCellId);
        Assert.Equal(BspScene.Ground, obj.Position.Frame.Origin.Z, 3);
        Assert.True((obj.TransientState & TransientState.Contact) != 0);

        // Requested with the room's id but at a corridor point (local (3, 9)): the portal neighbour that contains the
        // sphere's centre is chosen.
        var q = new Position(RoomScene.Room, Frame.FromHeading(RoomScene.Origin + new Vector3(3f, 9f, 0f), 0f));
        PhysicsObj obj2 = SweepScene.Walker(world, q, R, id: 2);
        Assert.Equal(RoomScene.Corridor, obj2.Position.ObjCellId);
    }

    [Theory]
    [InlineData(90f)]
    [InlineData(217f)]
    public void TurnedBuilding_DoorwayAndCorridorWorkInTheCellsLocalSpace(float heading)
    {
        WorldCells cells = BspScene.FlatWorld();
        RoomScene.Build(cells, heading);
        PhysicsWorld world = BspScene.Physics(cells);
        Frame frame = RoomScene.FrameFor(heading);
        // Local (3, -5), facing the building's local north (heading + 0): 70 ticks * 0.1 m reach local (3, 2) in the room,
        // 130 ticks local (3, 8) in the corridor.
        Vector3 start = frame.LocalToGlobal(new Vector3(3f, -5f, 0f));
        PhysicsObj obj = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(start.X, start.Y), Frame.FromHeading(start, heading)), R);
        SweepScene.SetWalk(obj, new Vector3(0f, 2f, 0f));
        SweepScene.Run(world, 70);
        Assert.Equal(RoomScene.Room, obj.Position.ObjCellId);
        Vector3 local = frame.GlobalToLocal(obj.Position.Frame.Origin);
        Assert.Equal(3f, local.X, 2);
        Assert.Equal(2f, local.Y, 2);
        SweepScene.Run(world, 60);
        Assert.Equal(RoomScene.Corridor, obj.Position.ObjCellId);
        Assert.Equal(BspScene.Ground, obj.Position.Frame.Origin.Z, 3);
    }
}
