using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;

namespace AcDream.Core.Tests.Support.Shared;

/// <summary>Static geometry as one-sided quads with outward normals (compiled into the tests and the benchmarks; no xunit here).</summary>
internal static class BoxShapes
{
    /// <summary>A quad with corners in order (counter-clockwise seen from the side it faces).</summary>
    public static Polygon Quad(Vector3 a, Vector3 b, Vector3 c, Vector3 d, short id = 0) =>
        new(id, new[] { a, b, c, d }, new ushort[] { 0, 1, 2, 3 });

    /// <summary>Appends the six outward-facing faces of the box <paramref name="min"/>..<paramref name="max"/>; their ids
    /// continue from the list's count.</summary>
    public static void AddBox(List<Polygon> polys, Vector3 min, Vector3 max)
    {
        float x0 = min.X, y0 = min.Y, z0 = min.Z, x1 = max.X, y1 = max.Y, z1 = max.Z;
        short id = (short)polys.Count;
        polys.Add(Quad(new(x1, y0, z0), new(x1, y1, z0), new(x1, y1, z1), new(x1, y0, z1), id++)); // +X
        polys.Add(Quad(new(x0, y0, z0), new(x0, y0, z1), new(x0, y1, z1), new(x0, y1, z0), id++)); // -X
        polys.Add(Quad(new(x0, y1, z0), new(x0, y1, z1), new(x1, y1, z1), new(x1, y1, z0), id++)); // +Y
        polys.Add(Quad(new(x0, y0, z0), new(x1, y0, z0), new(x1, y0, z1), new(x0, y0, z1), id++)); // -Y
        polys.Add(Quad(new(x0, y0, z1), new(x1, y0, z1), new(x1, y1, z1), new(x0, y1, z1), id++)); // +Z
        polys.Add(Quad(new(x0, y0, z0), new(x0, y1, z0), new(x1, y1, z0), new(x1, y0, z0), id));   // -Z
    }
}
