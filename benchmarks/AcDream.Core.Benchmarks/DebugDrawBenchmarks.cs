using System;
using System.Numerics;
using AcDream.Core.Physics.Debug;
using AcDream.Core.Physics.World;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// The view of what collides (<see cref="PhysicsDebugDraw"/>, issue #36 item 4) over the synthetic 3 × 3 of
/// <see cref="WorldBench"/> with its 3,600 statics and scenery objects, into a struct sink that only counts: every shape of the
/// loaded world, and the shapes of a 48 m box around the centre block's middle. Both must read 0 B.
/// </summary>
[MemoryDiagnoser]
public class DebugDrawBenchmarks
{
    private PhysicsDebugDraw _view = null!;
    private DebugDrawRegion _all, _box;

    [GlobalSetup]
    public void Setup()
    {
        PhysicsWorld world = WorldBench.World();
        WorldBench.Loader(world, WorldBench.Entries(populated: true), scenery: true).Load(WorldBench.Blocks);
        _view = new PhysicsDebugDraw(world);
        _all = DebugDrawRegion.Everything(0x8080FFFFu);
        _box = DebugDrawRegion.Box(0x8080FFFFu, new Vector2(72f, 72f), new Vector2(120f, 120f));
    }

    /// <summary>Every shape of the nine blocks (terrain, cell sides, objects).</summary>
    [Benchmark]
    public int WholeWorld()
    {
        var sink = new Counter();
        _view.Draw(ref sink, DebugDrawFlags.All, _all);
        return sink.Calls;
    }

    /// <summary>The shapes of a 48 m box (four land cells and the objects standing in it).</summary>
    [Benchmark]
    public int Box48m()
    {
        var sink = new Counter();
        _view.Draw(ref sink, DebugDrawFlags.All, _box);
        return sink.Calls;
    }

    private struct Counter : IDebugDrawSink
    {
        public int Calls;

        public void Sphere(in Vector3 center, float radius, ShapeKind kind, uint id) => Calls++;

        public void Cylinder(in Vector3 lowPoint, float radius, float height, ShapeKind kind, uint id) => Calls++;

        public void Polygon(ReadOnlySpan<Vector3> vertices, in Vector3 normal, ShapeKind kind, uint id) => Calls++;

        public void Triangle(in Vector3 a, in Vector3 b, in Vector3 c, ShapeKind kind, uint id) => Calls++;

        public void Segment(in Vector3 a, in Vector3 b, ShapeKind kind, uint id) => Calls++;

        public void Plane(in Vector3 point, in Vector3 normal, ShapeKind kind, uint id) => Calls++;
    }
}
