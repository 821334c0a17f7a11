using System;
using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// The obstacle summary each cell keeps per listed shadow (<see cref="ObstacleSummary"/>: origin, cell id, reach or kind)
/// stays equal to a fresh computation from its object across every change of an input: scale, spheres, part array, state,
/// parent, a walk across cells, a teleport; and the check the test suite runs with (<see cref="ObstacleSummary.Verify"/>)
/// throws on a stale one.
/// </summary>
public class ObstacleSummaryTests
{
    // One sphere of radius 0.5 on the origin: centre (0, 0, 0.5), so ObstacleReach = 0 + 0 + 0.5 + 0.5 = 1.
    private static readonly Sphere[] Ball = { new(new Vector3(0f, 0f, 0.5f), 0.5f) };

    [Fact]
    public void ScaleChange_ScalesTheReachInEveryCell()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep _);
        PhysicsObj rock = ObjectScene.Obstacle(world, 1, ObjectScene.At(100f, 100f), Ball);
        AssertSummaries(rock, 1f);

        rock.SetScaleStatic(2f);
        AssertSummaries(rock, 2f);
        rock.SetScaleStatic(0.25f);
        AssertSummaries(rock, 0.25f);
    }

    [Fact]
    public void SpheresAndPartArrayChange_FollowTheNewShapes()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep _);
        PhysicsObj rock = ObjectScene.Obstacle(world, 1, ObjectScene.At(100f, 100f), Ball);
        var parts = (SimplePartArray)rock.PartArray!;

        // (0.3, -0.4, 1.5) r 0.5 reaches 0.3 + 0.4 + 1.5 + 0.5 = 2.7, stored as the float 2.7f; at scale 1 the reach is that
        // float.
        parts.SetSpheres(new[] { new Sphere(new Vector3(0.3f, -0.4f, 1.5f), 0.5f) });
        AssertSummaries(rock, 2.7f);

        // Cylinder spheres: the object is always tested in full.
        parts.SetCylSpheres(new[] { new CylSphere(Vector3.Zero, 0.5f, 1.8f) });
        AssertSummaries(rock, ObstacleSummary.TestFully);

        // A new part array with its one dummy sphere (centre (0, 0, 0.1), r 0.1: 0.2f), at scale 3: 3 × 0.2f =
        // 0.60000000894069671630859375 in double, between the floats 0.599999964... and 0.60000002384185791015625 (0.6f), and
        // nearer the latter, which is above it: 0.6f.
        Assert.Equal(0.2f, (float)((double)PhysicsGlobals.DummySphereRadius + PhysicsGlobals.DummySphereRadius));
        rock.SetScaleStatic(3f);
        rock.PartArray = new SimplePartArray(1, 1);
        AssertSummaries(rock, 0.6f);

        // No part array: tested in full (as FindObjCollisions finds nothing to test).
        rock.PartArray = null;
        AssertSummaries(rock, ObstacleSummary.TestFully);
    }

    [Fact]
    public void PhysicsBspState_MakesTheObjectTestedInFull()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep _);
        PhysicsObj rock = ObjectScene.Obstacle(world, 1, ObjectScene.At(100f, 100f), Ball);
        PhysicsState state = rock.State;

        rock.SetState(state | PhysicsState.HasPhysicsBsp);
        AssertSummaries(rock, ObstacleSummary.TestFully);
        rock.SetState(state);
        AssertSummaries(rock, 1f);
    }

    [Fact]
    public void Parenting_MarksTheChildUntilItIsDetached()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep _);
        PhysicsObj carrier = ObjectScene.Creature(world, 1, ObjectScene.At(50f, 50f));
        PhysicsObj bag = ObjectScene.Obstacle(world, 2, ObjectScene.At(60f, 50f), Ball);
        Assert.True(bag.NumShadowObjects > 0);

        Assert.True(bag.SetParent(carrier, 0, Frame.FromHeading(new Vector3(0f, 0.5f, 1f), 0f)));
        AssertSummaries(bag, ObstacleSummary.Parented);

        // Carried along as the carrier walks (its frame is set through the carrier's): still marked, origin followed.
        SweepScene.SetWalk(carrier, new Vector3(0f, 2f, 0f));
        SweepScene.Run(world, 10, _ => AssertSummaries(bag, ObstacleSummary.Parented));
        Assert.True(carrier.Position.Frame.Origin.Y > 50.5f);

        bag.UnsetParent();
        AssertSummaries(bag, 1f);
    }

    [Fact]
    public void WalkAcrossCells_TheSummaryFollowsTheOriginAndCellEveryTick()
    {
        // A walker 1 m west of the cell edge x = 24 walking east at 4 m/s: it crosses into the next cell and is listed
        // in both while it overlaps the edge.
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep _);
        PhysicsObj walker = ObjectScene.Creature(world, 1, ObjectScene.At(23f, 30f, ObjectScene.GroundZ, 90f));
        SweepScene.SetWalk(walker, new Vector3(0f, 4f, 0f));
        uint startCell = walker.Position.ObjCellId;
        SweepScene.Run(world, 20, _ => AssertSummaries(walker, 1f));
        Assert.NotEqual(startCell, walker.Position.ObjCellId);
        Assert.Equal(ObjectScene.Cell(27f, 30f), walker.Position.ObjCellId);
    }

    [Fact]
    public void Teleports_TheSummaryFollowsTheNewPosition()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep _, twoBlocks: true);
        PhysicsObj walker = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f));

        // StorePosition moves the object without re-listing its shadows: the summaries where it was listed follow it.
        walker.StorePosition(ObjectScene.At(101.5f, 99f));
        AssertSummaries(walker, 1f);
        Assert.Equal(101.5f, walker.Position.Frame.Origin.X);

        // A placement in the next landblock (0x8180): new cells, new landblock id in the summaries.
        var east = new Position(SweepScene.CellId(SweepScene.BlockX + 1, SweepScene.BlockY, 1, 1),
            Frame.FromHeading(new Vector3(30f, 30f, ObjectScene.GroundZ), 0f));
        Assert.Equal(SetPositionError.Ok, walker.SetPositionSimple(east, true));
        Assert.Equal(0x8180u, walker.Position.ObjCellId >> 16);
        AssertSummaries(walker, 1f);
    }

    [Fact]
    public void StaleSummary_IsCaughtByTheCheck()
    {
        Assert.True(ObstacleSummary.Verify, "the test assembly runs with the obstacle-summary check on");
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep _);
        // A static rock (never stepped, so nothing rewrites its summary) and a walker heading for it.
        PhysicsObj rock = ObjectScene.Obstacle(world, 1, ObjectScene.At(100f, 100f), Ball, extra: PhysicsState.Static);
        PhysicsObj walker = ObjectScene.Creature(world, 2, ObjectScene.At(100f, 96f));
        SweepScene.SetWalk(walker, new Vector3(0f, 1f, 0f));

        // Write a summary that marks the rock as attached (never tested): a sweep through its cell must notice.
        ShadowObj shadow = rock.ShadowObjects[0];
        ObstacleSummary stale = rock.ComputeObstacleSummary();
        stale.Reach = ObstacleSummary.Parented;
        shadow.Cell!.SetObstacleSummary(shadow, stale);
        InvalidOperationException e = Assert.Throws<InvalidOperationException>(() => SweepScene.Run(world, 5));
        Assert.StartsWith("Stale obstacle summary of object 0x00000001", e.Message, StringComparison.Ordinal);
    }

    // The object's summary as it stands now has its origin, cell id and the expected reach (or mark), and every cell listing
    // one of its shadows stores it at the shadow's index.
    private static void AssertSummaries(PhysicsObj obj, float expectedReach)
    {
        ObstacleSummary fresh = obj.ComputeObstacleSummary();
        Assert.Equal(BitConverter.SingleToInt32Bits(expectedReach), BitConverter.SingleToInt32Bits(fresh.Reach));
        Assert.Equal(obj.Position.ObjCellId, fresh.CellId);
        Assert.Equal(obj.Position.Frame.Origin, new Vector3(fresh.X, fresh.Y, fresh.Z));
        int listed = 0;
        foreach (ShadowObj s in obj.ShadowObjects)
        {
            ObjCell? cell = s.Cell;
            if (cell is null)
            {
                continue;
            }

            listed++;
            Assert.Same(s, cell.ShadowObjects[s.Slot]);
            Assert.True(cell.HoldsObstacleSummary(s.Slot, fresh), $"cell 0x{cell.Id:X8} does not hold {fresh}");
        }

        Assert.True(listed > 0, "the object is listed in at least one cell");
    }
}
