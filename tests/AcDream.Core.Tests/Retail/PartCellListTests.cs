using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Geometry;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// The indoor half of a static object's part-based cell list (<c>CPhysicsObj::find_bbox_cell_list</c>, acclient.c:318275):
/// <c>CEnvCell::find_transit_cells(parts)</c> (348406) through an indoor cell's portals, and
/// <c>CBuildingObj::find_building_transit_cells(parts)</c> (719091) → <c>CEnvCell::check_building_transit(parts)</c> (348153)
/// through a building's door; with the box tests they use, <c>Plane::intersect_box</c> (467717) and
/// <c>BSPNODE::box_intersects_cell_bsp</c> (363424).
/// </summary>
/// <remarks>
/// The scene, built by hand with retail's portal conventions (as the real Holtburg cellar dumps have them: a portal
/// polygon's normal points into its own cell, and portal side 0 puts the other cell behind the plane): two indoor cells of
/// block 0x8080, both at the frame origin (100, 100, 20) with identity rotation. Room A (0x80800100): region x 0..6, y 0..6,
/// z -0.5..3; portal 0 a door to the outdoors in the plane y = 0 (normal +y, d 0, side 0), portal 1 into B in the plane
/// y = 6 (normal -y, d 6, side 0). Room B (0x80800101): region x 0..6, y 6..12, z -0.5..3; portal 0 back into A (normal +y,
/// d -6, side 0). A building on the outdoor cell (4, 4) (x, y 96..120) has one door, into A's portal 0. The object is the
/// low rock GfxObj of <see cref="WorldSceneEntries"/>: bounding box (-1, -1, 0)..(1, 1, 0.4), physics sphere centre
/// (0, 0, 0.2), radius sqrt(2.04) × 1.0001 + 0.001 = 1.4294 (BspBuilder's bound), so the portal tests use 1.4294 + 0.0002.
/// </remarks>
public class PartCellListTests
{
    private static readonly Vector3 Origin = new(100f, 100f, BspScene.Ground);
    private static readonly uint A = BspScene.IndoorCell(0);
    private static readonly uint B = BspScene.IndoorCell(1);
    private static readonly uint Outdoor44 = BspScene.OutdoorCell(100f, 100f);

    private static (PhysicsWorld World, WorldCells Cells) Scene(bool loadB = true)
    {
        WorldCells cells = BspScene.FlatWorld();
        var frame = new Frame(Origin, Quaternion.Identity);
        Polygon door = BspScene.Quad(new(2f, 0f, 0f), new(2f, 0f, 2.5f), new(4f, 0f, 2.5f), new(4f, 0f, 0f), 100);
        Polygon toB = BspScene.Quad(new(2f, 6f, 0f), new(4f, 6f, 0f), new(4f, 6f, 3f), new(2f, 6f, 3f), 101);
        Polygon toA = BspScene.Quad(new(2f, 6f, 0f), new(2f, 6f, 3f), new(4f, 6f, 3f), new(4f, 6f, 0f), 200);
        var roomA = new CellStruct(null, BspBuilder.BuildCell(BspBuilder.BoxCellPlanes(new(0f, 0f, -0.5f), new(6f, 6f, 3f))), [door, toB]);
        cells.AddEnvCell(new EnvCell(A, frame, roomA, [new CellPortal(CellPortal.OutsideCellId, door, 0), new CellPortal(B, toB, 0, 0)]));
        if (loadB)
        {
            var roomB = new CellStruct(null, BspBuilder.BuildCell(BspBuilder.BoxCellPlanes(new(0f, 6f, -0.5f), new(6f, 12f, 3f))), [toA]);
            cells.AddEnvCell(new EnvCell(B, frame, roomB, [new CellPortal(A, toA, 0, 1)]));
        }

        // The shell: the south wall either side of the door (x -0.2..2 and 4..6.2, y -0.2..0): on the outdoor cell (4, 4) only.
        var shell = new List<Polygon>();
        BspScene.AddBox(shell, new(-0.2f, -0.2f, 0f), new(2f, 0f, 3f));
        BspScene.AddBox(shell, new(4f, -0.2f, 0f), new(6.2f, 0f, 3f));
        BspScene.AddBuilding(cells, frame, 1f, shell, new BldPortal(A, 0));
        return (BspScene.Physics(cells), cells);
    }

