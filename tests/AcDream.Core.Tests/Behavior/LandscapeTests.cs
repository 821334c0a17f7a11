using System.Collections.Generic;
using System.Linq;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support;
using Xunit;
using static AcDream.Core.Tests.Support.LandscapeEntries;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// The landscape following the player (retail <c>CellManager::ChangePosition</c> 146645, <c>LScape::update_loadpoint</c>
/// 308282, <c>update_block</c> 307785, <c>grab_visible_cells</c> 306570): the grid's four shift directions and full reloads,
/// the 3 × 3 of full detail, demotion destroying statics, objects going to their lost cells and coming back.
/// </summary>
public class LandscapeTests
{
    // The 3 × 3 around block (x, y).
    private static HashSet<uint> Around(int x, int y)
    {
        var ids = new HashSet<uint>();
        for (int i = -1; i <= 1; i++)
        {
            for (int j = -1; j <= 1; j++)
            {
                ids.Add(BlockId(x + i, y + j));
            }
        }

        return ids;
    }

    // The grid's invariants after a change centred on block (x, y): each slot holds the block at its offset with retail's
    // size, the full-detail set is the 3 × 3, and the world holds exactly their terrain and one pine each.
    private static void AssertCentredOn(Landscape l, PhysicsWorld world, WorldCells cells, int x, int y)
    {
        int r = l.MidRadius;
        for (int ix = 0; ix < l.MidWidth; ix++)
        {
            for (int iy = 0; iy < l.MidWidth; iy++)
            {
                LandscapeBlock b = l.GetBlock(ix, iy)!;
                Assert.Equal(BlockId(x - r + ix, y - r + iy), b.BlockId);
                Assert.Equal((ix, iy), (b.GridX, b.GridY));
                int ring = System.Math.Max(System.Math.Abs(ix - r), System.Math.Abs(iy - r));
                Assert.Equal(ring <= 1 ? 1 : ring == 2 ? 2 : ring <= 4 ? 4 : 8, b.Size);
                Assert.Equal(ring <= 1, b.World is not null);
            }
        }

        HashSet<uint> full = Around(x, y);
        Assert.Equal(full, l.Blocks.Where(b => b.IsFullDetail).Select(b => b.BlockId).ToHashSet());
        Assert.Equal(9, cells.Terrain.LandBlockCount);
        foreach (uint id in full)
        {
            Assert.NotNull(cells.Terrain.GetLandBlock(id));
        }

        Assert.Equal(9, world.ObjectCount - world.LostObjectCount - CountNonStatic(world));
    }

    private static int CountNonStatic(PhysicsWorld world) => Objects(world).Count(o => (o.State & PhysicsState.Static) == 0);

    // The world's objects, in its order (removed objects are not among them).
    private static IEnumerable<PhysicsObj> Objects(PhysicsWorld world)
    {
        for (int i = 0; i < world.ObjectCount; i++)
        {
            yield return world.GetObject(i);
        }
    }

    [Fact]
    public void TheFirstChange_BuildsTheGrid_AndTheThreeByThreeAtFullDetail()
    {
        Landscape l = Landscape(Source(), out PhysicsWorld world, out WorldCells cells);
        LandscapeChange c = l.ChangePosition(At(0x80, 0x80, 100f, 100f));
        Assert.Equal(LandscapeStatus.Updated, c.Status);
        Assert.Equal(49, c.Entered.Count);
        Assert.Empty(c.Left);
        Assert.Equal(9, c.Built.Count);
        AssertCentredOn(l, world, cells, 0x80, 0x80);
        Assert.Equal(Cell(0x80, 0x80, 100f, 100f), l.LoadedCellId);
        Assert.Equal(Cell(0x80, 0x80, 100f, 100f), l.CurrentCellId);
        // The pine of each full block stands at its spot.
        PhysicsObj pine = c.Built[0].Objects.Single().Object!;
        Assert.Equal(PineAt, pine.Position.Frame.Origin);
    }

