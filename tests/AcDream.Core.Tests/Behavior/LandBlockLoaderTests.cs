using System;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// A client loads a landblock with a building and its two indoor cells from retail entries (<see cref="RoomSceneEntries"/>,
/// the <see cref="RoomScene"/> as bytes) through <see cref="LandBlockLoader"/>, and a walker walks in through the door,
/// on into the corridor and back out — the walks of <see cref="IndoorTests"/>, through the unpacked cells and shell.
/// </summary>
public class LandBlockLoaderTests
{
    private const float R = 0.5f;

    private static (WorldCells Cells, LandBlockContent Content) Load()
    {
        var cells = new WorldCells(SweepScene.Terrain());
        LandBlockContent c = LandBlockLoader.Load(cells, 0x80800100, RoomSceneEntries.Source());
        return (cells, c);
    }

    private static PhysicsObj WalkerAt(PhysicsWorld world, Vector3 p) =>
        SweepScene.Walker(world, new Position(BspScene.OutdoorCell(p.X, p.Y), Frame.FromHeading(p, 0f)), R);

    [Fact]
    public void TheLandBlock_ItsCells_AndItsBuilding_AreInTheWorld()
    {
        (WorldCells cells, LandBlockContent c) = Load();
        Assert.Equal(1, cells.Terrain.LandBlockCount);
        Assert.Equal(2, cells.EnvCellCount);
        Assert.Equal(BspScene.Ground, c.LandBlock.Vertices[40].Z);
        Assert.NotNull(cells.GetEnvCell(RoomScene.Room));
        Assert.Single(c.Buildings);
        // The building stands on the land cell under its origin (100, 100): cell (4, 4) of the block.
        Assert.Same(c.Buildings[0], cells.Terrain.GetLandCell(BspScene.OutdoorCell(100f, 100f))!.Building);
        Assert.Equal(RoomScene.Room, c.Buildings[0].Portals[0].OtherCellId);
    }

    [Fact]
    public void AWalker_WalksInThroughTheDoor_AndBackOut()
    {
        (WorldCells cells, _) = Load();
        PhysicsWorld world = BspScene.Physics(cells);
        // As IndoorTests: 5 m south of the door, 2 m/s north for 70 ticks (7 m: local y 2, in the room), then back.
        PhysicsObj obj = WalkerAt(world, RoomScene.Origin + new Vector3(3f, -5f, 0f));
        uint outdoor = BspScene.OutdoorCell(103f, 95f);
        SweepScene.SetWalk(obj, new Vector3(0f, 2f, 0f));
        SweepScene.Run(world, 70, _ => Assert.Equal(BspScene.Ground, obj.Position.Frame.Origin.Z, 3));
        Assert.Equal(RoomScene.Room, obj.Position.ObjCellId);
        Assert.Equal(102f, obj.Position.Frame.Origin.Y, 2);
        SweepScene.SetWalk(obj, new Vector3(0f, -2f, 0f));
        SweepScene.Run(world, 70, _ => Assert.Equal(BspScene.Ground, obj.Position.Frame.Origin.Z, 3));
        Assert.Equal(outdoor, obj.Position.ObjCellId);
        Assert.Equal(95f, obj.Position.Frame.Origin.Y, 2);
    }

    [Fact]
    public void AWalker_ReachesTheCorridor_StopsAtItsEndWall_AndWalksBackOut()
    {
        (WorldCells cells, _) = Load();
        PhysicsWorld world = BspScene.Physics(cells);
        PhysicsObj obj = WalkerAt(world, RoomScene.Origin + new Vector3(3f, -4f, 0f));
        SweepScene.SetWalk(obj, new Vector3(0f, 2f, 0f));
        SweepScene.Run(world, 130);
        Assert.Equal(RoomScene.Corridor, obj.Position.ObjCellId);
        SweepScene.Run(world, 40, _ => Assert.True(obj.Position.Frame.Origin.Y <= 112f - R + 0.001f));
        SweepScene.SetWalk(obj, new Vector3(0f, -2f, 0f));
        bool sawRoom = false;
        SweepScene.Run(world, 180, _ => sawRoom |= obj.Position.ObjCellId == RoomScene.Room);
        Assert.True(sawRoom);
        Assert.False(LandDefs.IsEnvCell(obj.Position.ObjCellId));
    }

