using System.Collections.Generic;
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

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// Global detection (a detection cylinder with object id 0; retail <c>DetectionManager::UpdateCellList</c> 327327,
/// <c>InitializeGlobalDetection</c> 327193, <c>FindCellList</c> 327153): the detector is a voyeur of the outdoor cells a
/// sphere of the cylinder's radius around it reaches, and each check (once a physics second) reports the objects that
/// entered or left them. Flat terrain in landblock 0x8080; cell (cx, cy) covers [24 cx, 24 cx + 24). With radius 5 a centre
/// adds the neighbour across an edge closer than 5 m (<c>add_all_outside_cells</c>). Ticks of 0.05 s; checks at t ≈ 1, 2, 3.
/// </summary>
public class GlobalDetectionTests
{
    private const uint Context = 7;

    private static uint Cell(int cx, int cy) => SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, cx, cy);

    private static Position At(float x, float y) => new(Cell((int)(x / 24f), (int)(y / 24f)), new Vector3(x, y, 0f));

    private static (PhysicsWorld world, TerrainWorld terrain, PhysicsObj d, DetectionRecorder rec) Scene(float dx, float dy)
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 0);
        PhysicsWorld world = SweepScene.Physics(terrain, out RetailSweep _);
        PhysicsObj d = SweepScene.Walker(world, At(dx, dy), id: 1);
        var rec = new DetectionRecorder();
        var dm = new DetectionManager(d, rec);
        d.DetectionManager = dm;
        return (world, terrain, d, rec);
    }

    private static HashSet<(uint, DetectionStatus)> Reports(DetectionRecorder rec, int from)
    {
        var set = new HashSet<(uint, DetectionStatus)>();
        for (int i = from; i < rec.Count; i++)
        {
            Assert.Equal(Context, rec.Context(i));
            set.Add((rec.Info(i).ObjectId, rec.Info(i).Status));
        }

        return set;
    }

    [Fact]
    public void DetectorCrossingCells_ReportsObjectsOfTheCellsItReachesAndLeaves()
    {
        // Detector at (12, 12): radius 5 reaches cell (0, 0) only (12 m from every edge). A at (16, 12) in (0, 0), B at
        // (36, 12) in (1, 0), C at (84, 12) in (3, 0).
        var (world, terrain, d, rec) = Scene(12f, 12f);
        SweepScene.Walker(world, At(16f, 12f), id: 10);
        SweepScene.Walker(world, At(36f, 12f), id: 11);
        SweepScene.Walker(world, At(84f, 12f), id: 12);
        ((DetectionManager)d.DetectionManager!).CreateDetectionCylsphere(Context, 0, 5f);

        SweepScene.Run(world, 25);                      // first check, t = 1
        Assert.Equal(new HashSet<(uint, DetectionStatus)> { (10, DetectionStatus.Entered) }, Reports(rec, 0));
        Assert.Equal(1, terrain.GetVisible(Cell(0, 0))!.VoyeurRefCount(1));
        Assert.Equal(new uint[] { Cell(0, 0) }, ((DetectionManager)d.DetectionManager!).GlobalDetectionCellIds);

        // To (30, 12), 18 m on: cell (1, 0) alone (6 m from its west edge). A's cell is left, B's entered.
        int n = rec.Count;
        Assert.Equal(SetPositionError.Ok, d.SetPosition(At(30f, 12f), SetPositionFlags.Placement));
        SweepScene.Run(world, 20);                      // t = 2
        Assert.Equal(new HashSet<(uint, DetectionStatus)> { (10, DetectionStatus.Left), (11, DetectionStatus.Entered) }, Reports(rec, n));
        Assert.Equal(0, terrain.GetVisible(Cell(0, 0))!.NumVoyeurs);
        Assert.Equal(1, terrain.GetVisible(Cell(1, 0))!.VoyeurRefCount(1));

        // An object walking into a watched cell between checks is reported at the next: C to (40, 12).
        n = rec.Count;
        SetPositionError moved = world.GetObjectById(12)!.SetPosition(At(40f, 12f), SetPositionFlags.Placement);
        Assert.Equal(SetPositionError.Ok, moved);
        SweepScene.Run(world, 20);                      // t = 3 (the detector did not move: same cell list)
        Assert.Equal(new HashSet<(uint, DetectionStatus)> { (12, DetectionStatus.Entered) }, Reports(rec, n));
    }

    [Fact]
    public void OverlappingCellLists_KeepOneReference_AndReportNothing()
    {
        // At (20, 12) (4 m from the east edge): cells (0, 0) and (1, 0). Moving to (28, 12) (8 m; 4 m past the edge) reaches
        // the same two cells: add_voyeur on the new list (ref 2), remove_voyeur on the old (ref 1); no report.
        var (world, terrain, d, rec) = Scene(20f, 12f);
        SweepScene.Walker(world, At(10f, 12f), id: 10);
        SweepScene.Walker(world, At(40f, 12f), id: 11);
        var dm = (DetectionManager)d.DetectionManager!;
        dm.CreateDetectionCylsphere(Context, 0, 5f);
        SweepScene.Run(world, 25);
        Assert.Equal(new HashSet<(uint, DetectionStatus)> { (10, DetectionStatus.Entered), (11, DetectionStatus.Entered) }, Reports(rec, 0));

        int n = rec.Count;
        Assert.Equal(SetPositionError.Ok, d.SetPosition(At(28f, 12f), SetPositionFlags.Placement));
        SweepScene.Run(world, 20);
        Assert.Equal(n, rec.Count);
        Assert.Equal(new uint[] { Cell(1, 0), Cell(0, 0) }, dm.GlobalDetectionCellIds);
        Assert.Equal(1, terrain.GetVisible(Cell(0, 0))!.VoyeurRefCount(1));
        Assert.Equal(1, terrain.GetVisible(Cell(1, 0))!.VoyeurRefCount(1));

        // Destroying the cylinder (CleanupGlobalDetection 327456) takes the detector out of both cells, with no report.
        Assert.True(dm.DestroyDetectionCylsphere(Context));
        SweepScene.Run(world, 20);
        Assert.Equal(n, rec.Count);
        Assert.Equal(0, terrain.GetVisible(Cell(0, 0))!.NumVoyeurs);
        Assert.Equal(0, terrain.GetVisible(Cell(1, 0))!.NumVoyeurs);
        Assert.Empty(dm.GlobalDetectionCellIds);
    }
}
