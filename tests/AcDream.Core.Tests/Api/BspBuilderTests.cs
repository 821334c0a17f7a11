using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using Xunit;

namespace AcDream.Core.Tests.Api;

public class BspBuilderTests
{
    private static Vector3[] RandomTriangles(int count, int seed)
    {
        var rng = new Random(seed);
        var c = new Vector3[count * 3];
        for (int i = 0; i < count; i++)
        {
            var centre = new Vector3((float)rng.NextDouble() * 40f, (float)rng.NextDouble() * 40f, (float)rng.NextDouble() * 10f);
            for (int k = 0; k < 3; k++)
            {
                c[i * 3 + k] = centre + new Vector3((float)rng.NextDouble() * 2f - 1f, (float)rng.NextDouble() * 2f - 1f, (float)rng.NextDouble() * 2f - 1f);
            }
        }

        return c;
    }

    [Fact]
    public void RoundTrip_EveryTriangleIsFoundByASpherePlacedOnIt()
    {
        Vector3[] corners = RandomTriangles(500, 12345);
        BspTree tree = BspBuilder.FromTriangles(corners);
        ReadOnlySpan<Polygon> polys = tree.Polygons;
        Assert.Equal(500, polys.Length);
        for (int i = 0; i < polys.Length; i++)
        {
            Polygon p = polys[i];
            Vector3 centroid = (corners[i * 3] + corners[i * 3 + 1] + corners[i * 3 + 2]) / 3f;
            // A 0.05 m sphere 0.02 in front of the centroid, moving into the face.
            var s = new Sphere(centroid + p.Plane.N * 0.02f, 0.05f);
            Polygon? hit = null;
            Assert.True(tree.SphereIntersectsPoly(s, -p.Plane.N, ref hit, out _), $"triangle {i} not found");
            Assert.True(hit!.HitsSphere(s));
            Assert.True(tree.SphereIntersectsSolid(s, false));
            // And it is in some leaf: the union of the leaves' lists holds every triangle.
        }

        var inLeaf = new bool[polys.Length];
        foreach (BspNode n in tree.Nodes)
        {
            if (n.IsLeaf)
            {
                for (int k = 0; k < n.NumPolys; k++)
                {
                    inLeaf[tree.PolyIndices[n.FirstPoly + k]] = true;
                }
            }
        }

        Assert.DoesNotContain(false, inLeaf);
    }

    [Fact]
    public void Tree_AgreesWithBruteForce_OnRandomSpheres()
    {
        Vector3[] corners = RandomTriangles(300, 777);
        BspTree tree = BspBuilder.FromTriangles(corners);
        var rng = new Random(4242);
        int hits = 0;
        for (int i = 0; i < 3000; i++)
        {
            var s = new Sphere(new Vector3((float)rng.NextDouble() * 44f - 2f, (float)rng.NextDouble() * 44f - 2f, (float)rng.NextDouble() * 14f - 2f),
                (float)rng.NextDouble() * 1.5f);
            bool brute = false;
            foreach (Polygon p in tree.Polygons)
            {
                brute |= p.HitsSphere(s);
            }

            hits += brute ? 1 : 0;
            Assert.Equal(brute, tree.SphereIntersectsSolid(s, false));
        }

        // The sample exercises both answers.
        Assert.InRange(hits, 100, 2900);
    }

    [Fact]
    public void Builder_RejectsBadInput()
    {
        Assert.Throws<ArgumentException>(() => BspBuilder.FromTriangles(ReadOnlySpan<Vector3>.Empty));
        Assert.Throws<ArgumentException>(() => BspBuilder.FromTriangles(new Vector3[4]));
        Assert.Throws<ArgumentException>(() => BspBuilder.FromTriangles(new[] { Vector3.Zero, new Vector3(float.NaN, 0f, 0f), Vector3.UnitY }));
        Assert.Throws<ArgumentException>(() => BspBuilder.BuildCell(ReadOnlySpan<CollisionPlane>.Empty));
        Assert.Throws<ArgumentException>(() => new BspTree(new[] { BspNode.Split(BspNodeType.SplitBothChildren, default, default, 0, -1) }, Array.Empty<Polygon>(), Array.Empty<int>()));
        Assert.Throws<ArgumentException>(() => new BspTree(new[] { BspNode.MakeLeaf(0, default, 0, 2, false) }, Array.Empty<Polygon>(), new[] { 0, 0 }));
    }
}