    [Fact]
    public void TheSameCell_DoesNothing_AnotherCellOfTheBlock_MovesTheLoadPointOnly()
    {
        Landscape l = Landscape(Source(), out PhysicsWorld world, out WorldCells cells);
        l.ChangePosition(At(0x80, 0x80, 100f, 100f));
        Assert.Equal(LandscapeStatus.SameCell, l.ChangePosition(At(0x80, 0x80, 101f, 100f)).Status);
        LandscapeChange c = l.ChangePosition(At(0x80, 0x80, 130f, 100f));
        Assert.Equal(LandscapeStatus.Updated, c.Status);
        Assert.Empty(c.Entered);
        Assert.Empty(c.Built);
        Assert.Equal(Cell(0x80, 0x80, 130f, 100f), l.LoadedCellId);
        AssertCentredOn(l, world, cells, 0x80, 0x80);
    }

    [Theory]
    [InlineData(1, 0)]
    [InlineData(-1, 0)]
    [InlineData(0, 1)]
    [InlineData(0, -1)]
    [InlineData(1, 1)]
    [InlineData(-1, -1)]
    [InlineData(1, -1)]
    [InlineData(-1, 1)]
    public void AShift_KeepsTheBlocksStillInTheGrid_ReadsTheNewEdge_AndReleasesTheOldOne(int dx, int dy)
    {
        DictionarySource s = Source();
        Landscape l = Landscape(s, out PhysicsWorld world, out WorldCells cells);
        l.ChangePosition(At(0x80, 0x80, 100f, 100f));
        LandscapeBlock kept = l.GetBlock(3 + dx, 3 + dy)!;
        int reads = s.Reads;
        LandscapeChange c = l.ChangePosition(At(0x80 + dx, 0x80 + dy, 100f, 100f));
        AssertCentredOn(l, world, cells, 0x80 + dx, 0x80 + dy);
        // The block that was one step away is now the centre: the same object, moved.
        Assert.Same(kept, l.GetBlock(3, 3));
        // A shift along one axis enters a row of 7; along both, 7 + 7 - 1 = 13.
        int edge = dx != 0 && dy != 0 ? 13 : 7;
        Assert.Equal(edge, c.Entered.Count);
        Assert.Equal(edge, c.Left.Count);
        Assert.All(c.Left, id => Assert.DoesNotContain(id, l.Blocks.Select(b => b.BlockId)));
        // Three (or five) blocks reach full detail and as many leave it.
        int n = dx != 0 && dy != 0 ? 5 : 3;
        Assert.Equal(n, c.Built.Count);
        Assert.Equal(n, c.Released.Count);
        Assert.True(s.Reads - reads > 0);
    }

    [Fact]
    public void AShiftOfTheWholeGrid_IsAFullReload()
    {
        Landscape l = Landscape(Source(), out PhysicsWorld world, out WorldCells cells, radius: 1);
        l.ChangePosition(At(0x80, 0x80, 100f, 100f));
        LandscapeBlock old = l.GetBlock(1, 1)!;
        // Radius 1: mid_width 3, so a shift of 3 blocks is the full reload (update_block's shift >= mid_width).
        LandscapeChange c = l.ChangePosition(At(0x83, 0x80, 100f, 100f));
        Assert.Equal(9, c.Entered.Count);
        Assert.Equal(9, c.Left.Count);
        Assert.Equal(9, c.Released.Count);
        Assert.NotSame(old, l.GetBlock(1, 1));
        AssertCentredOn(l, world, cells, 0x83, 0x80);
    }

