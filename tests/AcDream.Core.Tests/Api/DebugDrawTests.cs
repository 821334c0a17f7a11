using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using AcDream.Core.Physics.Debug;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// The view of what collides (<see cref="PhysicsDebugDraw"/>, issue #36 item 4) over the hand-built world of
/// <see cref="DebugDrawScene"/>: every shape the sweep tests, in the region's frame, with coordinates worked out from the
/// scene's numbers (block 0x8080 lies 0x80 · 192 = 24,576 m east and north of the world's corner).
/// </summary>
public class DebugDrawTests
{
    private const uint Block = 0x8080FFFFu;
    private const DebugDrawFlags Shapes = DebugDrawFlags.All & ~(DebugDrawFlags.ContactPlanes | DebugDrawFlags.LastSweeps);

    private static List<DrawnShape> Draw(PhysicsWorld world, DebugDrawFlags flags, DebugDrawRegion region)
    {
        var sink = new RecordingSink(new List<DrawnShape>());
        new PhysicsDebugDraw(world).Draw(ref sink, flags, region);
        return sink.Shapes;
    }

    private static Vector3 V(float x, float y, float z) => new(x, y, z);

    [Fact]
    public void TheWholeWorld_HandsEveryShape_InTheBlocksFrame()
    {
        PhysicsWorld world = DebugDrawScene.Build(out _);
        List<DrawnShape> s = Draw(world, Shapes, DebugDrawRegion.Everything(Block));

        // 64 cells: two triangles and four sides each, on the flat ground (z 20), corners on the 24 m grid.
        Assert.Equal(128, s.Count(x => x.Kind == ShapeKind.TerrainTriangle));
        Assert.Equal(256, s.Count(x => x.Kind == ShapeKind.LandCellBoundary));
        Assert.All(s.Where(x => x.Kind is ShapeKind.TerrainTriangle or ShapeKind.LandCellBoundary).SelectMany(x => x.Points),
            p => Assert.True(p.Z == 20f && p.X % 24f == 0f && p.Y % 24f == 0f && p.X is >= 0f and <= 192f && p.Y is >= 0f and <= 192f));
        Assert.Equal(
            new[] { (V(0, 0, 20), V(24, 0, 20)), (V(24, 0, 20), V(24, 24, 20)), (V(24, 24, 20), V(0, 24, 20)), (V(0, 24, 20), V(0, 0, 20)) },
            s.Where(x => x.Kind == ShapeKind.LandCellBoundary && x.Id == 0x80800001u).Select(x => (x.Points[0], x.Points[1])));

        // The building: its box 100..102 × 100..102 × 20..23, hung on cell (4, 4) = 0x80800025.
        DrawnShape[] building = s.Where(x => x.Kind == ShapeKind.BuildingPolygon).ToArray();
        Assert.Equal(6, building.Length);
        Assert.All(building, b => Assert.Equal(0x80800025u, b.Id));
        Assert.Equal(new[] { V(100, 100, 23), V(102, 100, 23), V(102, 102, 23), V(100, 102, 23) },
            building.Single(b => b.Normal == Vector3.UnitZ).Points);
        Assert.Equal(8, building.SelectMany(b => b.Points).Distinct().Count());
        Assert.All(building.SelectMany(b => b.Points), p => Assert.True(p.X is 100f or 102f && p.Y is 100f or 102f && p.Z is 20f or 23f));

        // The indoor cell at (100, 150): its floor and its portal (the west side, normal -x).
        DrawnShape floor = s.Single(x => x.Kind == ShapeKind.EnvCellPolygon);
        Assert.Equal(DebugDrawScene.Cell, floor.Id);
        Assert.Equal(new[] { V(100, 150, 20), V(104, 150, 20), V(104, 154, 20), V(100, 154, 20) }, floor.Points);
        Assert.Equal(Vector3.UnitZ, floor.Normal);
        DrawnShape portal = s.Single(x => x.Kind == ShapeKind.EnvCellPortal);
        Assert.Equal(new[] { V(100, 150, 20), V(100, 150, 24), V(100, 154, 24), V(100, 154, 20) }, portal.Points);
        Assert.Equal(-Vector3.UnitX, portal.Normal);

        // Object 1: its sphere; object 2: its cylinder sphere only (a cylinder hides the spheres, as in FindObjCollisions);
        // object 3: its BSP box -1..1 × -1..1 × 0..1 at (150, 30, 20), no sphere.
        DrawnShape sphere = s.Single(x => x.Kind == ShapeKind.ObjectSphere);
        Assert.Equal((1u, V(30, 30, 20.5f), 0.5f), (sphere.Id, sphere.Points[0], sphere.Radius));
        DrawnShape cyl = s.Single(x => x.Kind == ShapeKind.ObjectCylSphere);
        Assert.Equal((2u, V(60, 30, 20), 1f, 4f), (cyl.Id, cyl.Points[0], cyl.Radius, cyl.Height));
        DrawnShape[] rock = s.Where(x => x.Kind == ShapeKind.ObjectPolygon).ToArray();
        Assert.Equal(6, rock.Length);
        Assert.All(rock, r => Assert.Equal(3u, r.Id));
        Assert.All(rock.SelectMany(r => r.Points), p => Assert.True(p.X is 149f or 151f && p.Y is 29f or 31f && p.Z is 20f or 21f));

        Assert.Equal(128 + 256 + 6 + 1 + 1 + 1 + 1 + 6, s.Count);
    }