    // The low rock made from its data id as a static object, put in `cell` at cell-local (x, y, 0) without a sweep.
    private static PhysicsObj Rock(PhysicsWorld world, WorldCells cells, uint cell, float x, float y) =>
        RockAt(world, cells, cell, Origin + new Vector3(x, y, 0f));

    // The low rock made from its data id as a static object, put in `cell` at landblock point `at` without a sweep.
    private static PhysicsObj RockAt(PhysicsWorld world, WorldCells cells, uint cell, Vector3 at)
    {
        var source = new DictionarySource();
        WorldSceneEntries.AddModels(source);
        PhysicsObj rock = new ObjectFactory(source).MakeObject(world, WorldSceneEntries.LowRock, isDynamic: false)!;
        rock.AddObjToCell(cells.GetVisible(cell)!, new Frame(at, Quaternion.Identity), (RetailSweep)world.Sweep!);
        return rock;
    }

    private static HashSet<uint> ShadowCells(PhysicsObj o) => o.ShadowObjects.ToArray().Select(s => s.CellId).ToHashSet();

    [Fact]
    public void AnIndoorStaticWhoseBoxCrossesAPortal_IsListedInBothCells()
    {
        // The rock at A-local (3, 5.5): box y 4.5..6.5. Portal 0 (y = 0): the sphere is 5.5 in front (> 1.4296), skipped.
        // Portal 1 (-y + 6): the sphere centre is 0.5 in front (<= 1.4296); the box's low corner (2, 4.5, 0) is 1.5 in front,
        // its high corner (4, 6.5, 0.4) 0.5 behind: crossing (3), not side 0; B is loaded and the box (B's frame is A's)
        // meets B's region (y 6..6.5 inside it): B joins. From B, its portal back into A lists A again (already there).
        (PhysicsWorld world, WorldCells cells) = Scene();
        PhysicsObj rock = Rock(world, cells, A, 3f, 5.5f);
        Assert.Equal(A, rock.CellId);
        Assert.Equal(new HashSet<uint> { A, B }, ShadowCells(rock));
        Assert.True(ObjectScene.CellLists(cells.GetVisible(B)!, rock));
    }

    [Fact]
    public void AnIndoorStaticWhoseBoxStaysInside_IsListedOnlyInItsCell_ThoughItsSphereReachesThePortal()
    {
        // The rock at A-local (3, 4.8): box y 3.8..5.8. Portal 1: the sphere centre is 1.2 in front (<= 1.4296, so the sphere
        // reaches 0.23 m past the plane), but every box corner is at least 0.2 in front: intersect_box answers 0 (positive),
        // the portal's side, and the part is skipped. (The sorting sphere that stood in before reached B's region.)
        (PhysicsWorld world, WorldCells cells) = Scene();
        PhysicsObj rock = Rock(world, cells, A, 3f, 4.8f);
        Assert.Equal(new HashSet<uint> { A }, ShadowCells(rock));
        Assert.False(ObjectScene.CellLists(cells.GetVisible(B)!, rock));
    }

    [Fact]
    public void AnIndoorStaticWhoseBoxCrossesAPortalIntoAnUnloadedCell_ListsThatCellWithoutACell()
    {
        // As the crossing case with B not loaded: the portal's cell is listed by id alone (add_cell(other_cell_id, 0)).
        (PhysicsWorld world, WorldCells cells) = Scene(loadB: false);
        PhysicsObj rock = Rock(world, cells, A, 3f, 5.5f);
        Assert.Equal(new HashSet<uint> { A, B }, ShadowCells(rock));
        Assert.Null(rock.ShadowObjects.ToArray().Single(s => s.CellId == B).Cell);
    }

    [Fact]
    public void AnIndoorStaticWhoseBoxStaysInside_DoesNotListTheUnloadedCellBehindThePortal()
    {
        // As the inside case with B not loaded: no region to test, so the box's side of the plane decides alone. The sphere
        // reaches past the plane, the box does not (intersect_box 0, the portal's side): B is not listed, not even by id.
        (PhysicsWorld world, WorldCells cells) = Scene(loadB: false);
        PhysicsObj rock = Rock(world, cells, A, 3f, 4.8f);
        Assert.Equal(new HashSet<uint> { A }, ShadowCells(rock));
    }

