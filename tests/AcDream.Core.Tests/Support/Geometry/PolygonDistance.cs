using System;
using System.Numerics;

namespace AcDream.Core.Tests.Support.Geometry;

/// <summary>Point and segment tests against convex polygons given by their vertices (test-side geometry).</summary>
internal static class PolygonDistance
{
    /// <summary>Distance from <paramref name="p"/> to the convex polygon <paramref name="v"/>.</summary>
    public static float To(Vector3 p, Vector3[] v)
    {
        Vector3 n = Normal(v);
        float d = Vector3.Dot(n, p - v[0]);
        Vector3 q = p - d * n;
        if (Inside(q, v, n))
        {
            return MathF.Abs(d);
        }

        float best = float.MaxValue;
        for (int i = 0; i < v.Length; i++)
        {
            Vector3 a = v[i], b = v[(i + 1) % v.Length];
            Vector3 ab = b - a;
            float t = Math.Clamp(Vector3.Dot(p - a, ab) / MathF.Max(ab.LengthSquared(), 1e-12f), 0f, 1f);
            best = MathF.Min(best, Vector3.Distance(p, a + t * ab));
        }

        return best;
    }

    /// <summary>True when the segment <paramref name="a"/>..<paramref name="b"/> passes through the polygon's interior
    /// (strictly from one side of its plane to the other).</summary>
    public static bool Crosses(Vector3 a, Vector3 b, Vector3[] v)
    {
        Vector3 n = Normal(v);
        float da = Vector3.Dot(n, a - v[0]), db = Vector3.Dot(n, b - v[0]);
        if (da * db >= 0f)
        {
            return false;
        }

        Vector3 q = a + da / (da - db) * (b - a);
        return Inside(q, v, n);
    }

    private static Vector3 Normal(Vector3[] v)
    {
        Vector3 n = Vector3.Zero;
        for (int i = 1; i + 1 < v.Length; i++)
        {
            n += Vector3.Cross(v[i] - v[0], v[i + 1] - v[0]);
        }

        return Vector3.Normalize(n);
    }

    private static bool Inside(Vector3 q, Vector3[] v, Vector3 n)
    {
        for (int i = 0; i < v.Length; i++)
        {
            Vector3 a = v[i], b = v[(i + 1) % v.Length];
            if (Vector3.Dot(Vector3.Cross(b - a, q - a), n) < 0f)
            {
                return false;
            }
        }

        return true;
    }
}
