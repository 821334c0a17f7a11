using System;
using System.Numerics;

namespace AcDream.Core.Physics.Debug;

/// <summary>
/// What receives the collision shapes of <see cref="PhysicsDebugDraw"/> (library addition, in the manner of Box2D's
/// <c>b2DebugDraw</c> and Jolt's <c>DebugRenderer</c>): a client implements it as a struct that draws in its own renderer.
/// Every point is in the one frame of the <see cref="DebugDrawRegion"/> the call was given; z is up. The spans and
/// <c>in</c> arguments are valid only during the call.
/// </summary>
public interface IDebugDrawSink
{
    /// <summary>A sphere.</summary>
    /// <param name="center">Its centre.</param>
    /// <param name="radius">Its radius, metres.</param>
    /// <param name="kind">What it is.</param>
    /// <param name="id">The object's id (see <see cref="ShapeKind"/>).</param>
    void Sphere(in Vector3 center, float radius, ShapeKind kind, uint id);

    /// <summary>A vertical cylinder (retail's cylinder sphere): the centre of its bottom disc, its radius and height.</summary>
    /// <param name="lowPoint">The centre of the bottom disc.</param>
    /// <param name="radius">The radius, metres.</param>
    /// <param name="height">The height above <paramref name="lowPoint"/>, metres.</param>
    /// <param name="kind">What it is.</param>
    /// <param name="id">The object's id.</param>
    void Cylinder(in Vector3 lowPoint, float radius, float height, ShapeKind kind, uint id);

    /// <summary>A convex polygon, its vertices in order, with its plane's normal.</summary>
    /// <param name="vertices">The vertices (valid only during the call).</param>
    /// <param name="normal">The polygon's normal (the side that collides).</param>
    /// <param name="kind">What it is.</param>
    /// <param name="id">An object or cell id (see <see cref="ShapeKind"/>).</param>
    void Polygon(ReadOnlySpan<Vector3> vertices, in Vector3 normal, ShapeKind kind, uint id);

    /// <summary>A triangle (terrain), counter-clockwise seen from above.</summary>
    /// <param name="a">The first vertex.</param>
    /// <param name="b">The second vertex.</param>
    /// <param name="c">The third vertex.</param>
    /// <param name="kind">What it is.</param>
    /// <param name="id">The cell's id.</param>
    void Triangle(in Vector3 a, in Vector3 b, in Vector3 c, ShapeKind kind, uint id);

    /// <summary>A segment.</summary>
    /// <param name="a">One end.</param>
    /// <param name="b">The other end.</param>
    /// <param name="kind">What it is.</param>
    /// <param name="id">A cell or object id (see <see cref="ShapeKind"/>).</param>
    void Segment(in Vector3 a, in Vector3 b, ShapeKind kind, uint id);

    /// <summary>A plane, given by a point on it and its unit normal.</summary>
    /// <param name="point">A point of the plane.</param>
    /// <param name="normal">The normal.</param>
    /// <param name="kind">What it is.</param>
    /// <param name="id">The object's id.</param>
    void Plane(in Vector3 point, in Vector3 normal, ShapeKind kind, uint id);
}
