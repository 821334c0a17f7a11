using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// <see cref="PhysicsObj.HandleReceivedPosition"/> says what it did. A report into a landblock that is not loaded sends the
/// creature out of the world as retail does (the lost cell), and the result says so (<see cref="ReceivedPositionResult.LeftWorld"/>)
/// instead of reporting success; a later report into a loaded cell places it again.
/// </summary>
public class ReceivedPositionResultTests
{
    // Only landblock 0x8080 is loaded; 0x8180 (east of it) is not.
    private static readonly Position InUnloadedBlock =
        new(SweepScene.CellId(SweepScene.BlockX + 1, SweepScene.BlockY, 0, 4), Frame.FromHeading(new Vector3(2f, 100f, 20f), 0f));

    private static PhysicsWorld Flat(out TerrainWorld terrain)
    {
        terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20); // flat, z = 20
        return new PhysicsWorld(0.0) { Sweep = new RetailSweep(terrain) };
    }

    [Fact]
    public void Teleport_IntoAnUnloadedLandblock_LeftWorld_ThenBackIntoALoadedOne_Placed()
    {
        PhysicsWorld world = Flat(out TerrainWorld terrain);
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f));
        ObjCell cell = terrain.GetVisible(ObjectScene.Cell(100f, 100f))!;

        // Teleport stamp 1 is newer than 0: the teleport branch places it (SetPosition with TELEPORT | SLIDE).
        Assert.Equal(ReceivedPositionResult.LeftWorld, c.HandleReceivedPosition(InUnloadedBlock, 1, 1, true));

        Assert.Equal(0u, c.CellId);
        Assert.Equal(0, c.NumShadowObjects);
        Assert.False(ObjectScene.CellLists(cell, c));
        world.Tick(0.05);

        // An object with no cell is placed by any newer report (MoveOrTeleport's cell == 0 branch).
        Position back = ObjectScene.At(130f, 100f);
        Assert.Equal(ReceivedPositionResult.Placed, c.HandleReceivedPosition(back, 2, 1, true));
        Assert.Equal(back.ObjCellId, c.CellId);
        Assert.Equal(new Vector3(130f, 100f, 20f), c.Position.Frame.Origin);
    }

    [Fact]
    public void FarSnap_IntoAnUnloadedLandblock_LeftWorld()
    {
        PhysicsWorld world = Flat(out _);
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f));
        // No player: the player distance stays float.MaxValue (>= 96 m), so a report in contact snaps (SetPositionSimple).
        Assert.Equal(ReceivedPositionResult.Placed, c.HandleReceivedPosition(ObjectScene.At(101f, 100f), 1, 0, true));
        Assert.Equal(ReceivedPositionResult.LeftWorld, c.HandleReceivedPosition(InUnloadedBlock, 2, 0, true));
        Assert.Equal(0u, c.CellId);
    }

    [Fact]
    public void NearReport_IntoAnUnloadedLandblock_SaysItsCellIsNotLoaded()
    {
        PhysicsWorld world = Flat(out _);
        PhysicsObj player = ObjectScene.Creature(world, 1, ObjectScene.At(185f, 100f));
        PhysicsObj c = ObjectScene.Creature(world, 2, ObjectScene.At(190f, 100f));
        world.Player = player;
        world.Tick(0.05); // measures the player distance: 5 m

        Assert.Equal(ReceivedPositionResult.Interpolating, c.HandleReceivedPosition(ObjectScene.At(191f, 100f), 1, 0, true));
        Assert.Equal(ReceivedPositionResult.InterpolatingToUnloadedCell, c.HandleReceivedPosition(InUnloadedBlock, 2, 0, true));
        Assert.NotEqual(0u, c.CellId); // still in the world for now
    }

    [Fact]
    public void UnusedReports_SayWhy()
    {
        PhysicsWorld world = Flat(out _);
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f));
        Assert.Equal(ReceivedPositionResult.Placed, c.HandleReceivedPosition(ObjectScene.At(101f, 100f), 5, 2, true));
        Assert.Equal(ReceivedPositionResult.Stale, c.HandleReceivedPosition(ObjectScene.At(102f, 100f), 5, 2, true));
        Assert.Equal(ReceivedPositionResult.StaleTeleport, c.HandleReceivedPosition(ObjectScene.At(102f, 100f), 6, 1, true));
        Assert.Equal(ReceivedPositionResult.NoContact, c.HandleReceivedPosition(ObjectScene.At(102f, 100f), 7, 2, false));
        Assert.Equal(new Vector3(101f, 100f, 20f), c.Position.Frame.Origin);
    }
}
