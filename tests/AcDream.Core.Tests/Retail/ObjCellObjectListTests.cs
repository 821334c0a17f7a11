using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// Retail <c>CObjCell</c>'s object list and voyeur table (acclient.c:347258–347764), pinned from the decompiled code. Flat
/// terrain in landblock 0x8080; outdoor cell (cx, cy) covers x in [24 cx, 24 cx + 24), y likewise. Objects are walkers of
/// radius 0.5 standing on the ground.
/// </summary>
public class ObjCellObjectListTests
{
    private static (PhysicsWorld world, TerrainWorld terrain) Flat()
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 0);
        PhysicsWorld world = SweepScene.Physics(terrain, out RetailSweep _);
        return (world, terrain);
    }

    private static uint Cell(int cx, int cy) => SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, cx, cy);

    private static Position At(float x, float y) => new(Cell((int)(x / 24f), (int)(y / 24f)), new Vector3(x, y, 0f));

    private static PhysicsObj Obj(PhysicsWorld world, uint id, float x, float y) => SweepScene.Walker(world, At(x, y), id: id);

    private static DetectionManager Voyeur(PhysicsObj o)
    {
        var dm = new DetectionManager(o, new DetectionRecorder());
        o.DetectionManager = dm;
        dm.InitializeGlobalDetectionObjects();
        return dm;
    }

    [Fact]
    public void EnterCell_Appends_LeaveCell_SwapRemoves()
    {
        // add_object (347702) appends; remove_object (347764) moves the last object into the hole: A, B, C less A is C, B.
        var (world, terrain) = Flat();
        PhysicsObj a = Obj(world, 10, 12f, 12f);
        PhysicsObj b = Obj(world, 11, 14f, 12f);
        PhysicsObj c = Obj(world, 12, 16f, 12f);
        ObjCell cell00 = terrain.GetVisible(Cell(0, 0))!;
        Assert.Equal(new[] { a, b, c }, cell00.ObjectList.ToArray());
        Assert.Same(cell00, a.Cell);

        a.GoToLostCell(a.Position);
        Assert.Equal(new[] { c, b }, cell00.ObjectList.ToArray());
        Assert.Null(a.Cell);
        Assert.Null(cell00.GetObject(10));
        Assert.Same(b, cell00.GetObject(11));

        // b moves to cell (1, 0): it leaves the first list and enters the second.
        Assert.Equal(SetPositionError.Ok, b.SetPosition(At(36f, 12f), SetPositionFlags.Placement));
        Assert.Equal(new[] { c }, cell00.ObjectList.ToArray());
        Assert.Equal(new[] { b }, terrain.GetVisible(Cell(1, 0))!.ObjectList.ToArray());

        // An object removed from the world leaves its cell's list.
        world.RemoveObject(c);
        Assert.Equal(0, cell00.NumObjects);
    }

    [Fact]
    public void AddVoyeur_ReportsObjectsAlreadyThere_HiddenIncluded_ReferenceCounted()
    {
        // add_voyeur (347422): a new voyeur (ref 1) is sent EnteredDetection for every object already in the cell with an id
        // and no parent, itself excepted, hidden or not; a voyeur already there only gets ref + 1. remove_voyeur (347501):
        // ref - 1; at 0 it leaves and is sent LeftDetection for every such object.
        var (world, terrain) = Flat();
        PhysicsObj d = Obj(world, 1, 12f, 12f);
        PhysicsObj a = Obj(world, 10, 14f, 12f);
        PhysicsObj h = Obj(world, 11, 16f, 12f);
        h.SetState(h.State | PhysicsState.Hidden);
        DetectionManager dm = Voyeur(d);
        ObjCell cell = terrain.GetVisible(Cell(0, 0))!;

        Assert.True(cell.AddVoyeur(d));
        Assert.Equal(1, cell.VoyeurRefCount(1));
        Assert.Equal(DetectionStatus.Entered, dm.GlobalDetectionStatus(10));
        Assert.Equal(DetectionStatus.Entered, dm.GlobalDetectionStatus(11));
        Assert.Null(dm.GlobalDetectionStatus(1));
        Assert.Equal(2u, dm.NumPendingGlobalDetectUpdates);

        Assert.True(cell.AddVoyeur(d));                 // overlap: ref 2, no report
        Assert.Equal(2, cell.VoyeurRefCount(1));
        Assert.Equal(2u, dm.NumPendingGlobalDetectUpdates);

        Assert.True(cell.RemoveVoyeur(d));              // ref 1: still watching, no report
        Assert.Equal(1, cell.VoyeurRefCount(1));
        Assert.Equal(2u, dm.NumPendingGlobalDetectUpdates);

        Assert.True(cell.RemoveVoyeur(d));              // ref 0: LeftDetection for both (entered then left: dropped)
        Assert.Equal(0, cell.NumVoyeurs);
        Assert.Null(dm.GlobalDetectionStatus(10));
        Assert.Null(dm.GlobalDetectionStatus(11));
        Assert.Equal(0u, dm.NumPendingGlobalDetectUpdates);
        Assert.False(cell.RemoveVoyeur(d));
    }

    [Fact]
    public void ObjectsEnteringAndLeaving_AreReportedToVoyeurs_HiddenOnlyOnLeaving()
    {
        // add_object skips a hidden object (0x4000); remove_object -> update_all_voyeur(LeftDetection) does not (the hidden
        // test is for EnteredDetection only). The voyeur moving itself is never reported to itself.
        var (world, terrain) = Flat();
        PhysicsObj d = Obj(world, 1, 12f, 12f);
        DetectionManager dm = Voyeur(d);
        ObjCell cell = terrain.GetVisible(Cell(0, 0))!;
        Assert.True(cell.AddVoyeur(d));
        Assert.Equal(0u, dm.NumPendingGlobalDetectUpdates);

        PhysicsObj e = Obj(world, 20, 6f, 6f);
        Assert.Equal(DetectionStatus.Entered, dm.GlobalDetectionStatus(20));
        Assert.Equal(1u, dm.NumPendingGlobalDetectUpdates);

        PhysicsObj h = world.CreateObject(21);
        h.PartArray = new AcDream.Core.Physics.Objects.Parts.SimplePartArray(1, 1) { Radius = 0.5f };
        h.SetState(h.State | PhysicsState.Hidden);
        Assert.True(h.EnterWorld(At(18f, 18f)));
        Assert.Same(cell, h.Cell);
        Assert.Null(dm.GlobalDetectionStatus(21));      // hidden: not reported entering

        h.GoToLostCell(h.Position);
        Assert.Equal(DetectionStatus.Left, dm.GlobalDetectionStatus(21));   // reported leaving
        Assert.Equal(2u, dm.NumPendingGlobalDetectUpdates);

        e.GoToLostCell(e.Position);                     // entered then left: dropped
        Assert.Null(dm.GlobalDetectionStatus(20));
        Assert.Equal(1u, dm.NumPendingGlobalDetectUpdates);

        d.GoToLostCell(d.Position);                     // the voyeur itself: no report
        Assert.Null(dm.GlobalDetectionStatus(1));
        Assert.Equal(1u, dm.NumPendingGlobalDetectUpdates);
    }

    [Fact]
    public void HideAndUnhide_TellTheVoyeurs()
    {
        // hide_object (347616) = update_all_voyeur(LeftDetection); unhide_object (347622) sends EnteredDetection unless the
        // object is (still) hidden.
        var (world, terrain) = Flat();
        PhysicsObj d = Obj(world, 1, 12f, 12f);
        PhysicsObj a = Obj(world, 10, 14f, 12f);
        DetectionManager dm = Voyeur(d);
        ObjCell cell = terrain.GetVisible(Cell(0, 0))!;
        cell.AddVoyeur(d);
        cell.HideObject(a);                             // entered then left: dropped
        Assert.Null(dm.GlobalDetectionStatus(10));
        cell.UnhideObject(a);                           // shown: entered again
        Assert.Equal(DetectionStatus.Entered, dm.GlobalDetectionStatus(10));
        // set_state (322171) -> set_hidden (322077) calls them itself when HIDDEN changes.
        a.SetState(a.State | PhysicsState.Hidden);      // hide_object: entered then left, dropped
        Assert.Null(dm.GlobalDetectionStatus(10));
        cell.UnhideObject(a);                           // still hidden: nothing
        Assert.Null(dm.GlobalDetectionStatus(10));
        a.SetState(a.State & ~PhysicsState.Hidden);     // unhide_object
        Assert.Equal(DetectionStatus.Entered, dm.GlobalDetectionStatus(10));
    }
}