    [Fact]
    public void TheGlobalFrame_MovesEachShapeByItsBlocksOffset()
    {
        PhysicsWorld world = DebugDrawScene.Build(out _);
        List<DrawnShape> s = Draw(world, DebugDrawFlags.ObjectSpheres | DebugDrawFlags.EnvCellPolygons, DebugDrawRegion.Everything());
        Assert.Equal(V(24606f, 24606f, 20.5f), s.Single(x => x.Kind == ShapeKind.ObjectSphere).Points[0]);
        Assert.Equal(V(24676f, 24726f, 20f), s.Single(x => x.Kind == ShapeKind.EnvCellPolygon).Points[0]);

        // The frame of the block to the east (0x8180): the same shapes 192 m further west.
        s = Draw(world, DebugDrawFlags.ObjectSpheres, DebugDrawRegion.Everything(0x81800001u));
        Assert.Equal(V(30f - 192f, 30f, 20.5f), s.Single().Points[0]);
    }

    [Fact]
    public void ABox_HandsTheCellsItOverlaps_AndTheObjectsInIt()
    {
        PhysicsWorld world = DebugDrawScene.Build(out _);

        // 24..48 touches cells 0, 1 and 2 in x and in y (edges included): 9 cells. Only object 1 (30, 30) stands in it.
        List<DrawnShape> s = Draw(world, Shapes, DebugDrawRegion.Box(Block, new Vector2(24f, 24f), new Vector2(48f, 48f)));
        Assert.Equal(18, s.Count(x => x.Kind == ShapeKind.TerrainTriangle));
        Assert.Equal(36, s.Count(x => x.Kind == ShapeKind.LandCellBoundary));
        Assert.Equal(new uint[] { 1 }, s.Where(x => x.Kind == ShapeKind.ObjectSphere).Select(x => x.Id));
        Assert.Equal(18 + 36 + 1, s.Count);

        // A box inside the indoor cell: the cell (4, 6) under it (0x80800027) and the indoor cell, not the building of (4, 4).
        s = Draw(world, Shapes, DebugDrawRegion.Box(Block, new Vector2(101f, 151f), new Vector2(103f, 153f)));
        Assert.Equal(new uint[] { 0x80800027u, 0x80800027u }, s.Where(x => x.Kind == ShapeKind.TerrainTriangle).Select(x => x.Id));
        Assert.Single(s, x => x.Kind == ShapeKind.EnvCellPolygon);
        Assert.Single(s, x => x.Kind == ShapeKind.EnvCellPortal);
        Assert.DoesNotContain(s, x => x.Kind == ShapeKind.BuildingPolygon);
    }

    [Fact]
    public void TheFlags_SelectTheKinds()
    {
        PhysicsWorld world = DebugDrawScene.Build(out _);
        Assert.Empty(Draw(world, DebugDrawFlags.None, DebugDrawRegion.Everything(Block)));
        Assert.All(Draw(world, DebugDrawFlags.TerrainTriangles, DebugDrawRegion.Everything(Block)),
            x => Assert.Equal(ShapeKind.TerrainTriangle, x.Kind));
        Assert.Equal(new[] { ShapeKind.ObjectCylSphere, ShapeKind.ObjectPolygon },
            Draw(world, DebugDrawFlags.ObjectCylSpheres | DebugDrawFlags.ObjectPolygons, DebugDrawRegion.Everything(Block))
                .Select(x => x.Kind).Distinct().Order());
        Assert.Equal(6, Draw(world, DebugDrawFlags.BuildingPolygons, DebugDrawRegion.Everything(Block)).Count);
    }

