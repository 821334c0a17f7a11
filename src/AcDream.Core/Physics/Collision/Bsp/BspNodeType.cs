namespace AcDream.Core.Physics.Collision.Bsp;

/// <summary>
/// The kind of a BSP node, as retail stores it: a four-character tag read as a big-endian integer
/// (<c>BSPNODE::type</c>, acclient.h:32157; tags decoded from <c>BSPNODE::UnPack</c>, acclient.c:363185). For the split
/// nodes, 'P'/'p' says whether a positive child is stored and 'N'/'n' (last letter) whether a negative child is stored.
/// </summary>
public enum BspNodeType : uint
{
    /// <summary>Split node with both children. Retail: 'BPIN' (0x4250494E).</summary>
    BPIN = 0x4250494E,

    /// <summary>Split node with a positive child only. Retail: 'BPIn' (0x4250496E).</summary>
    BPIn = 0x4250496E,

    /// <summary>Split node with a negative child only. Retail: 'BpIN' (0x4270494E).</summary>
    BpIN = 0x4270494E,

    /// <summary>Split node with both children. Retail: 'BPnN' (0x42506E4E).</summary>
    BPnN = 0x42506E4E,

    /// <summary>Split node with a positive child only. Retail: 'BPnn' (0x42506E6E).</summary>
    BPnn = 0x42506E6E,

    /// <summary>Split node with a negative child only. Retail: 'BpnN' (0x42706E4E).</summary>
    BpnN = 0x42706E4E,

    /// <summary>A leaf: a polygon list with a bounding sphere and a solid flag. Retail: 'LEAF' (0x4C454146).</summary>
    Leaf = 0x4C454146,

    /// <summary>A drawing BSP's portal node (not used by the physics queries). Retail: 'PORT' (0x504F5254).</summary>
    Portal = 0x504F5254,
}
