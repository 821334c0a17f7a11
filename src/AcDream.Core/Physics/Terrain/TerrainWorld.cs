using System;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Terrain;

/// <summary>
/// The outdoor world: every loaded landblock's terrain, addressed by landblock column and row (a flat 255 × 255 array,
/// no hashing on the query path). Retail keeps the loaded blocks in <c>LScape</c> around the viewer; this class is that
/// state made explicit, so several worlds can coexist (no global state).
/// </summary>
/// <remarks>
/// Queries allocate nothing. Landblocks are added and removed between ticks; the class is not thread-safe for writes.
/// </remarks>
public sealed partial class TerrainWorld : ICellSource
{
    private readonly LandBlock?[] _blocks = new LandBlock?[LandDefs.LandblocksPerSide * LandDefs.LandblocksPerSide];

    /// <summary>Creates an empty world whose landblocks are built with <paramref name="heightTable"/>.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="heightTable"/> is null.</exception>
    public TerrainWorld(LandHeightTable heightTable)
    {
        ArgumentNullException.ThrowIfNull(heightTable);
        HeightTable = heightTable;
    }

    /// <summary>The land height table used by <see cref="AddLandBlock(uint, ReadOnlySpan{byte}, ReadOnlySpan{ushort})"/>.</summary>
    public LandHeightTable HeightTable { get; }

    /// <summary>The number of loaded landblocks.</summary>
    public int LandBlockCount { get; private set; }

    /// <summary>Builds a landblock from its retail data with this world's height table and adds it (replacing any
    /// landblock already at its place).</summary>
    /// <exception cref="ArgumentException">See <see cref="LandBlock(uint, ReadOnlySpan{byte}, ReadOnlySpan{ushort}, LandHeightTable)"/>.</exception>
    public LandBlock AddLandBlock(uint blockId, ReadOnlySpan<byte> height, ReadOnlySpan<ushort> terrain)
    {
        var block = new LandBlock(blockId, height, terrain, HeightTable);
        AddLandBlock(block);
        return block;
    }

    /// <summary>Adds a built landblock, replacing any landblock already at its place.</summary>
    /// <remarks>Objects of the world these cells serve that stand in the block, or whose shadows reach into it, are listed in
    /// the new cells (their shadows leave a replaced block's old cells); their positions, cells and contact state are kept, so
    /// terrain that changed height under a resting object is met at its next move. Objects lost in the block's cells (their
    /// block was removed, or they were placed there while it was not loaded) come back: each is placed again at its stored
    /// position, sliding (retail <c>CObjectMaint::InitObjCell</c>). Call between ticks.</remarks>
    /// <exception cref="ArgumentNullException"><paramref name="block"/> is null.</exception>
    /// <exception cref="InvalidOperationException">Called from a callback inside the tick of the world these cells serve;
    /// nothing changes.</exception>
    public void AddLandBlock(LandBlock block) => AddLandBlock(block, initObjects: true);

    /// <summary>Adds a built landblock; with <paramref name="initObjects"/> the objects lost in its cells come back at once,
    /// else the caller brings them back later (the world loader, after the block's static objects:
    /// <c>LScape::grab_visible_cells</c>' second pass).</summary>
    internal void AddLandBlock(LandBlock block, bool initObjects)
    {
        ArgumentNullException.ThrowIfNull(block);
        ThrowIfOwnerTicking();
        int i = Index(block.BlockX, block.BlockY);
        if (_blocks[i] is null)
        {
            LandBlockCount++;
        }

        _blocks[i] = block;
        // non-retail: objects re-homed into the new cells (retail never swaps the cells under an object)
        OwnerWorld?.RehomeObjectsIn(BlockPrefix(block.BlockX, block.BlockY), 0xFFFF0000u);
        if (initObjects)
        {
            OwnerWorld?.InitLandBlockObjCells(block);
        }
    }