    [Fact]
    public void ATeleport_IsAFullReload_EvenOneBlockAway()
    {
        Landscape l = Landscape(Source(), out PhysicsWorld world, out WorldCells cells);
        l.ChangePosition(At(0x80, 0x80, 100f, 100f));
        LandscapeBlock centre = l.GetBlock(3, 3)!;
        LandscapeChange c = l.ChangePosition(At(0x81, 0x80, 100f, 100f), blocking: true);
        Assert.Equal(49, c.Entered.Count);
        Assert.Equal(9, c.Released.Count);
        Assert.Equal(9, c.Built.Count);
        Assert.NotSame(centre, l.GetBlock(2, 3));
        AssertCentredOn(l, world, cells, 0x81, 0x80);
    }

    [Fact]
    public void ADemotedBlock_LosesItsStatics_AndGetsThemAgainWhenItReturns()
    {
        Landscape l = Landscape(Source(), out PhysicsWorld world, out _);
        l.ChangePosition(At(0x80, 0x80, 100f, 100f));
        PhysicsObj pine = l.GetLandBlock(BlockId(0x7F, 0x80))!.World!.Objects.Single().Object!;
        l.ChangePosition(At(0x81, 0x80, 100f, 100f));
        LandscapeBlock west = l.GetBlock(1, 3)!;
        Assert.Equal(BlockId(0x7F, 0x80), west.BlockId);
        Assert.Equal(2, west.Size);
        Assert.Null(west.World);
        Assert.True(pine.IsRemoved);
        l.ChangePosition(At(0x80, 0x80, 100f, 100f));
        PhysicsObj again = l.GetLandBlock(BlockId(0x7F, 0x80))!.World!.Objects.Single().Object!;
        Assert.NotSame(pine, again);
        Assert.Equal(PineAt, again.Position.Frame.Origin);
        Assert.Equal(9, Objects(world).Count());
    }

    [Fact]
    public void AnObjectInABlockThatLeavesFullDetail_GoesToItsLostCell_AndComesBackWithTheBlock()
    {
        Landscape l = Landscape(Source(), out PhysicsWorld world, out _);
        l.ChangePosition(At(0x80, 0x80, 100f, 100f));
        PhysicsObj walker = SweepScene.Walker(world, At(0x7F, 0x80, 118f, 130f), id: 7);
        uint cell = walker.CellId;
        Assert.Equal(Cell(0x7F, 0x80, 118f, 130f), cell);
        System.Numerics.Vector3 at = walker.Position.Frame.Origin;

        l.ChangePosition(At(0x81, 0x80, 100f, 100f));
        Assert.Equal(0u, walker.CellId);
        Assert.Equal(1, world.LostObjectCount);
        Assert.Equal(cell, walker.Position.ObjCellId);

        l.ChangePosition(At(0x80, 0x80, 100f, 100f));
        Assert.Equal(cell, walker.CellId);
        Assert.Equal(at, walker.Position.Frame.Origin);
        Assert.Equal(0, world.LostObjectCount);
    }

    [Fact]
    public void WhileALandscapeOwnsTheLoader_LoadAndUnloadAreRefused()
    {
        Landscape l = Landscape(Source(), out _, out _);
        Assert.Throws<System.InvalidOperationException>(() => l.Loader.Load(BlockId(0x80, 0x80)));
        Assert.Throws<System.InvalidOperationException>(() => l.Loader.Unload(BlockId(0x80, 0x80)));
        Assert.Throws<System.ArgumentException>(() => new Landscape(l.Loader));
    }

    [Fact]
    public void ReleaseAll_EmptiesTheWorld_AndTheNextChangeBuildsAgain()
    {
        Landscape l = Landscape(Source(), out PhysicsWorld world, out WorldCells cells);
        l.ChangePosition(At(0x80, 0x80, 100f, 100f));
        l.ReleaseAll();
        Assert.False(l.HasGrid);
        Assert.Equal(0, cells.Terrain.LandBlockCount);
        Assert.Empty(Objects(world));
        Assert.True(l.SetMidRadius(2));
        l.ChangePosition(At(0x80, 0x80, 100f, 100f));
        Assert.Equal(25, l.Blocks.Count());
        Assert.Equal(9, cells.Terrain.LandBlockCount);
    }
}
