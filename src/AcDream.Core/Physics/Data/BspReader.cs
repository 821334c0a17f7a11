using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Data;

/// <summary>What a stored BSP tree holds per node. Retail: <c>BSPTreeType</c> (<c>BSPNODE::pack_tree_type</c>).</summary>
internal enum BspKind
{
    /// <summary>A drawing tree: node spheres and polygon lists, portal lists in portal nodes (retail 0).</summary>
    Drawing = 0,

    /// <summary>A physics tree: node spheres, leaf solid flags, spheres and polygon lists (retail 1).</summary>
    Physics = 1,

    /// <summary>A cell tree: planes only (retail 2).</summary>
    Cell = 2,
}

/// <summary>
/// Retail's BSP unpack (<c>BSPTREE::UnPack</c>, <c>BSPNODE::UnPackChild</c> / <c>UnPack</c>, <c>BSPLEAF::UnPackLeaf</c>,
/// <c>BSPPORTAL::UnPackPortal</c>): a tree stored depth first — a node's tag, its plane, its stored children in order, then
/// what the tree kind keeps — read into a <see cref="BspTree"/> that keeps the stored node order (preorder: a node, then its
/// positive subtree, then its negative one), planes, leaf lists, solid flags and spheres, so the queries walk retail's tree.
/// </summary>
/// <remarks>
/// <para>Retail's static <c>BSPNODE::pack_poly</c> and <c>pack_tree_type</c> become the reader's own fields (no global state).</para>
/// <para>A tag other than <c>PORT</c> and <c>LEAF</c> is a split node (<c>BSPNODE::UnPackChild</c>); <c>BSPNODE::UnPack</c>
/// reads its plane, then only the children the six split tags name (any other tag, such as the <c>BPOL</c> and <c>BPFL</c> real
/// drawing trees hold, has none), then what the tree kind stores for every split node. Such a node is kept with its tag and no
/// children in a physics or cell tree (where the queries treat a missing child as an empty leaf).</para>
/// <para>Divergences (why): a polygon index outside the owner's polygon list is a format error (retail would point past the
/// list); a tree deeper than <see cref="MaxDepth"/> is a format error (retail recurses without bound; bad bytes must not
/// overflow the stack). The stream form cannot express a cycle or a shared child (children are stored inline), so none can be
/// read.</para>
/// </remarks>
internal sealed class BspReader
{
    /// <summary>Deepest node accepted, counting the root as 1.</summary>
    public const int MaxDepth = 256;

    private readonly BspKind _kind;
    private readonly int _numPolys;
    private readonly List<BspNode> _nodes;
    private readonly List<int> _polyIndices;
    private int _leaves;
    private int _rootSphereAt = -1;

    private BspReader(BspKind kind, int numPolys)
    {
        _kind = kind;
        _numPolys = numPolys;
        _nodes = new List<BspNode>();
        _polyIndices = new List<int>();
        _leaves = 0;
    }

    /// <summary>
    /// Reads one tree of <paramref name="kind"/> whose leaves index <paramref name="polygons"/> (retail <c>pack_poly</c>);
    /// a drawing tree is consumed exactly and null returned (the physics never walks it), with its polygon indices checked
    /// against <paramref name="numPolys"/>.
    /// </summary>
    // retail: BSPTREE::UnPack (acclient.c:360685)
    public static BspTree? UnPackTree(ref RetailDataReader r, BspKind kind, Polygon[] polygons, int numPolys) =>
        UnPackTree(ref r, kind, polygons, numPolys, out _);

    /// <summary><see cref="UnPackTree(ref RetailDataReader, BspKind, Polygon[], int)"/>, also giving the offset of the root's
    /// sphere (-1 when the root stores none), so that a check of <c>BSPTREE::GetSphere</c> can name that field.</summary>
    public static BspTree? UnPackTree(ref RetailDataReader r, BspKind kind, Polygon[] polygons, int numPolys, out int rootSphereAt)
    {
        int at = r.Offset;
        var bsp = new BspReader(kind, numPolys);
        int root = bsp.UnPackChild(ref r, 1);
        rootSphereAt = bsp._rootSphereAt;
        if (kind == BspKind.Drawing)
        {
            return null;
        }

        try
        {
            return new BspTree(bsp._nodes.ToArray(), polygons, bsp._polyIndices.ToArray(), root);
        }
        catch (ArgumentException e)
        {
            // Every value the tree checks has been checked while reading; kept as a net so no other exception escapes.
            throw r.ErrorAt(at, "the tree is not valid: " + e.Message);
        }
    }

    /// <summary>A child: its tag, then the node of that kind. Returns its index in the node list.</summary>
    // retail: BSPNODE::UnPackChild (acclient.c:363343)
    private int UnPackChild(ref RetailDataReader r, int depth)
    {
        int at = r.Offset;
        if (depth > MaxDepth)
        {
            throw r.ErrorAt(at, $"tree deeper than {MaxDepth} nodes");
        }

        uint tag = r.ReadUInt32("BSP node type");
        return (BspNodeType)tag switch
        {
            BspNodeType.Portal => UnPackPortal(ref r, depth),
            BspNodeType.Leaf => UnPackLeaf(ref r),
            // Every other tag, the six split tags and any other (BPOL, BPFL, ...), is a BSPNODE.
            _ => UnPack(ref r, (BspNodeType)tag, depth),
        };
    }

