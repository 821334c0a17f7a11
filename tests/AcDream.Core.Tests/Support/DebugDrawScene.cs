using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Debug;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;

namespace AcDream.Core.Tests.Support;

/// <summary>One shape handed to a sink, its points in the call's frame (a polygon's vertices copied).</summary>
internal sealed record DrawnShape(string Call, ShapeKind Kind, uint Id, Vector3[] Points, float Radius = 0f, float Height = 0f,
    Vector3 Normal = default);

/// <summary>A sink that records every shape (tests only: it allocates).</summary>
internal struct RecordingSink(List<DrawnShape> shapes) : IDebugDrawSink
{
    public readonly List<DrawnShape> Shapes = shapes;

    public void Sphere(in Vector3 center, float radius, ShapeKind kind, uint id) =>
        Shapes.Add(new DrawnShape("Sphere", kind, id, [center], radius));

    public void Cylinder(in Vector3 lowPoint, float radius, float height, ShapeKind kind, uint id) =>
        Shapes.Add(new DrawnShape("Cylinder", kind, id, [lowPoint], radius, height));

    public void Polygon(ReadOnlySpan<Vector3> vertices, in Vector3 normal, ShapeKind kind, uint id) =>
        Shapes.Add(new DrawnShape("Polygon", kind, id, vertices.ToArray(), Normal: normal));

    public void Triangle(in Vector3 a, in Vector3 b, in Vector3 c, ShapeKind kind, uint id) =>
        Shapes.Add(new DrawnShape("Triangle", kind, id, [a, b, c]));

    public void Segment(in Vector3 a, in Vector3 b, ShapeKind kind, uint id) => Shapes.Add(new DrawnShape("Segment", kind, id, [a, b]));

    public void Plane(in Vector3 point, in Vector3 normal, ShapeKind kind, uint id) =>
        Shapes.Add(new DrawnShape("Plane", kind, id, [point], Normal: normal));
}

/// <summary>A sink that counts the calls and sums the coordinates (allocates nothing).</summary>
internal struct CountingSink : IDebugDrawSink
{
    public int Calls;
    public double Sum;

    public void Sphere(in Vector3 center, float radius, ShapeKind kind, uint id) { Calls++; Sum += center.X + radius; }

    public void Cylinder(in Vector3 lowPoint, float radius, float height, ShapeKind kind, uint id) { Calls++; Sum += lowPoint.X + height; }

    public void Polygon(ReadOnlySpan<Vector3> vertices, in Vector3 normal, ShapeKind kind, uint id) { Calls++; Sum += vertices[0].X; }

    public void Triangle(in Vector3 a, in Vector3 b, in Vector3 c, ShapeKind kind, uint id) { Calls++; Sum += a.X; }

    public void Segment(in Vector3 a, in Vector3 b, ShapeKind kind, uint id) { Calls++; Sum += b.X; }

    public void Plane(in Vector3 point, in Vector3 normal, ShapeKind kind, uint id) { Calls++; Sum += point.Z; }
}

/// <summary>
/// The hand-built world of the debug-view tests: the flat landblock 0x8080 at z 20 (<see cref="BspScene.FlatWorld"/>), a
/// building at (100, 100) whose shell is the box 0..2 × 0..2 × 0..3 (six quads), an indoor cell 0x80800100 at (100, 150) with
/// one floor quad 0..4 × 0..4 and one portal (the quad's west side, 0..4 high), object 1 with one sphere (r 0.5, centre
/// (0, 0, 0.5)) at (30, 30), object 2 with a sphere and a cylinder sphere (low point (0, 0, 0), r 1, h 4) at (60, 30), and
/// object 3, static with a physics BSP part (the box −1..1 × −1..1 × 0..1) at (150, 30).
/// </summary>
internal static class DebugDrawScene
{
    public const uint Cell = 0x80800100u;

    public static PhysicsWorld Build(out WorldCells cells)
    {
        cells = BspScene.FlatWorld();
        PhysicsWorld world = BspScene.Physics(cells);
        BspScene.AddBoxes(cells, new Vector3(100f, 100f, BspScene.Ground), (Vector3.Zero, new Vector3(2f, 2f, 3f)));

        Polygon floor = BspScene.Quad(new(0f, 0f, 0f), new(4f, 0f, 0f), new(4f, 4f, 0f), new(0f, 4f, 0f));
        Polygon portal = BspScene.Quad(new(0f, 0f, 0f), new(0f, 0f, 4f), new(0f, 4f, 4f), new(0f, 4f, 0f), 100);
        var structure = new CellStruct(BspBuilder.Build([floor]),
            BspBuilder.BuildCell(BspBuilder.BoxCellPlanes(new(0f, 0f, -0.5f), new(4f, 4f, 4f))), [portal]);
        cells.AddEnvCell(new EnvCell(Cell, new Frame(new Vector3(100f, 150f, BspScene.Ground), Quaternion.Identity), structure,
            [new CellPortal(CellPortal.OutsideCellId, portal, 0)]));

        Walkers.Create(world, 1, At(30f, 30f), Walkers.OneSphere(0.5f));

        SimplePartArray cyl = Walkers.OneSphere(0.5f);
        cyl.SetCylSpheres([new CylSphere(Vector3.Zero, 1f, 4f)]);
        Walkers.Create(world, 2, At(60f, 30f), cyl);

        var rock = new SimplePartArray(1, 0);
        var box = new List<Polygon>();
        BspScene.AddBox(box, new Vector3(-1f, -1f, 0f), new Vector3(1f, 1f, 1f));
        rock.SetPhysicsParts([new GfxObjPhysics(BspBuilder.Build(box.ToArray()))], [Frame.Identity], [Vector3.One]);
        PhysicsObj r = world.CreateObject(3);
        r.PartArray = rock;
        r.SetState(PhysicsState.Static | PhysicsState.HasPhysicsBsp);
        if (!r.EnterWorld(At(150f, 30f)))
        {
            throw new InvalidOperationException("The rock could not enter the world.");
        }

        return world;
    }

    /// <summary>A position on the ground at block-local (x, y) of block 0x8080.</summary>
    public static Position At(float x, float y) =>
        new(BspScene.OutdoorCell(x, y), new Frame(new Vector3(x, y, BspScene.Ground), Quaternion.Identity));
}