    /// <summary>Removes the landblock that contains <paramref name="cellOrBlockId"/>; false when none was loaded.</summary>
    /// <param name="cellOrBlockId">Any id <c>0xXXYY....</c> of the landblock.</param>
    /// <param name="leftWorld">When given, receives every object that left the world because it stood in one of the block's
    /// outdoor cells (in the world's order; children go with their parent and are not listed).</param>
    /// <remarks>Objects of the world these cells serve that stand in one of the block's outdoor cells leave the world, as
    /// retail's lost cell: <see cref="Objects.PhysicsObj.CellId"/> 0, no shadows, their last position kept, not simulated
    /// until placed again (<see cref="Objects.PhysicsObj.EnterWorld"/>, <see cref="Objects.PhysicsObj.SetPosition"/> or a
    /// server report) or until the block is added again, which places them back where they were. They remain the world's
    /// objects. Objects elsewhere whose shadows reached into the block keep only
    /// their shadows in cells still loaded. Indoor cells are not part of a landblock here: objects in them stay. Call between
    /// ticks.</remarks>
    /// <exception cref="InvalidOperationException">Called from a callback inside the tick of the world these cells serve;
    /// nothing changes.</exception>
    public bool RemoveLandBlock(uint cellOrBlockId, System.Collections.Generic.ICollection<Objects.PhysicsObj>? leftWorld = null)
    {
        ThrowIfOwnerTicking();
        if (!TryBlockIndex(cellOrBlockId, out int i) || _blocks[i] is null)
        {
            return false;
        }

        _blocks[i] = null;
        LandBlockCount--;
        // non-retail: objects in the block leave the world (retail unloads blocks only away from objects it simulates)
        OwnerWorld?.SendObjectsOutOfWorld(cellOrBlockId & 0xFFFF0000u, 0xFFFF0000u, leftWorld);
        return true;
    }

    private void ThrowIfOwnerTicking()
    {
        if (OwnerWorld is { IsTicking: true })
        {
            throw new InvalidOperationException("Landblocks cannot change inside a tick of the world whose objects stand in them.");
        }
    }

    private static uint BlockPrefix(int blockX, int blockY) => ((uint)blockX << 24) | ((uint)blockY << 16);

    /// <summary>The loaded landblock at column <paramref name="blockX"/>, row <paramref name="blockY"/>, or null (also
    /// for coordinates outside 0..254).</summary>
    public LandBlock? GetLandBlock(int blockX, int blockY)
    {
        if ((uint)blockX >= LandDefs.LandblocksPerSide || (uint)blockY >= LandDefs.LandblocksPerSide)
        {
            return null;
        }

        return _blocks[Index(blockX, blockY)];
    }

    /// <summary>The loaded landblock that contains <paramref name="cellOrBlockId"/> (any id <c>0xXXYY....</c>), or null.</summary>
    public LandBlock? GetLandBlock(uint cellOrBlockId) =>
        TryBlockIndex(cellOrBlockId, out int i) ? _blocks[i] : null;

    /// <summary>
    /// The land cell with id <paramref name="cellId"/>, or null when the id is not an outdoor cell id or its landblock
    /// is not loaded.
    /// </summary>
    // retail: LScape::get_landcell (acclient.c:307511) / CLandCell::Get (acclient.c:354915)
    public LandCell? GetLandCell(uint cellId)
    {
        if (!LandDefs.IsOutdoorCell(cellId) || !TryBlockIndex(cellId, out int i))
        {
            return null;
        }

        return _blocks[i]?.GetLandCell(cellId);
    }

    private static int Index(int blockX, int blockY) => blockX * LandDefs.LandblocksPerSide + blockY;

    private static bool TryBlockIndex(uint id, out int index)
    {
        int bx = (int)(id >> 24);
        int by = (int)((id >> 16) & 0xFF);
        if (bx >= LandDefs.LandblocksPerSide || by >= LandDefs.LandblocksPerSide)
        {
            index = 0;
            return false;
        }

        index = Index(bx, by);
        return true;
    }

    /// <summary>The world whose objects' shadows these cells hold (set when a world takes a sweep over them).</summary>
    internal PhysicsWorld? OwnerWorld { get; set; }

    /// <summary>The loaded outdoor cell <paramref name="cellId"/>, or null (land cells only: indoor cells come from <see cref="WorldCells"/>).</summary>
    // retail: CObjCell::GetVisible (acclient.c:346416) -> CLandCell::Get (acclient.c:354915) -> LScape::get_landcell
    public ObjCell? GetVisible(uint cellId) => GetLandCell(cellId);
}
