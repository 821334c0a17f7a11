using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class CellListTests
{
    // Landblock 0xA9B4: column 169, row 180. Cell (x, y) has low word x * 8 + y + 1.
    private static readonly Position InA9B4 = new(0xA9B4000Au, new Vector3(36f, 36f, 0f));

    private static uint[] Cells(in Position p, Vector3[] centers, float[] radii)
    {
        var ids = new uint[32];
        int n = LandCell.AddAllOutsideCells(p, centers, radii, ids, 0);
        return ids.AsSpan(0, n).ToArray();
    }

    [Fact]
    public void SphereInsideOneCell_ListsOnlyThatCell()
    {
        // Centre (36, 36) is the middle of cell (1, 1): offset in cell (12, 12), well within r = 1 of no edge.
        Assert.Equal(new[] { 0xA9B4000Au }, Cells(InA9B4, [new(36f, 36f, 0f)], [1f]));
    }

    [Fact]
    public void SphereNearNorthEastCorner_AddsEastDiagonalAndNorthInRetailOrder()
    {
        // Centre (47.5, 47.5): offset (23.5, 23.5) in cell (1, 1); incell_max = 24 - 1 = 23, incell_min = 1.
        // x > max: (2,1) = 0x12, then y > max: (2,2) = 0x13; finally y > max: (1,2) = 0x0B.
        Assert.Equal(new[] { 0xA9B4000Au, 0xA9B40012u, 0xA9B40013u, 0xA9B4000Bu }, Cells(InA9B4, [new(47.5f, 47.5f, 0f)], [1f]));
    }

    [Fact]
    public void SphereAtEasternBlockEdge_AddsCellOfNeighbourBlock()
    {
        // Centre (191.5, 36): cell (7, 1) = 0x3A; offset x = 191.5 - 168 = 23.5 > 23 -> global column 169*8 + 8 = 1360,
        // i.e. block 0xAA, cell (0, 1) = 0x02.
        Assert.Equal(new[] { 0xA9B4003Au, 0xAAB40002u }, Cells(InA9B4, [new(191.5f, 36f, 0f)], [1f]));
    }

    [Fact]
    public void CentreOutsideBlock_IsRehomedWithAdjustToOutside()
    {
        // x = 200 is 8 m into block 0xAA: cell (0, 1) of 0xAAB4.
        Assert.Equal(new[] { 0xAAB40002u }, Cells(InA9B4, [new(200f, 36f, 0f)], [1f]));
        // y = -30: one block south (0xB3), y = 162 -> cell row 6; x = 36 -> column 1: low 1*8 + 6 + 1 = 15 = 0x0F.
        Assert.Equal(new[] { 0xA9B3000Fu }, Cells(InA9B4, [new(36f, -30f, 0f)], [1f]));
    }

    [Fact]
    public void LargeRadius_ReachesAllEightNeighbours()
    {
        // r = 13 > 12: offset (12, 12) is both > 24 - 13 = 11 and < 13 on each axis.
        // Order: (x+1,y) (x+1,y+1) (x+1,y-1) (x-1,y) (x-1,y+1) (x-1,y-1) (x,y+1) (x,y-1) around cell (1, 1).
        uint[] expected =
        [
            0xA9B4000Au,
            0xA9B40012u, 0xA9B40013u, 0xA9B40011u,
            0xA9B40002u, 0xA9B40003u, 0xA9B40001u,
            0xA9B4000Bu, 0xA9B40009u,
        ];
        Assert.Equal(expected, Cells(InA9B4, [new(36f, 36f, 0f)], [13f]));
    }

    [Fact]
    public void WorldEdge_NeighboursPastTheEdgeAreSkipped()
    {
        // Block 0x0000, cell (0, 1): offset x = 0.5 < r = 1 would add column -1, which is outside the world.
        var p = new Position(0x00000002u, new Vector3(0.5f, 36f, 0f));
        Assert.Equal(new[] { 0x00000002u }, Cells(p, [new(0.5f, 36f, 0f)], [1f]));
    }

    [Fact]
    public void CentrePastWorldEdge_FailsAndStopsTheSphereLoop()
    {
        var p = new Position(0x00000002u, new Vector3(0.5f, 36f, 0f));
        var ids = new uint[16];
        int count = 0;
        Assert.False(LandCell.AddOutsideCellsForSphere(p.ObjCellId, new Vector3(-30f, 36f, 0f), 1f, ids, ref count));
        Assert.Equal(0, count);

        // Retail breaks out of the loop at the first failing sphere: the valid second sphere adds nothing.
        Assert.Empty(Cells(p, [new(-30f, 36f, 0f), new(36f, 36f, 0f)], [1f, 1f]));
        // In the other order the first sphere's cells are kept.
        Assert.Equal(new[] { 0x0000000Au }, Cells(p, [new(36f, 36f, 0f), new(-30f, 36f, 0f)], [1f, 1f]));
    }

    [Fact]
    public void TwoSpheresInOneCell_ListItOnce()
    {
        Assert.Equal(new[] { 0xA9B4000Au }, Cells(InA9B4, [new(36f, 36f, 0f), new(36f, 36f, 1.2f)], [1f, 1f]));
    }

    [Fact]
    public void NoSpheres_ListsTheOriginsCell()
    {
        Assert.Equal(new[] { 0xA9B4000Au }, Cells(InA9B4, [], []));
    }

    [Fact]
    public void BadInput_ThrowsAndWritesNothing()
    {
        var ids = new uint[12];
        Assert.Throws<ArgumentException>(() => LandCell.AddAllOutsideCells(InA9B4, [new(36f, 36f, 0f), new(1f, 1f, 0f)], [1f, 1f], ids, 0));
        Assert.Throws<ArgumentException>(() => LandCell.AddAllOutsideCells(InA9B4, [new(float.NaN, 36f, 0f)], [1f], ids, 0));
        Assert.Throws<ArgumentException>(() => LandCell.AddAllOutsideCells(InA9B4, [new(36f, 36f, 0f)], [-1f], ids, 0));
        Assert.Throws<ArgumentException>(() => LandCell.AddAllOutsideCells(InA9B4, [new(36f, 36f, 0f)], [1f, 2f], ids, 0));
        Assert.All(ids, id => Assert.Equal(0u, id));
    }

    [Fact]
    public void FindCellList_CurrentCellIsTheLastContainingCell()
    {
        var world = new TerrainWorld(TerrainTestData.IdentityTable());
        world.AddLandBlock(0xA9B4FFFFu, new byte[81], TerrainTestData.Terrain(1));
        world.AddLandBlock(0xAAB4FFFFu, new byte[81], TerrainTestData.Terrain(1));
        var p = new Position(0xA9B4003Au, new Vector3(191.5f, 36f, 0f));
        var ids = new uint[18];

        // Centre 0.5 m west of the block edge: the list has both cells, the centre is only over 0xA9B4003A.
        int n = world.FindCellList(p, [new(191.5f, 36f, 0.5f)], [1f], ids, out LandCell? current);
        Assert.Equal(new[] { 0xA9B4003Au, 0xAAB40002u }, ids.AsSpan(0, n).ToArray());
        Assert.Equal(0xA9B4003Au, current!.Id);

        // Centre exactly on the edge (x = 192): re-homed to 0xAAB40002 first, then the west neighbour; the point lies on
        // both cells' shared edge (edges count as inside), so the last in the list wins.
        n = world.FindCellList(p, [new(192f, 36f, 0.5f)], [1f], ids, out current);
        Assert.Equal(new[] { 0xAAB40002u, 0xA9B4003Au }, ids.AsSpan(0, n).ToArray());
        Assert.Equal(0xA9B4003Au, current!.Id);
    }

    [Fact]
    public void FindCellList_IndoorPositionListsItself_UnloadedBlockHasNoCurrentCell()
    {
        var world = new TerrainWorld(TerrainTestData.IdentityTable());
        var ids = new uint[18];
        int n = world.FindCellList(new Position(0xA9B40105u, new Vector3(1f, 1f, 1f)), [new(1f, 1f, 1f)], [1f], ids, out LandCell? current);
        Assert.Equal(1, n);
        Assert.Equal(0xA9B40105u, ids[0]);
        Assert.Null(current);

        n = world.FindCellList(InA9B4, [new(36f, 36f, 0f)], [1f], ids, out current);
        Assert.Equal(1, n);
        Assert.Null(current);
    }
}