    private int Reserve()
    {
        _nodes.Add(default);
        return _nodes.Count - 1;
    }

    /// <summary>A split node: the plane, the children its tag stores (BPIN / BPnN both, BPIn / BPnn the positive one,
    /// BpIN / BpnN the negative one, any other tag none), then the sphere (drawing and physics) and the polygon count (u32)
    /// and list (u16 each; drawing).</summary>
    // retail: BSPNODE::UnPack (acclient.c:363185)
    private int UnPack(ref RetailDataReader r, BspNodeType type, int depth)
    {
        int index = Reserve();
        CollisionPlane plane = CollisionPlane.UnPack(ref r, "BSP splitting plane");
        int pos = -1, neg = -1;
        switch (type)
        {
            case BspNodeType.SplitBothChildren:
            case BspNodeType.SplitBothChildrenUnmarked:
                pos = UnPackChild(ref r, depth + 1);
                neg = UnPackChild(ref r, depth + 1);
                break;
            case BspNodeType.SplitPositiveChild:
            case BspNodeType.SplitPositiveChildUnmarked:
                pos = UnPackChild(ref r, depth + 1);
                break;
            case BspNodeType.SplitNegativeChild:
            case BspNodeType.SplitNegativeChildUnmarked:
                neg = UnPackChild(ref r, depth + 1);
                break;
            default:
                // BSPNODE::UnPack's type test falls through to the sphere for any other tag: no child is read.
                break;
        }

        Sphere sphere = default;
        int first = _polyIndices.Count, count = 0;
        if (_kind != BspKind.Cell)
        {
            if (index == 0)
            {
                _rootSphereAt = r.Offset;
            }

            sphere = Sphere.UnPack(ref r, "BSP node sphere");
            if (_kind == BspKind.Drawing)
            {
                count = ReadPolyList(ref r, r.ReadCount("BSP node polygon count", 2));
            }
        }

        BspNode node = BspNode.Split(type, plane, sphere, pos, neg);
        node.FirstPoly = first;
        node.NumPolys = count;
        _nodes[index] = node;
        return index;
    }

    /// <summary>A leaf: its index, then (physics) the solid flag, the sphere and the polygon list.</summary>
    // retail: BSPLEAF::UnPackLeaf (acclient.c:364132)
    private int UnPackLeaf(ref RetailDataReader r)
    {
        int index = Reserve();
        int leafIndex = r.ReadInt32("BSP leaf index");
        bool solid = false;
        Sphere sphere = default;
        int first = _polyIndices.Count, count = 0;
        if (_kind == BspKind.Physics)
        {
            solid = r.ReadUInt32("BSP leaf solid") != 0;
            if (index == 0)
            {
                _rootSphereAt = r.Offset;
            }

            sphere = Sphere.UnPack(ref r, "BSP leaf sphere");
            count = ReadPolyList(ref r, r.ReadCount("BSP leaf polygon count", 2));
        }

        _leaves++;
        _nodes[index] = BspNode.MakeLeaf(leafIndex, sphere, first, count, solid);
        return index;
    }

    /// <summary>A portal node: the plane, both children, then (drawing) the sphere, the polygon and portal counts, the
    /// polygon list and the portal list (a polygon index and a portal index each).</summary>
    // retail: BSPPORTAL::UnPackPortal (acclient.c:364645)
    private int UnPackPortal(ref RetailDataReader r, int depth)
    {
        int index = Reserve();
        CollisionPlane plane = CollisionPlane.UnPack(ref r, "BSP portal plane");
        int pos = UnPackChild(ref r, depth + 1);
        int neg = UnPackChild(ref r, depth + 1);
        Sphere sphere = default;
        int first = _polyIndices.Count, count = 0;
        if (_kind == BspKind.Drawing)
        {
            if (index == 0)
            {
                _rootSphereAt = r.Offset;
            }

            sphere = Sphere.UnPack(ref r, "BSP portal sphere");
            int numPolysAt = r.Offset;
            uint numPolys = r.ReadUInt32("BSP portal polygon count");
            uint numPortals = r.ReadUInt32("BSP portal portal count");
            count = ReadPolyList(ref r, r.CheckCount(numPolys, "BSP portal polygon count", 2, numPolysAt));
            int portals = r.CheckCount(numPortals, "BSP portal portal count", 4, numPolysAt + 4);
            for (int i = 0; i < portals; i++)
            {
                ReadPolyIndex(ref r);
                r.ReadInt16("BSP portal index");
            }
        }

        BspNode node = BspNode.Split(BspNodeType.Portal, plane, sphere, pos, neg);
        node.FirstPoly = first;
        node.NumPolys = count;
        _nodes[index] = node;
        return index;
    }

    private int ReadPolyList(ref RetailDataReader r, int count)
    {
        for (int i = 0; i < count; i++)
        {
            _polyIndices.Add(ReadPolyIndex(ref r));
        }

        return count;
    }

    private int ReadPolyIndex(ref RetailDataReader r)
    {
        int at = r.Offset;
        short id = r.ReadInt16("BSP polygon index");
        if (id < 0 || id >= _numPolys)
        {
            throw r.ErrorAt(at, $"BSP polygon index {id} is outside the polygon list ({_numPolys} polygons)");
        }

        return id;
    }
}
