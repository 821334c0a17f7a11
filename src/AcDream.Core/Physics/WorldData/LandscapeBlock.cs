using AcDream.Core.Physics.Data;

namespace AcDream.Core.Physics.WorldData;

/// <summary>Where a landscape block lies from the viewer's block (retail <c>LandDefs::Direction</c>): the side a lower level
/// of detail's edge meets a finer neighbour on, for a renderer stitching the levels.</summary>
public enum LandscapeDirection
{
    /// <summary>The viewer's block, or a block with no coarser edge (retail <c>IN_VIEWER_BLOCK</c>).</summary>
    InViewerBlock = 0,

    /// <summary>Retail <c>NORTH_OF_VIEWER</c> (+y).</summary>
    North = 1,

    /// <summary>Retail <c>SOUTH_OF_VIEWER</c> (−y).</summary>
    South = 2,

    /// <summary>Retail <c>EAST_OF_VIEWER</c> (+x).</summary>
    East = 3,

    /// <summary>Retail <c>WEST_OF_VIEWER</c> (−x).</summary>
    West = 4,

    /// <summary>Retail <c>NORTHWEST_OF_VIEWER</c>.</summary>
    Northwest = 5,

    /// <summary>Retail <c>SOUTHWEST_OF_VIEWER</c>.</summary>
    Southwest = 6,

    /// <summary>Retail <c>NORTHEAST_OF_VIEWER</c>.</summary>
    Northeast = 7,

    /// <summary>Retail <c>SOUTHEAST_OF_VIEWER</c>.</summary>
    Southeast = 8,
}

/// <summary>
/// One block of the <see cref="Landscape"/>'s grid (retail <c>LScape::land_blocks</c>): its id, its place in the grid, its
/// level of detail and, at full detail, what the world holds of it.
/// </summary>
/// <remarks>Only full-detail blocks (the 3 × 3 around the load point, <see cref="SideCellCount"/> 8) have land cells physics
/// can reach, buildings, static objects and scenery; the other levels matter only for drawing.</remarks>
public sealed class LandscapeBlock
{
    internal LandscapeBlock(uint blockId, LandBlockEntry entry)
    {
        BlockId = blockId;
        Entry = entry;
    }

    /// <summary>The landblock id, <c>0xXXYYFFFF</c>.</summary>
    public uint BlockId { get; }

    /// <summary>The landblock entry (heights and terrain types, as read), for drawing it at any level.</summary>
    public LandBlockEntry Entry { get; }

    /// <summary>Column of the grid, 0 at the west edge (retail's first index of <c>land_blocks</c>).</summary>
    public int GridX { get; internal set; }

    /// <summary>Row of the grid, 0 at the south edge.</summary>
    public int GridY { get; internal set; }

    /// <summary>Retail's size from <c>LScape::get_block_orient</c>: 1 within one block of the load point, 2 at two, 4 at
    /// three or four, 8 beyond.</summary>
    public int Size { get; internal set; }

    /// <summary>Cells along a side at this level of detail, <c>8 / Size</c> (retail <c>side_cell_count</c>): 8 is full
    /// detail.</summary>
    public int SideCellCount => 8 / Size;

    /// <summary>Where the block lies from the load point's block, at its ring (retail <c>LandDefs::Direction</c>).</summary>
    public LandscapeDirection Direction { get; internal set; }

    /// <summary>True at full detail (<see cref="SideCellCount"/> 8): the block is in the world.</summary>
    public bool IsFullDetail => Size == 1;

    /// <summary>What the world holds of the block (terrain, indoor cells, buildings, static objects, scenery) while it is at
    /// full detail; null otherwise.</summary>
    public WorldBlock? World => Loaded?.Block;

    internal WorldLoader.LoadedBlock? Loaded { get; set; }
}