    [Fact]
    public void AnIndoorStaticWhoseBoxStopsShortOfTheDoor_IsNotListedOutdoors()
    {
        // The rock at A-local (3, 1.2): box y 0.2..2.2. Portal 0: the sphere centre is 1.2 in front (<= 1.4296, it reaches
        // 0.23 m outside), but every box corner is at least 0.2 in front: intersect_box 0, the portal's side; no outdoor cell.
        (PhysicsWorld world, WorldCells cells) = Scene();
        PhysicsObj rock = Rock(world, cells, A, 3f, 1.2f);
        Assert.Equal(new HashSet<uint> { A }, ShadowCells(rock));
    }

    [Fact]
    public void AnIndoorStaticWhoseBoxCrossesTheDoor_IsListedOutdoorsToo()
    {
        // The rock at A-local (3, 0.5): box y -0.5..1.5. Portal 0 (y = 0, outdoors): the sphere centre is 0.5 in front
        // (<= 1.4296), the box crosses the plane: check_outside. Portal 1: 5.5 in front, skipped. The outdoor cells the box
        // covers (x 102..104, y 99.5..101.5: cell (4, 4) only) join: add_all_outside_cells(parts).
        (PhysicsWorld world, WorldCells cells) = Scene();
        PhysicsObj rock = Rock(world, cells, A, 3f, 0.5f);
        Assert.Equal(new HashSet<uint> { A, Outdoor44 }, ShadowCells(rock));
    }

    [Fact]
    public void AnOutdoorStaticWhoseBoxReachesTheDoor_IsListedInTheCellBehindIt()
    {
        // The rock outdoors at A-local (3, -0.8) (landblock (103, 99.2), cell (4, 4)): box y -1.8..0.2. The land cell's
        // building's door leads to A's portal 0 (+y, d 0, side 0): the sphere centre is 0.8 behind, not more than 1.4296
        // behind; the box's low corner is 1.8 behind, its high corner 0.2 in front: crossing (3); the box meets A's region
        // (y 0..0.2 inside it): A joins, and A's own portals then add nothing new (the door: outdoors, already added).
        (PhysicsWorld world, WorldCells cells) = Scene();
        PhysicsObj rock = Rock(world, cells, Outdoor44, 3f, -0.8f);
        Assert.Equal(Outdoor44, rock.CellId);
        Assert.Equal(new HashSet<uint> { Outdoor44, A }, ShadowCells(rock));
        Assert.True(ObjectScene.CellLists(cells.GetVisible(A)!, rock));
    }

    [Fact]
    public void AnOutdoorStaticWhoseBoxStopsShortOfTheDoor_IsNotListedIndoors_ThoughItsSphereReachesIn()
    {
        // The rock at A-local (3, -1.3): box y -2.3..-0.3. The sphere centre is 1.3 behind the door's plane (not more than
        // 1.4296: it reaches 0.13 m into A), but every box corner is at least 0.3 behind: intersect_box answers 1
        // (negative), neither crossing nor the portal's side 0, and the part is skipped.
        (PhysicsWorld world, WorldCells cells) = Scene();
        PhysicsObj rock = Rock(world, cells, Outdoor44, 3f, -1.3f);
        Assert.Equal(new HashSet<uint> { Outdoor44 }, ShadowCells(rock));
        Assert.False(ObjectScene.CellLists(cells.GetVisible(A)!, rock));
    }

