using System.Linq;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// Indoor cells and the landscape (retail <c>CellManager::ChangePosition</c>, acclient.c:146645, lines 146695–146757): a
/// cell that does not see outside releases the landscape and holds its dungeon's cells alone (146704), unless
/// <c>keep_lscape_loaded</c>; a cell that sees outside keeps the landscape around the outdoor cell under it (146754). The
/// scene is <see cref="RoomSceneEntries"/>: the room (flag 1, seen outside) and its corridor (flag 0).
/// </summary>
public class LandscapeDungeonTests
{
    private static readonly Position InRoom = new(RoomScene.Room, new Frame(new Vector3(103f, 103f, BspScene.Ground), Quaternion.Identity));
    private static readonly Position InCorridor = new(RoomScene.Corridor, new Frame(new Vector3(103f, 109f, BspScene.Ground), Quaternion.Identity));

    private static Landscape Make(out PhysicsWorld world, out WorldCells cells) =>
        LandscapeEntries.Landscape(RoomSceneEntries.Source(), out world, out cells, radius: 1);

    private static uint[] Visible(Landscape l) => l.VisibleCells.Select(c => c.CellId).ToArray();

    [Fact]
    public void ACellThatSeesOutside_KeepsTheLandscape_AroundTheOutdoorCellUnderIt()
    {
        Landscape l = Make(out _, out WorldCells cells);
        LandscapeChange c = l.ChangePosition(InRoom);
        Assert.Equal(LandscapeStatus.Updated, c.Status);
        Assert.True(l.HasGrid);
        // get_outside_cell_id: block-local (103, 103) is cell x 4, y 4 -> 4 * 8 + 4 + 1 = 0x25.
        Assert.Equal(0x80800025u, l.LoadedCellId);
        Assert.Equal(RoomScene.Room, l.CurrentCellId);
        Assert.Equal(1, cells.Terrain.LandBlockCount);
        // The room and its visible list (the corridor), then the block's stab list (the door sees both): no repeats.
        Assert.Equal(new[] { RoomScene.Room, RoomScene.Corridor }, Visible(l));
        Assert.Equal(new[] { RoomScene.Room, RoomScene.Corridor }, c.CellsEntered);
        Assert.NotNull(cells.GetEnvCell(RoomScene.Corridor));
    }

    [Fact]
    public void Outdoors_TheVisibleCells_AreTheBuildingsStabLists()
    {
        Landscape l = Make(out _, out WorldCells cells);
        LandscapeChange c = l.ChangePosition(new Position(0x80800001u, new Frame(new Vector3(10f, 10f, BspScene.Ground), Quaternion.Identity)));
        // The door (RoomSceneEntries: stab list 0x0100, 0x0101) sees both cells: retail's LScape::grab_visible_cells' first pass.
        Assert.Equal(new[] { RoomScene.Room, RoomScene.Corridor }, c.CellsEntered);
        Assert.Equal(2, cells.EnvCellCount);
    }

    [Fact]
    public void ADungeonCell_ReleasesTheLandscape_AndHoldsItsVisibleCells()
    {
        Landscape l = Make(out _, out WorldCells cells);
        l.ChangePosition(InRoom);
        LandscapeChange c = l.ChangePosition(InCorridor);
        Assert.False(l.HasGrid);
        Assert.Equal(0u, l.LoadedCellId);
        Assert.Equal(0, cells.Terrain.LandBlockCount);
        // The corridor and the room it sees stay visible (not reloaded, not released).
        Assert.Equal(new[] { RoomScene.Room, RoomScene.Corridor }, Visible(l));
        Assert.Empty(c.CellsEntered);
        Assert.Empty(c.CellsReleased);
        Assert.Equal(2, cells.EnvCellCount);
        Assert.Equal(RoomScene.Corridor, l.CurrentCellId);
        Assert.Equal(new[] { 0x8080FFFFu }, c.Released);
        Assert.Empty(c.Built);

        // Back into the room: the landscape comes back.
        LandscapeChange back = l.ChangePosition(InRoom);
        Assert.True(l.HasGrid);
        Assert.Equal(1, cells.Terrain.LandBlockCount);
        Assert.Single(back.Built);
        Assert.Empty(back.Released);
    }

    [Fact]
    public void KeepLandscapeLoaded_KeepsTheGrid_InADungeonCell()
    {
        Landscape l = Make(out _, out WorldCells cells);
        l.KeepLandscapeLoaded = true;
        l.ChangePosition(InRoom);
        l.ChangePosition(InCorridor);
        Assert.True(l.HasGrid);
        Assert.Equal(1, cells.Terrain.LandBlockCount);
        Assert.Equal(RoomScene.Corridor, l.CurrentCellId);
        Assert.Equal(new[] { RoomScene.Room, RoomScene.Corridor }, Visible(l));
    }

    [Fact]
    public void AnObjectInTheCorridor_StaysWhenTheDungeonIsHeldAlone()
    {
        Landscape l = Make(out PhysicsWorld world, out _);
        l.ChangePosition(InRoom);
        PhysicsObj o = SweepScene.Walker(world, InCorridor, radius: 0.4f, id: 5);
        Assert.Equal(RoomScene.Corridor, o.CellId);
        Vector3 at = o.Position.Frame.Origin;
        l.ChangePosition(InCorridor);
        Assert.Equal(RoomScene.Corridor, o.CellId);
        Assert.Equal(at, o.Position.Frame.Origin);
        Assert.Equal(0, world.LostObjectCount);
    }

    [Fact]
    public void ADungeonCellOfABlockNotInTheSource_IsNoCell_AndNothingChanges()
    {
        Landscape l = Make(out _, out WorldCells cells);
        l.ChangePosition(InRoom);
        // The info holds two cells: 0x0102 is not one of them.
        Position missing = new(0x80800102u, InCorridor.Frame);
        Assert.Equal(LandscapeStatus.NoCell, l.ChangePosition(missing).Status);
        Assert.Equal(RoomScene.Room, l.CurrentCellId);
        Assert.Equal(1, cells.Terrain.LandBlockCount);
        Assert.Equal(LandscapeStatus.NoCell, l.ChangePosition(new Position(0x30300100u, InCorridor.Frame)).Status);
        Assert.Equal(RoomScene.Room, l.CurrentCellId);
    }
}
