using AcDream.Core.Physics.Collision.Primitives;

namespace AcDream.Core.Physics.Collision.Bsp;

/// <summary>
/// One node of a <see cref="BspTree"/>, in retail's shape (<c>BSPNODE</c> acclient.h:32157 and <c>BSPLEAF</c>
/// acclient.h:57775) with the pointers replaced by indices into the tree's arrays.
/// </summary>
/// <remarks>
/// Split nodes use <see cref="SplittingPlane"/>, <see cref="Sphere"/> (the bound of everything below) and the two child
/// indices; leaves use <see cref="Sphere"/>, the polygon range and <see cref="Solid"/>. A cell BSP (the region of an
/// indoor cell) chains its planes through <see cref="PosNode"/> only. Physics split nodes keep no polygons (retail's
/// physics pack type stores only the sphere for a split node).
/// </remarks>
public struct BspNode
{
    /// <summary>The node kind. Retail: <c>type</c>.</summary>
    public BspNodeType Type;

    /// <summary>The plane that splits the node's space (split nodes and cell BSP nodes). Retail: <c>splitting_plane</c>.</summary>
    public CollisionPlane SplittingPlane;

    /// <summary>Bounding sphere of the node's polygons. Retail: <c>sphere</c>.</summary>
    public Sphere Sphere;

    /// <summary>Index of the child on the plane's positive side, or -1. Retail: <c>pos_node</c>.</summary>
    public int PosNode;

    /// <summary>Index of the child on the plane's negative side, or -1. Retail: <c>neg_node</c>.</summary>
    public int NegNode;

    /// <summary>First entry of the node's polygons in <see cref="BspTree.PolyIndices"/>. Retail: <c>in_polys</c>.</summary>
    public int FirstPoly;

    /// <summary>Number of polygons. Retail: <c>num_polys</c>.</summary>
    public int NumPolys;

    /// <summary>The leaf's index in its tree (leaves only). Retail: <c>BSPLEAF::leaf_index</c>.</summary>
    public int LeafIndex;

    /// <summary>The leaf is inside solid matter (leaves only). Retail: <c>BSPLEAF::solid</c>.</summary>
    public bool Solid;

    /// <summary>True for a leaf node.</summary>
    public readonly bool IsLeaf => Type == BspNodeType.Leaf;

    /// <summary>A split node.</summary>
    public static BspNode Split(BspNodeType type, in CollisionPlane plane, in Sphere sphere, int posNode, int negNode) => new()
    {
        Type = type,
        SplittingPlane = plane,
        Sphere = sphere,
        PosNode = posNode,
        NegNode = negNode,
        LeafIndex = -1,
    };

    /// <summary>A leaf holding <paramref name="numPolys"/> polygons from <paramref name="firstPoly"/> in the tree's index list.</summary>
    public static BspNode MakeLeaf(int leafIndex, in Sphere sphere, int firstPoly, int numPolys, bool solid) => new()
    {
        Type = BspNodeType.Leaf,
        Sphere = sphere,
        PosNode = -1,
        NegNode = -1,
        FirstPoly = firstPoly,
        NumPolys = numPolys,
        LeafIndex = leafIndex,
        Solid = solid,
    };
}
