using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision.Bsp;

/// <summary>
/// Builds <see cref="BspTree"/>s for synthetic scenes and tests: a physics BSP from polygons or triangles, and a cell BSP
/// (an indoor cell's region) from its bounding planes. Not a port: retail's trees come from the game's data; this
/// builder produces trees in the same shape that the same queries walk.
/// </summary>
/// <remarks>
/// <para>For hand-made geometry only (tests, samples, scenes without the game's data files). With the data files, collision runs
/// through the retail trees as stored — unpacked by <see cref="Data.GfxObjEntry"/>, <see cref="Data.EnvironmentEntry"/> and
/// <see cref="Data.LandBlockLoader"/> (node order, splitting planes, leaf lists, solid leaves and spheres as retail
/// has them) — never through a tree built here.</para>
/// <para>Physics trees: each split plane is axis-aligned, through the median polygon centroid on the longest axis of the
/// centroids' box. A polygon that straddles a plane is listed in both children (polygons are never cut), so every leaf
/// holds whole polygons and a sphere query finds each polygon it touches. Leaves are not marked solid (the builder
/// cannot know which side of an arbitrary mesh is inside), so placement relies on polygon contact only.</para>
/// <para>Build time allocates; queries on the result do not.</para>
/// </remarks>
public static class BspBuilder
{
    /// <summary>Default most polygons in a leaf.</summary>
    public const int DefaultMaxLeafPolys = 4;

    private const int MaxDepth = 48;
    private const double SideEpsilon = 1e-5;

    /// <summary>
    /// A physics BSP over triangles given as consecutive corner triples (counter-clockwise seen from the side that
    /// collides: the polygons are one-sided, their normal by the right-hand rule).
    /// </summary>
    /// <exception cref="ArgumentException">No triangle, a corner count not divisible by three, or a non-finite or degenerate triangle.</exception>
    public static BspTree FromTriangles(ReadOnlySpan<Vector3> corners, int maxLeafPolys = DefaultMaxLeafPolys)
    {
        if (corners.Length == 0 || corners.Length % 3 != 0)
        {
            throw new ArgumentException("Give three corners per triangle, at least one triangle.", nameof(corners));
        }

        var polys = new Polygon[corners.Length / 3];
        ReadOnlySpan<ushort> ids = [0, 1, 2];
        for (int i = 0; i < polys.Length; i++)
        {
            polys[i] = new Polygon((short)i, corners.Slice(i * 3, 3), ids);
        }

        return Build(polys, maxLeafPolys);
    }

    /// <summary>A physics BSP over <paramref name="polygons"/> (convex, one-sided, in the tree owner's local space).</summary>
    /// <exception cref="ArgumentException">No polygon, a null polygon, a degenerate polygon (non-finite plane), or
    /// <paramref name="maxLeafPolys"/> below 1.</exception>
    public static BspTree Build(ReadOnlySpan<Polygon> polygons, int maxLeafPolys = DefaultMaxLeafPolys)
    {
        if (polygons.Length == 0)
        {
            throw new ArgumentException("A BSP needs at least one polygon.", nameof(polygons));
        }

        if (maxLeafPolys < 1)
        {
            throw new ArgumentException("A leaf must be allowed at least one polygon.", nameof(maxLeafPolys));
        }

        var polys = polygons.ToArray();
        for (int i = 0; i < polys.Length; i++)
        {
            if (polys[i] is null)
            {
                throw new ArgumentException("Polygons must not be null.", nameof(polygons));
            }

            if (!VectorMath.IsFinite(polys[i].Plane.N) || !float.IsFinite(polys[i].Plane.D))
            {
                throw new ArgumentException($"Polygon {i} is degenerate (no plane).", nameof(polygons));
            }
        }

        var state = new BuildState(polys, maxLeafPolys);
        var all = new List<int>(polys.Length);
        for (int i = 0; i < polys.Length; i++)
        {
            all.Add(i);
        }

        int root = state.BuildNode(all, 0);
        return new BspTree(state.Nodes.ToArray(), polys, state.Indices.ToArray(), root);
    }

    /// <summary>
    /// A cell BSP: the region where the point is in front of (or on) every plane of <paramref name="inwardPlanes"/>
    /// (normals pointing into the cell), chained through the positive children as retail's cell trees are walked.
    /// </summary>
    /// <exception cref="ArgumentException">No plane, or a non-finite plane.</exception>
    public static BspTree BuildCell(ReadOnlySpan<CollisionPlane> inwardPlanes)
    {
        if (inwardPlanes.Length == 0)
        {
            throw new ArgumentException("A cell needs at least one plane.", nameof(inwardPlanes));
        }

        var nodes = new BspNode[inwardPlanes.Length];
        for (int i = 0; i < nodes.Length; i++)
        {
            CollisionPlane p = inwardPlanes[i];
            if (!VectorMath.IsFinite(p.N) || !float.IsFinite(p.D))
            {
                throw new ArgumentException("Cell planes must be finite.", nameof(inwardPlanes));
            }

            nodes[i] = BspNode.Split(BspNodeType.SplitPositiveChild, p, default, i + 1 < nodes.Length ? i + 1 : -1, -1);
        }

        return new BspTree(nodes, [], [], 0);
    }