    [GeometryDataFact]
    public void RealCellarDoor_AnOutdoorStaticWhoseBoxCrossesIt_IsListedInTheDoorway_OneStoppingShortIsNot()
    {
        // The real Holtburg doorway 0x0145 (cell frame (130.5, 11.5, 94) turned 180°: world = (130.5 - x, 11.5 - y, 94 + z)):
        // region x -6.2..-5.8, y 5.4..7.3, z 0..2.5; its outdoor portal (the building's door) is the plane x = -5.8 with
        // normal -x (d -5.8) and flags 7 (side 0: the outdoors behind it, x > -5.8). The rock at world (135.5, 5.15, 94.5) is at
        // local (-5, 6.35, 0.5): sphere centre 0.8 behind the plane (not more than 1.4296); box local x -6..-4 (low corner
        // 0.2 in front, high corner 1.8 behind: crossing), y 5.35..7.35, z 0.5..0.9, meeting the region. 0x0145 joins; from
        // it, its portal to 0x0143 (x = -6.2, normal +x, side 0) sees the box wholly in front (x + 6.2 >= 0.2): skipped.
        // Outdoors the box covers world x 134.5..136.5, y 4.15..6.15: the one land cell (5, 0) of 0xA9B4.
        var s = CellarScene.Load(GeometryTestData.Dir!, TerrainTestData.Dir);
        PhysicsWorld world = BspScene.Physics(s.Cells);
        uint outdoor = Holtburg.CentreCell(135.5f, 5.15f);
        uint doorway = CellarScene.Block | 0x0145;
        PhysicsObj crossing = RockAt(world, s.Cells, outdoor, new Vector3(135.5f, 5.15f, 94.5f));
        Assert.Equal(new HashSet<uint> { outdoor, doorway }, ShadowCells(crossing));

        // At world x 135 (local x -4.5): the sphere centre is 1.3 behind (it reaches 0.13 m in), the box local x -5.5..-3.5
        // is wholly behind (every corner at least 0.3): intersect_box 1, neither crossing nor side 0: outdoors only.
        PhysicsObj shortOf = RockAt(world, s.Cells, outdoor, new Vector3(135f, 5.15f, 94.5f));
        Assert.Equal(new HashSet<uint> { outdoor }, ShadowCells(shortOf));
    }

    // The plane y = 6 (N = (0, 1, 0), d = -6).
    private static readonly CollisionPlane Y6 = new(new Vector3(0f, 1f, 0f), -6f);

    [Fact]
    public void IntersectBox_TheLowCornerDecides_AnyOtherSideIsCrossing()
    {
        Assert.Equal(Sidedness.Negative, Y6.IntersectBox(new(0f, 0f, 0f), new(1f, 1f, 1f)));
        Assert.Equal(Sidedness.Positive, Y6.IntersectBox(new(0f, 7f, 0f), new(1f, 8f, 1f)));
        Assert.Equal(Sidedness.Crossing, Y6.IntersectBox(new(0f, 5f, 0f), new(1f, 7f, 1f)));
        // The low corner in the plane (within EPSILON): crossing, though every other corner is in front.
        Assert.Equal(Sidedness.Crossing, Y6.IntersectBox(new(0f, 6f, 0f), new(1f, 7f, 1f)));
        // The high corner in the plane (6.0001 - 6 = 0.0001 <= 0.0002): in plane (2) is not negative (1): crossing.
        Assert.Equal(Sidedness.Crossing, Y6.IntersectBox(new(0f, 5f, 0f), new(1f, 6.0001f, 1f)));
    }

    [Fact]
    public void BoxIntersectsCellBsp_FalseOnlyWhenWhollyBehindOnePlaneOfTheChain()
    {
        // The region x 0..6, y 0..6, z 0..3.
        BspTree region = BspBuilder.BuildCell(BspBuilder.BoxCellPlanes(new(0f, 0f, 0f), new(6f, 6f, 3f)));
        Assert.False(region.BoxIntersectsCellBsp(new(7f, 1f, 1f), new(8f, 2f, 2f)));
        Assert.True(region.BoxIntersectsCellBsp(new(5f, 1f, 1f), new(7f, 2f, 2f)));
        Assert.True(region.BoxIntersectsCellBsp(new(1f, 1f, 1f), new(2f, 2f, 2f)));
        // 0.0001 beyond x = 6 is within EPSILON of the plane x <= 6: not behind it, so the box meets the region.
        Assert.True(region.BoxIntersectsCellBsp(new(6.0001f, 1f, 1f), new(8f, 2f, 2f)));
        // 0.001 beyond is behind it: outside.
        Assert.False(region.BoxIntersectsCellBsp(new(6.001f, 1f, 1f), new(8f, 2f, 2f)));
        // Behind the floor (z < 0) only.
        Assert.False(region.BoxIntersectsCellBsp(new(1f, 1f, -2f), new(2f, 2f, -1f)));
    }
}
