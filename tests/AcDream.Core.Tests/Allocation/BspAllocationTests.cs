using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Allocation;

public class BspAllocationTests
{
    [Fact]
    public void SweepsThroughBuildingsWallsStairsAndIndoorCells_AllocateNothing_AfterWarmUp()
    {
        WorldCells cells = BspScene.FlatWorld();
        RoomScene.Build(cells);
        // A wall (south face y = 80) and a staircase (first riser x = 60) away from the room.
        BspScene.AddBoxes(cells, new Vector3(40f, 80f, BspScene.Ground), (new Vector3(0f, 0f, 0f), new Vector3(30f, 0.5f, 3f)));
        var stairs = new (Vector3, Vector3)[5];
        for (int i = 0; i < 5; i++)
        {
            stairs[i] = (new Vector3(i, -1.5f, 0f), new Vector3(i + 1, 1.5f, (i + 1) * 0.3f));
        }

        BspScene.AddBoxes(cells, new Vector3(60f, 60f, BspScene.Ground), stairs);
        PhysicsWorld world = BspScene.Physics(cells);
        PhysicsState noEdgeSlide = (PhysicsState)PhysicsGlobals.DefaultState & ~PhysicsState.EdgeSlide;
        PhysicsObj door = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(103f, 95f), Frame.FromHeading(new Vector3(103f, 95f, BspScene.Ground), 0f)), id: 1);
        PhysicsObj wall = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(45f, 78f), Frame.FromHeading(new Vector3(45f, 78f, BspScene.Ground), 80f)), id: 2);
        PhysicsObj stair = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(57f, 60f), Frame.FromHeading(new Vector3(57f, 60f, BspScene.Ground), 90f)),
            stepUp: 0.4f, stepDown: 0.4f, state: noEdgeSlide, id: 3);
        SweepScene.SetWalk(door, new Vector3(0f, 2f, 0f));
        SweepScene.SetWalk(wall, new Vector3(0f, 2f, 0f));
        SweepScene.SetWalk(stair, new Vector3(0f, 1f, 0f));

        // Warm up 40 ticks (the door walker is still outside, 1 m from the door; the others have not hit anything yet),
        // then measure 60 ticks in which all three hit their geometry: the doorway and room, the wall, the stairs.
        SweepScene.Run(world, 40);
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 60; i++)
        {
            world.Tick(world.CurrentTime + SweepScene.Dt);
        }

        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        Assert.Equal(0, allocated);
        Assert.Equal(RoomScene.Room, door.Position.ObjCellId);
        Assert.True(stair.Position.Frame.Origin.Z > BspScene.Ground + 0.25f, "the stair walker climbed");
    }
}
