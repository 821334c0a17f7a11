using System;
using System.Buffers.Binary;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Data;

namespace AcDream.Core.Fixtures.Data;

/// <summary>
/// Retail's BSP pack (<c>BSPNODE::PackChild</c> / <c>Pack</c>, <c>BSPLEAF::PackLeaf</c>, <c>BSPPORTAL::PackPortal</c> and their
/// size functions): a <see cref="BspTree"/> written in the layout <see cref="RetailBsp"/> reads, depth first from the root, so
/// a tree round-trips (the library ships the reader only; the writer lives here). As retail, a split node writes the children
/// it has (not the ones its tag names), and a polygon list writes each polygon's <see cref="Polygon.PolyId"/> (retail's
/// <c>poly_id</c>, which the unpack reads back as the index into the owner's list: the two agree in retail's data).
/// </summary>
internal static class RetailBspPack
{
    /// <summary>The tree's bytes for <paramref name="kind"/> (what <c>BSPTREE::UnPack</c> reads: the root as a child).</summary>
    public static byte[] Pack(BspTree tree, RetailBspKind kind)
    {
        ArgumentNullException.ThrowIfNull(tree);
        var bytes = new byte[PackChildSize(tree, tree.Root, kind)];
        int at = 0;
        PackChild(tree, tree.Root, kind, bytes, ref at);
        return bytes;
    }

    /// <summary>The child's tag (4 bytes) and its body.</summary>
    // retail: BSPNODE::pack_child_size (acclient.c:363290)
    private static int PackChildSize(BspTree tree, int i, RetailBspKind kind)
    {
        BspNode n = tree.Nodes[i];
        return n.Type switch
        {
            BspNodeType.Portal => PackPortalSize(tree, n, kind) + 4,
            BspNodeType.Leaf => PackLeafSize(n, kind) + 4,
            _ => PackSize(tree, n, kind) + 4,
        };
    }

    /// <summary>Writes the tag, then the node as its type packs.</summary>
    // retail: BSPNODE::PackChild (acclient.c:363316)
    private static void PackChild(BspTree tree, int i, RetailBspKind kind, Span<byte> b, ref int at)
    {
        BspNode n = tree.Nodes[i];
        U32(b, ref at, (uint)n.Type);
        if (n.Type == BspNodeType.Portal)
        {
            PackPortal(tree, n, kind, b, ref at);
        }
        else if (n.Type == BspNodeType.Leaf)
        {
            PackLeaf(tree, n, kind, b, ref at);
        }
        else
        {
            PackNode(tree, n, kind, b, ref at);
        }
    }

    // retail: BSPNODE::pack_size (acclient.c:363108)
    private static int PackSize(BspTree tree, in BspNode n, RetailBspKind kind)
    {
        int size = 16;
        if (n.PosNode >= 0)
        {
            size = PackChildSize(tree, n.PosNode, kind) + 16;
        }

        if (n.NegNode >= 0)
        {
            size += PackChildSize(tree, n.NegNode, kind);
        }

        return kind switch
        {
            RetailBspKind.Drawing => size + 2 * n.NumPolys + 20,
            RetailBspKind.Physics => size + 16,
            _ => size,
        };
    }

    /// <summary>A split node: the plane, the children it has, then the sphere (drawing, physics) and the polygon ids (drawing).</summary>
    // retail: BSPNODE::Pack (acclient.c:363142)
    private static void PackNode(BspTree tree, in BspNode n, RetailBspKind kind, Span<byte> b, ref int at)
    {
        Plane(b, ref at, n.SplittingPlane);
        if (n.PosNode >= 0)
        {
            PackChild(tree, n.PosNode, kind, b, ref at);
        }

        if (n.NegNode >= 0)
        {
            PackChild(tree, n.NegNode, kind, b, ref at);
        }

        if (kind == RetailBspKind.Cell)
        {
            return;
        }

        SphereOut(b, ref at, n.Sphere);
        if (kind == RetailBspKind.Drawing)
        {
            PolyIds(tree, n, b, ref at, withCount: true);
        }
    }