    [Fact]
    public void ABadCellEntry_AddsNothing_AndNamesTheStructure()
    {
        var cells = new WorldCells(SweepScene.Terrain());
        DictionarySource s = RoomSceneEntries.Source();
        s.Entries[RoomScene.Corridor] = s.Entries[RoomScene.Corridor].AsSpan(0, 30).ToArray();
        var e = Assert.Throws<RetailDataFormatException>(() => LandBlockLoader.Load(cells, 0x8080FFFF, s));
        Assert.Equal("CEnvCell", e.Structure);
        Assert.Equal(0, cells.Terrain.LandBlockCount);
        Assert.Equal(0, cells.EnvCellCount);
    }

    [Fact]
    public void AMissingEntry_IsAnArgumentException_AndAddsNothing()
    {
        var cells = new WorldCells(SweepScene.Terrain());
        DictionarySource s = RoomSceneEntries.Source();
        s.Entries.Remove(RoomSceneEntries.Env);
        var e = Assert.Throws<ArgumentException>(() => LandBlockLoader.Load(cells, 0x8080FFFF, s));
        Assert.Contains("0x0D000001", e.Message);
        Assert.Equal(0, cells.Terrain.LandBlockCount);
    }

    [Fact]
    public void AnEntryHoldingAnotherId_IsAFormatError_AndAddsNothing()
    {
        // The corridor's bytes served for the room's id: the cell id inside (offset 8) is not the one asked for.
        var cells = new WorldCells(SweepScene.Terrain());
        DictionarySource s = RoomSceneEntries.Source();
        s.Entries[RoomScene.Room] = s.Entries[RoomScene.Corridor];
        var e = Assert.Throws<RetailDataFormatException>(() => LandBlockLoader.Load(cells, 0x8080FFFF, s));
        Assert.Equal("CEnvCell", e.Structure);
        Assert.Equal(8, e.Offset);
        Assert.Equal(0, cells.EnvCellCount);
    }

    [Fact]
    public void TwoShellsInOneLandCell_TheFirstWins_AndAShellOutsideTheBlockIsDropped()
    {
        // Retail CSortCell::add_building keeps the first (the loader used to keep the last), and init_buildings drops a
        // building whose origin is outside the block (the loader used to clamp it onto edge cell (0, 4)).
        var cells = new WorldCells(SweepScene.Terrain());
        DictionarySource s = WorldSceneEntries.Source([],
        [
            new BuildingDef(WorldSceneEntries.LowRock, WorldSceneEntries.At(100f, 100f), 0, []),
            new BuildingDef(WorldSceneEntries.TallRock, WorldSceneEntries.At(110f, 100f), 0, []),
            new BuildingDef(WorldSceneEntries.LowRock, WorldSceneEntries.At(-5f, 100f), 0, []),
        ]);
        LandBlockContent c = LandBlockLoader.Load(cells, WorldSceneEntries.Block, s);
        Assert.Equal(2, c.Buildings.Count);
        Assert.Same(c.Buildings[0], cells.Terrain.GetLandCell(BspScene.OutdoorCell(100f, 100f))!.Building);
        Assert.Null(cells.Terrain.GetLandCell(BspScene.OutdoorCell(0f, 100f))!.Building);
    }

    [Fact]
    public void TheEnvironmentIsReadOnce_ForBothCells()
    {
        DictionarySource s = RoomSceneEntries.Source();
        LandBlockLoader.Load(new WorldCells(SweepScene.Terrain()), 0x8080FFFF, s);
        // Block, info, two cells, one environment, one shell.
        Assert.Equal(6, s.Reads);
    }
}
