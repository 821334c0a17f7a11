namespace AcDream.Core.Physics.Collision.Bsp;

/// <summary>
/// The kind of a BSP node, as retail stores it: a four-character tag read as a big-endian integer
/// (<c>BSPNODE::type</c>, acclient.h:32157; tags decoded from <c>BSPNODE::UnPack</c>, acclient.c:363185).
/// </summary>
/// <remarks>
/// A split node's tag is 'B' and three letters, capital or lower case: 'P' / 'p' (second letter) says whether a positive child
/// is stored, 'N' / 'n' (last letter) whether a negative child is stored; these two are all <c>BSPNODE::UnPack</c> reads
/// (<c>BPIN</c>, <c>BPnN</c>: both children; <c>BPIn</c>, <c>BPnn</c>: the positive one; <c>BpIN</c>, <c>BpnN</c>: the
/// negative one). The third letter is 'I' (here: marked) or 'n' (unmarked), and the client never reads it: a node's bounding
/// sphere and in-plane polygons (<c>in_polys</c>) are stored or not by the tree's pack type, whatever the tag, and no query
/// tests a split node's tag. A marked node and its unmarked twin therefore behave the same; both are kept so that data
/// keeps its tag. Any other tag (real drawing trees hold 'BPOL', 0x42504F4C, and 'BPFL', 0x4250464C) is, as
/// <c>BSPNODE::UnPackChild</c> (acclient.c:363343) reads it, a split node with no stored child; it keeps its value, unnamed.
/// </remarks>
public enum BspNodeType : uint
{
    /// <summary>Split node with both children, marked. Retail: 'BPIN' (0x4250494E).</summary>
    SplitBothChildren = 0x4250494E,

    /// <summary>Split node with a positive child only, marked. Retail: 'BPIn' (0x4250496E).</summary>
    SplitPositiveChild = 0x4250496E,

    /// <summary>Split node with a negative child only, marked. Retail: 'BpIN' (0x4270494E).</summary>
    SplitNegativeChild = 0x4270494E,

    /// <summary>Split node with both children, unmarked. Retail: 'BPnN' (0x42506E4E).</summary>
    SplitBothChildrenUnmarked = 0x42506E4E,

    /// <summary>Split node with a positive child only, unmarked. Retail: 'BPnn' (0x42506E6E).</summary>
    SplitPositiveChildUnmarked = 0x42506E6E,

    /// <summary>Split node with a negative child only, unmarked. Retail: 'BpnN' (0x42706E4E).</summary>
    SplitNegativeChildUnmarked = 0x42706E4E,

    /// <summary>A leaf: a polygon list with a bounding sphere and a solid flag. Retail: 'LEAF' (0x4C454146).</summary>
    Leaf = 0x4C454146,

    /// <summary>A drawing BSP's portal node (not used by the physics queries). Retail: 'PORT' (0x504F5254).</summary>
    Portal = 0x504F5254,
}