    // The leaf's size: 4, or 2 × polygons + 28 in a physics tree.
    private static int PackLeafSize(in BspNode n, RetailBspKind kind) => kind == RetailBspKind.Physics ? 2 * n.NumPolys + 28 : 4;

    /// <summary>A leaf: its index, then (physics) the solid flag, the sphere, the polygon count and ids.</summary>
    // retail: BSPLEAF::PackLeaf (acclient.c:364091)
    private static void PackLeaf(BspTree tree, in BspNode n, RetailBspKind kind, Span<byte> b, ref int at)
    {
        U32(b, ref at, (uint)n.LeafIndex);
        if (kind == RetailBspKind.Physics)
        {
            U32(b, ref at, n.Solid ? 1u : 0u);
            SphereOut(b, ref at, n.Sphere);
            PolyIds(tree, n, b, ref at, withCount: true);
        }
    }

    // retail: BSPPORTAL::pack_portal_size (acclient.c:364565)
    private static int PackPortalSize(BspTree tree, in BspNode n, RetailBspKind kind)
    {
        int size = PackChildSize(tree, n.PosNode, kind) + 16 + PackChildSize(tree, n.NegNode, kind);
        // The library keeps no portal lists (drawing trees are not kept): num_portals is 0.
        return kind == RetailBspKind.Drawing ? size + 2 * (n.NumPolys + 2 * 0 + 12) : size;
    }

    /// <summary>A portal node: the plane, both children, then (drawing) the sphere, the polygon and portal counts and lists.</summary>
    // retail: BSPPORTAL::PackPortal (acclient.c:364589)
    private static void PackPortal(BspTree tree, in BspNode n, RetailBspKind kind, Span<byte> b, ref int at)
    {
        Plane(b, ref at, n.SplittingPlane);
        PackChild(tree, n.PosNode, kind, b, ref at);
        PackChild(tree, n.NegNode, kind, b, ref at);
        if (kind == RetailBspKind.Drawing)
        {
            SphereOut(b, ref at, n.Sphere);
            U32(b, ref at, (uint)n.NumPolys);
            U32(b, ref at, 0);
            PolyIds(tree, n, b, ref at, withCount: false);
        }
    }

    private static void PolyIds(BspTree tree, in BspNode n, Span<byte> b, ref int at, bool withCount)
    {
        if (withCount)
        {
            U32(b, ref at, (uint)n.NumPolys);
        }

        for (int p = 0; p < n.NumPolys; p++)
        {
            BinaryPrimitives.WriteInt16LittleEndian(b.Slice(at), tree.Polygons[tree.PolyIndices[n.FirstPoly + p]].PolyId);
            at += 2;
        }
    }

    // Plane::Pack: normal x, y, z, then d.
    private static void Plane(Span<byte> b, ref int at, in CollisionPlane p)
    {
        F32(b, ref at, p.N.X);
        F32(b, ref at, p.N.Y);
        F32(b, ref at, p.N.Z);
        F32(b, ref at, p.D);
    }

    // A sphere, packed as retail packs it (through Plane::Pack): centre x, y, z, then radius.
    private static void SphereOut(Span<byte> b, ref int at, in Sphere s)
    {
        F32(b, ref at, s.Center.X);
        F32(b, ref at, s.Center.Y);
        F32(b, ref at, s.Center.Z);
        F32(b, ref at, s.Radius);
    }

    private static void U32(Span<byte> b, ref int at, uint v)
    {
        BinaryPrimitives.WriteUInt32LittleEndian(b.Slice(at), v);
        at += 4;
    }

    private static void F32(Span<byte> b, ref int at, float v)
    {
        BinaryPrimitives.WriteSingleLittleEndian(b.Slice(at), v);
        at += 4;
    }
}