public class CellListManySpheresTests
{
    [Fact]
    public void MoreThanTwoSpheres_EveryCentreAddsItsCell()
    {
        // An object's cylinder spheres reach the outdoor cell search (CPhysicsObj::calc_cross_cells → find_cell_list →
        // CLandCell::add_all_outside_cells, acclient.c:355345, which loops over every sphere). Three r 1 spheres in the
        // middles of cells (1, 1), (2, 1), (3, 1) of 0xA9B4 (low words 1*8+1+1 = 0x0A, 0x12, 0x1A): all three are listed,
        // in sphere order. (The port listed only the first two before.)
        var cells = new WorldCells(new TerrainWorld(TerrainTestData.IdentityTable()));
        var ca = new AcDream.Core.Physics.Collision.CellArray();
        var p = new Position(0xA9B4000Au, new Vector3(36f, 36f, 0f));
        CellList.AddAllOutsideCells(cells, p,
            [new(new Vector3(36f, 36f, 0f), 1f), new(new Vector3(60f, 36f, 0f), 1f), new(new Vector3(84f, 36f, 0f), 1f)], ca);
        Assert.Equal(3, ca.NumCells);
        Assert.Equal(new[] { 0xA9B4000Au, 0xA9B40012u, 0xA9B4001Au }, new[] { ca.Cells[0].CellId, ca.Cells[1].CellId, ca.Cells[2].CellId });
    }
}