    [Fact]
    public void TheContactPlane_IsTheGroundUnderTheObject()
    {
        PhysicsWorld world = DebugDrawScene.Build(out _);
        PhysicsObj obj = world.GetObjectById(1)!;
        Assert.True((obj.TransientState & TransientState.Contact) != 0);
        var sink = new RecordingSink(new List<DrawnShape>());
        new PhysicsDebugDraw(world).DrawObject(ref sink, obj, DebugDrawFlags.ContactPlanes, Block);
        DrawnShape plane = Assert.Single(sink.Shapes);
        Assert.Equal((ShapeKind.ContactPlane, 1u, V(30, 30, 20), Vector3.UnitZ), (plane.Kind, plane.Id, plane.Points[0], plane.Normal));
    }

    [Fact]
    public void ARemovedObject_IsNotDrawn()
    {
        PhysicsWorld world = DebugDrawScene.Build(out _);
        world.RemoveObject(world.GetObjectById(1)!);
        List<DrawnShape> s = Draw(world, DebugDrawFlags.All, DebugDrawRegion.Everything(Block));
        Assert.DoesNotContain(s, x => x.Kind is ShapeKind.ObjectSphere or ShapeKind.ContactPlane && x.Id == 1);
        Assert.Single(s, x => x.Kind == ShapeKind.ObjectCylSphere);
    }

    [Fact]
    public void TheLastSweep_IsTheUpdatesStartAndEnd()
    {
        PhysicsWorld world = DebugDrawScene.Build(out _);
        world.ObjectMaintenanceActive = false;
        PhysicsObj obj = world.GetObjectById(1)!;
        var view = new PhysicsDebugDraw(world);
        var sink = new RecordingSink(new List<DrawnShape>());

        // Placed, never updated: no motion to draw.
        view.DrawObject(ref sink, obj, DebugDrawFlags.LastSweeps, Block);
        Assert.Empty(sink.Shapes);

        ((SimplePartArray)obj.PartArray!).SequenceVelocity = new Vector3(0f, 2f, 0f);
        world.Tick(0.1);
        world.Tick(0.2);
        Assert.False(obj.IsPlacedSinceLastUpdate);
        view.DrawObject(ref sink, obj, DebugDrawFlags.LastSweeps, Block);
        Vector3 lift = new(0f, 0f, 0.5f);
        Vector3 from = obj.PreviousPose.Frame.Origin, to = obj.Position.Frame.Origin;
        Assert.True(to.Y > from.Y, $"the walker should have moved north: {from} -> {to}");
        Assert.Equal(new[] { ShapeKind.SweepStart, ShapeKind.SweepEnd, ShapeKind.SweepPath }, sink.Shapes.Select(x => x.Kind));
        Assert.Equal(from + lift, sink.Shapes[0].Points[0]);
        Assert.Equal(to + lift, sink.Shapes[1].Points[0]);
        Assert.Equal(new[] { from, to }, sink.Shapes[2].Points);
    }

    [Fact]
    public void BadInput_IsRefused()
    {
        Assert.Throws<ArgumentException>(() => DebugDrawRegion.Box(Block, new Vector2(float.NaN, 0f), new Vector2(1f, 1f)));
        Assert.Throws<ArgumentException>(() => DebugDrawRegion.Box(Block, new Vector2(2f, 0f), new Vector2(1f, 1f)));
        Assert.Throws<ArgumentException>(() => DebugDrawRegion.Everything(0xFF00FFFFu));
        Assert.Throws<ArgumentNullException>(() => new PhysicsDebugDraw(null!));

        PhysicsWorld world = DebugDrawScene.Build(out _);
        PhysicsWorld other = DebugDrawScene.Build(out _);
        var sink = new RecordingSink(new List<DrawnShape>());
        Assert.Throws<ArgumentException>(() => new PhysicsDebugDraw(world).DrawObject(ref sink, other.GetObjectById(1)!, DebugDrawFlags.All));
        Assert.Empty(sink.Shapes);
    }
}
