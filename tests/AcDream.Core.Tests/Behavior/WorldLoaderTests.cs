using System;
using System.Linq;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support;
using Xunit;
using static AcDream.Core.Tests.Support.WorldSceneEntries;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// <see cref="WorldLoader"/>, the client's door: retail's <c>CLandBlock::init_buildings</c> (acclient.c:352113: the first
/// building of a land cell wins, a building outside its block is dropped), <c>init_static_objs</c> (352786: statics outside
/// the block dropped, the restriction table onto the land cells), <c>CEnvCell::init_static_objects</c> (347954), the
/// scenery steps of <c>get_land_scenes</c> (352707–352721), missing entries and bad bytes.
/// </summary>
public class WorldLoaderTests
{
    private static (PhysicsWorld World, WorldCells Cells, WorldBlock Block) Load(DictionarySource s)
    {
        PhysicsWorld world = World(out WorldCells cells);
        WorldBlock b = new WorldLoader(world, s).Load(Block)[0];
        return (world, cells, b);
    }

    [Fact]
    public void TwoBuildingsInOneLandCell_TheFirstWins_TheSecondIsKeptWithItsCell()
    {
        // Both origins lie in cell (4, 4) (96..120 m): retail's CSortCell::add_building keeps the first.
        (_, WorldCells cells, WorldBlock b) = Load(Source([],
            [new BuildingDef(LowRock, At(100f, 100f), 0, []), new BuildingDef(TallRock, At(110f, 100f), 0, [])]));
        BuildingObj first = b.Objects[0].Building!, second = b.Objects[1].Building!;
        uint cell = BspScene.OutdoorCell(100f, 100f);
        Assert.Same(first, cells.Terrain.GetLandCell(cell)!.Building);
        Assert.Equal(cell, second.CellId);
        Assert.Equal(TallRock, b.Objects[1].DataId);
    }

    [Fact]
    public void ABuildingWhoseOriginIsOutsideTheBlock_IsDropped()
    {
        (_, WorldCells cells, WorldBlock b) = Load(Source([], [new BuildingDef(LowRock, At(-5f, 100f), 0, [])]));
        Assert.Empty(b.Objects);
        Assert.Null(cells.Terrain.GetLandCell(BspScene.OutdoorCell(0f, 100f))!.Building);
    }

    [Fact]
    public void StaticsOutsideTheBlock_AreDropped_TheOthersStandStatic_InTheCellUnderTheirOrigin()
    {
        (PhysicsWorld world, _, WorldBlock b) = Load(Source([(Pine, At(50f, 60f)), (Pine, At(200f, 60f))]));
        WorldObject o = Assert.Single(b.Objects);
        Assert.Equal(WorldObjectKind.LandBlockStatic, o.Kind);
        Assert.Equal(BspScene.OutdoorCell(50f, 60f), o.CellId);
        Assert.Equal(PhysicsState.Static, o.Object!.State & PhysicsState.Static);
        Assert.Equal(new Vector3(50f, 60f, BspScene.Ground), o.Object.Position.Frame.Origin);
        Assert.Equal(1, world.ObjectCount);
    }

    [Fact]
    public void TheRestrictionTable_IsAppliedToTheLandCells()
    {
        uint cell = BspScene.OutdoorCell(30f, 30f);
        (_, WorldCells cells, _) = Load(Source([], restrictions: [(cell, 0x7526200Cu)]));
        Assert.Equal(0x7526200Cu, cells.Terrain.GetLandCell(cell)!.RestrictionObj);
        Assert.Equal(0u, cells.Terrain.GetLandCell(BspScene.OutdoorCell(60f, 30f))!.RestrictionObj);
    }

    [Fact]
    public void BuildingsComeFirst_ThenTheStatics()
    {
        (_, _, WorldBlock b) = Load(Source([(Grass, At(50f, 60f))], [new BuildingDef(Building, At(100f, 100f), 0, [])]));
        Assert.Equal(new[] { WorldObjectKind.Building, WorldObjectKind.LandBlockStatic }, b.Objects.Select(o => o.Kind));
    }

    [Fact]
    public void AMissingSetup_FailsOnlyItsObject_AndTheBlockListsIt()
    {
        (PhysicsWorld world, _, WorldBlock b) = Load(Source([(0x02000077, At(50f, 60f)), (Pine, At(80f, 60f))]));
        Assert.Equal(new[] { 0x02000077u }, b.MissingIds);
        Assert.Equal(Pine, Assert.Single(b.Objects).DataId);
        Assert.Equal(1, world.ObjectCount);
    }

    [Fact]
    public void ABadSetup_IsAFormatError_AndNothingIsAdded()
    {
        DictionarySource s = Source([(Pine, At(80f, 60f))], [new BuildingDef(LowRock, At(100f, 100f), 0, [])]);
        s.Entries[Pine] = s.Entries[Pine].AsSpan(0, 30).ToArray();
        PhysicsWorld world = World(out WorldCells cells);
        var loader = new WorldLoader(world, s);
        Assert.Throws<RetailDataFormatException>(() => loader.Load(Block));
        Assert.Equal(0, world.ObjectCount);
        Assert.Equal(0, cells.Terrain.LandBlockCount);
        Assert.Empty(loader.LoadedBlockIds);
    }