    /// <summary>The six inward planes of the box <paramref name="min"/>..<paramref name="max"/>.</summary>
    public static CollisionPlane[] BoxCellPlanes(Vector3 min, Vector3 max) =>
    [
        new CollisionPlane(new Vector3(1f, 0f, 0f), -min.X),
        new CollisionPlane(new Vector3(-1f, 0f, 0f), max.X),
        new CollisionPlane(new Vector3(0f, 1f, 0f), -min.Y),
        new CollisionPlane(new Vector3(0f, -1f, 0f), max.Y),
        new CollisionPlane(new Vector3(0f, 0f, 1f), -min.Z),
        new CollisionPlane(new Vector3(0f, 0f, -1f), max.Z),
    ];

    private sealed class BuildState(Polygon[] polys, int maxLeafPolys)
    {
        public readonly List<BspNode> Nodes = new();
        public readonly List<int> Indices = new();
        private int _leaves;

        public int BuildNode(List<int> set, int depth)
        {
            Sphere bound = Bound(set);
            if (set.Count > maxLeafPolys && depth < MaxDepth && TrySplit(set, out CollisionPlane plane, out List<int>? pos, out List<int>? neg))
            {
                int self = Nodes.Count;
                Nodes.Add(default);
                int p = BuildNode(pos!, depth + 1);
                int n = BuildNode(neg!, depth + 1);
                Nodes[self] = BspNode.Split(BspNodeType.SplitBothChildren, plane, bound, p, n);
                return self;
            }

            int first = Indices.Count;
            Indices.AddRange(set);
            Nodes.Add(BspNode.MakeLeaf(_leaves++, bound, first, set.Count, false));
            return Nodes.Count - 1;
        }

        private bool TrySplit(List<int> set, out CollisionPlane plane, out List<int>? pos, out List<int>? neg)
        {
            Vector3 min = new(float.MaxValue), max = new(float.MinValue);
            var centroids = new Vector3[set.Count];
            for (int i = 0; i < set.Count; i++)
            {
                centroids[i] = Centroid(polys[set[i]]);
                min = Vector3.Min(min, centroids[i]);
                max = Vector3.Max(max, centroids[i]);
            }

            Vector3 ext = max - min;
            Span<int> axes = [0, 1, 2];
            axes.Sort((a, b) => Get(ext, b).CompareTo(Get(ext, a)));
            foreach (int axis in axes)
            {
                var keys = new float[centroids.Length];
                for (int i = 0; i < keys.Length; i++)
                {
                    keys[i] = Get(centroids[i], axis);
                }

                Array.Sort(keys);
                float c = keys[keys.Length / 2];
                var n = new Vector3(axis == 0 ? 1f : 0f, axis == 1 ? 1f : 0f, axis == 2 ? 1f : 0f);
                plane = new CollisionPlane(n, -c);
                pos = new List<int>();
                neg = new List<int>();
                foreach (int pi in set)
                {
                    double lo = double.MaxValue, hi = double.MinValue;
                    foreach (Vector3 v in polys[pi].Vertices)
                    {
                        double d = plane.DotProduct(v);
                        lo = Math.Min(lo, d);
                        hi = Math.Max(hi, d);
                    }

                    if (lo >= -SideEpsilon && hi > SideEpsilon)
                    {
                        pos.Add(pi);
                    }
                    else if (hi <= SideEpsilon && lo < -SideEpsilon)
                    {
                        neg.Add(pi);
                    }
                    else if (hi <= SideEpsilon && lo >= -SideEpsilon)
                    {
                        // In the plane: on the side its normal faces.
                        (Get(polys[pi].Plane.N, axis) >= 0f ? pos : neg).Add(pi);
                    }
                    else
                    {
                        pos.Add(pi);
                        neg.Add(pi);
                    }
                }

                if (pos.Count < set.Count && neg.Count < set.Count)
                {
                    return true;
                }
            }

            plane = default;
            pos = null;
            neg = null;
            return false;
        }

        private Sphere Bound(List<int> set)
        {
            Vector3 min = new(float.MaxValue), max = new(float.MinValue);
            foreach (int pi in set)
            {
                foreach (Vector3 v in polys[pi].Vertices)
                {
                    min = Vector3.Min(min, v);
                    max = Vector3.Max(max, v);
                }
            }

            if (set.Count == 0)
            {
                return default;
            }

            Vector3 c = (min + max) * 0.5f;
            double r = 0.0;
            foreach (int pi in set)
            {
                foreach (Vector3 v in polys[pi].Vertices)
                {
                    double dx = (double)v.X - c.X, dy = (double)v.Y - c.Y, dz = (double)v.Z - c.Z;
                    r = Math.Max(r, Math.Sqrt(dx * dx + dy * dy + dz * dz));
                }
            }

            // A small margin so float rounding of the bound never rejects a sphere touching a polygon.
            return new Sphere(c, (float)(r * 1.0001 + 1e-3));
        }

        private static Vector3 Centroid(Polygon p)
        {
            Vector3 s = Vector3.Zero;
            foreach (Vector3 v in p.Vertices)
            {
                s += v;
            }

            return s / p.NumPoints;
        }

        private static float Get(Vector3 v, int axis) => axis == 0 ? v.X : axis == 1 ? v.Y : v.Z;
    }
}
