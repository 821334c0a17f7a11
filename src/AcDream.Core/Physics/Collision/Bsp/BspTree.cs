using System;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision.Bsp;

/// <summary>
/// A BSP tree in retail's shape (<c>BSPTREE</c> acclient.h:31963, PORTAL/cgeometry/CBSPTree.c, CBSPNode.c, CBSPLeaf.c):
/// split nodes with planes and bounding spheres, leaves with polygon lists, a solid flag and a bounding sphere — held as
/// flat arrays linked by index, so a query allocates nothing.
/// </summary>
/// <remarks>
/// <para>A client fills it from the game's data (the physics BSP of a GfxObj or an environment's cell structure, and the
/// cell BSP of an indoor cell); <see cref="BspBuilder"/> makes one from triangles for synthetic scenes. The polygons are
/// in the tree owner's local space (part-local for an object, cell-local for an env cell).</para>
/// <para>The class is split by concern: this file (data), <c>BspTree.Queries.cs</c> (the recursive node and leaf
/// sphere queries), <c>BspTree.Cell.cs</c> (cell BSP point and sphere tests), <c>BspTree.Collisions.cs</c> (the
/// transition entry points: find_collisions, placement_insert and their helpers).</para>
/// <para>Divergence (why): retail dereferences both children of every split node without a null test (its physics trees
/// always have both); a missing child here (index -1) is treated as an empty leaf, so a hand-made tree cannot crash a
/// query.</para>
/// </remarks>
public sealed partial class BspTree
{
    private readonly BspNode[] _nodes;
    private readonly Polygon[] _polygons;
    private readonly int[] _polyIndices;

    /// <summary>Creates a tree from its nodes (root at <paramref name="root"/>), its polygons and the leaves' polygon index lists.</summary>
    /// <param name="nodes">The nodes; child indices refer to this array.</param>
    /// <param name="polygons">The polygons the leaves refer to.</param>
    /// <param name="polyIndices">For each node, <see cref="BspNode.NumPolys"/> entries from <see cref="BspNode.FirstPoly"/>, each an index into <paramref name="polygons"/>.</param>
    /// <param name="root">Index of the root node.</param>
    /// <exception cref="ArgumentNullException">An array is null.</exception>
    /// <exception cref="ArgumentException">An index is out of range, a node is reached twice (a cycle or a shared
    /// child), or a plane or sphere is not finite. A node whose type is not a named <see cref="BspNodeType"/> is a split node,
    /// as retail's <c>BSPNODE</c> of any tag other than LEAF and PORT is (real drawing trees hold <c>BPOL</c> and
    /// <c>BPFL</c>).</exception>
    public BspTree(BspNode[] nodes, Polygon[] polygons, int[] polyIndices, int root = 0)
    {
        ArgumentNullException.ThrowIfNull(nodes);
        ArgumentNullException.ThrowIfNull(polygons);
        ArgumentNullException.ThrowIfNull(polyIndices);
        if (nodes.Length == 0 || (uint)root >= (uint)nodes.Length)
        {
            throw new ArgumentException("The tree needs a root node inside the node array.", nameof(root));
        }

        for (int i = 0; i < polygons.Length; i++)
        {
            if (polygons[i] is null)
            {
                throw new ArgumentException("Polygons must not be null.", nameof(polygons));
            }
        }

        Validate(nodes, polygons.Length, polyIndices, root);
        _nodes = (BspNode[])nodes.Clone();
        _polygons = (Polygon[])polygons.Clone();
        _polyIndices = (int[])polyIndices.Clone();
        Root = root;
    }

    /// <summary>Index of the root node. Retail: <c>root_node</c>.</summary>
    public int Root { get; }

    /// <summary>The nodes.</summary>
    public ReadOnlySpan<BspNode> Nodes => _nodes;

    /// <summary>The polygons the leaves refer to.</summary>
    public ReadOnlySpan<Polygon> Polygons => _polygons;

    /// <summary>The leaves' polygon lists (indices into <see cref="Polygons"/>).</summary>
    public ReadOnlySpan<int> PolyIndices => _polyIndices;

    /// <summary>The bounding sphere of the whole tree (the root's sphere). Retail: <c>BSPTREE::GetSphere</c>.</summary>
    // retail: BSPTREE::GetSphere (acclient.c:360661)
    public Sphere Sphere => _nodes[Root].Sphere;

    private Polygon Poly(in BspNode node, int i) => _polygons[_polyIndices[node.FirstPoly + i]];

    private static void Validate(BspNode[] nodes, int numPolygons, int[] polyIndices, int root)
    {
        var seen = new bool[nodes.Length];
        var stack = new int[nodes.Length];
        int top = 0;
        stack[top++] = root;
        seen[root] = true;
        while (top > 0)
        {
            int i = stack[--top];
            ref readonly BspNode n = ref nodes[i];
            if (!VectorMath.IsFinite(n.Sphere.Center) || !float.IsFinite(n.Sphere.Radius)
                || !VectorMath.IsFinite(n.SplittingPlane.N) || !float.IsFinite(n.SplittingPlane.D))
            {
                throw new ArgumentException($"Node {i} has a non-finite plane or sphere.", nameof(nodes));
            }

            if (n.NumPolys < 0 || n.FirstPoly < 0 || (long)n.FirstPoly + n.NumPolys > polyIndices.Length)
            {
                throw new ArgumentException($"Node {i} has a polygon range outside the index list.", nameof(nodes));
            }

            for (int p = 0; p < n.NumPolys; p++)
            {
                if ((uint)polyIndices[n.FirstPoly + p] >= (uint)numPolygons)
                {
                    throw new ArgumentException($"Node {i} refers to a polygon outside the polygon array.", nameof(polyIndices));
                }
            }

            Push(n.PosNode);
            Push(n.NegNode);
        }

        void Push(int child)
        {
            if (child < 0)
            {
                return;
            }

            if (child >= nodes.Length || seen[child])
            {
                throw new ArgumentException($"Child index {child} is out of range or reached twice.", nameof(nodes));
            }

            seen[child] = true;
            stack[top++] = child;
        }
    }
}