    [Fact]
    public void ABspStatic_IsShadowed_InEveryCellItsPartBoxCovers()
    {
        // The low rock (2 m box) centred on the cell line x = 96: its box reaches cells (3, 4) and (4, 4). The pine
        // (cylinder, no BSP) at the same spot is shadowed through its cylinder's cells.
        (_, WorldCells cells, WorldBlock b) = Load(Source([(LowRock, At(96.5f, 100f))]));
        PhysicsObj rock = b.Objects[0].Object!;
        var ids = rock.ShadowObjects.ToArray().Select(s => s.CellId).ToHashSet();
        Assert.Equal(new[] { BspScene.OutdoorCell(90f, 100f), BspScene.OutdoorCell(100f, 100f) }.ToHashSet(), ids);
    }

    [Fact]
    public void AStaticReachingIntoABlockLoadedLater_IsShadowedThereOnceItLoads()
    {
        // The low rock's box (x ±1 m) at x 191.5 reaches 0.5 m into the east block 0x8180, not loaded yet: its shadow there
        // has no cell. Loading that block lists it in the block's cell (retail: init_static_objs' later call re-lists the
        // statics not completely visible with calc_cross_cells_static).
        DictionarySource s = Source([(LowRock, At(191.5f, 100f))]);
        var height = new byte[81];
        Array.Fill(height, (byte)BspScene.Ground);
        s.Entries[0x8180FFFF] = RetailEntries.LandBlock(0x8180FFFF, false, new ushort[81], height);
        PhysicsWorld world = World(out _);
        var loader = new WorldLoader(world, s);
        PhysicsObj rock = loader.Load(Block)[0].Objects[0].Object!;
        uint east = SweepScene.CellId(0x81, 0x80, 0, 4);
        Assert.Null(rock.ShadowObjects.ToArray().Single(x => x.CellId == east).Cell);
        loader.Load(0x8180FFFF);
        Assert.NotNull(rock.ShadowObjects.ToArray().Single(x => x.CellId == east).Cell);
    }

    [Fact]
    public void AnIndoorCellsStatics_StandInTheirCell()
    {
        DictionarySource s = RoomSceneEntries.Source();
        AddModels(s);
        s.Entries[RoomScene.Room] = RetailEntries.EnvCell(RoomScene.Room, 1, 1, 0, RoomScene.FrameFor(0f),
            [new PortalDef(7, 100, 0xFFFF, -1), new PortalDef(1, 101, 0x0101, 0)], visible: [0x0101],
            statics: [(Grass, RoomScene.FrameFor(0f)), (0, RoomScene.FrameFor(0f))]);
        PhysicsWorld world = World(out _);
        WorldBlock b = new WorldLoader(world, s).Load(Block)[0];
        WorldObject o = b.Objects.Single(x => x.Kind == WorldObjectKind.EnvCellStatic);
        Assert.Equal(RoomScene.Room, o.CellId);
        Assert.Equal(Grass, o.DataId);
    }

    [Fact]
    public void Scenery_OutsideTheBlockAtScale1_IsDropped_ElseScaledAfterItsShadows()
    {
        PhysicsWorld world = World(out _);
        var loader = new WorldLoader(world, Source([]));
        uint c = BspScene.OutdoorCell(100f, 100f);
        uint edge = BspScene.OutdoorCell(191f, 100f);
        loader.ScenerySource = (_, _) =>
        [
            new SceneryItem(Pine, c, At(100f, 100f), 1.5f),
            // The pine's cylinder (r 1.53) at x 191 reaches past the block's edge at 192: not within the block.
            new SceneryItem(Pine, edge, At(191f, 100f), 1f),
        ];
        WorldBlock b = loader.Load(Block)[0];
        WorldObject o = Assert.Single(b.Objects);
        Assert.Equal(WorldObjectKind.Scenery, o.Kind);
        Assert.Equal(1.5f, o.Object!.Scale);
        Assert.Equal(1, world.ObjectCount);
    }

    [Fact]
    public void Unload_TakesTheBlocksObjectsOutOfTheWorld()
    {
        PhysicsWorld world = World(out WorldCells cells);
        var loader = new WorldLoader(world, Source([(Pine, At(50f, 60f))], [new BuildingDef(LowRock, At(100f, 100f), 0, [])]));
        WorldBlock b = loader.Load(Block)[0];
        Assert.True(loader.Unload(Block));
        Assert.Equal(0, world.ObjectCount);
        Assert.True(b.Objects[1].Object!.IsRemoved);
        Assert.Equal(0, cells.Terrain.LandBlockCount);
        Assert.False(loader.Unload(Block));
    }

    [Fact]
    public void StaticObjects_AreNotVisitedByTheTick_AfterTheirFirst()
    {
        // Retail never updates a static object; here each sleeps after its first visit: with a walking player among ten
        // statics, a tick visits the player alone.
        PhysicsWorld world = World(out _);
        new WorldLoader(world, Source(
        [
            (Pine, At(20f, 20f)), (Pine, At(40f, 20f)), (LowRock, At(60f, 20f)), (TallRock, At(80f, 20f)), (Grass, At(20f, 40f)),
            (Grass, At(40f, 40f)), (Pine, At(150f, 150f)), (LowRock, At(160f, 150f)), (TallRock, At(170f, 150f)), (Grass, At(150f, 170f)),
        ])).Load(Block);
        PhysicsObj w = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(100f, 100f), At(100f, 100f)), 0.5f);
        world.Player = w;
        SweepScene.SetWalk(w, new Vector3(0f, 1f, 0f));
        SweepScene.Run(world, 5);
        Assert.Equal(11, world.ObjectCount);
        Assert.Equal(1, world.LastTickVisitCount);
    }

    [Fact]
    public void TheDoor_RefusesAWorldWithoutTheRetailSweepOverWorldCells()
    {
        Assert.Throws<ArgumentException>(() => new WorldLoader(new PhysicsWorld(), Source([])));
    }
}
