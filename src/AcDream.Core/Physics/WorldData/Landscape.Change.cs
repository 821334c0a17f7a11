using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.WorldData;

// CellManager::ChangePosition and LScape::update_loadpoint: what a new position does to the grid and the world.
public sealed partial class Landscape
{
    /// <summary>
    /// The player is at <paramref name="position"/>: when its cell differs from the last call's (or that cell was not found),
    /// the landscape follows — outdoors, the grid shifts around the new cell's block (blocks entering are read, blocks
    /// leaving released) and the 3 × 3 around it are built into the world; in a dungeon cell the landscape is released and
    /// the dungeon's indoor cells are held alone; a building's cell that sees outside keeps the landscape around the outdoor
    /// cell under it. Then the full-detail blocks' buildings, static objects and scenery are made (first time) and the objects
    /// lost in their cells come back.
    /// </summary>
    /// <param name="position">The player's position: a valid cell id (0 releases everything, as retail's reset) and a frame
    /// in the position domain (<see cref="InputLimits"/>; not read while the cell is the last call's).</param>
    /// <param name="blocking">True for a teleport or a login: everything is released first, then built again around the
    /// new cell (retail releases on the blocking call and builds once its prefetch completes; the library's data source is
    /// synchronous, so both happen in this call).</param>
    /// <returns>What happened (<see cref="LandscapeChange"/>); <see cref="LandscapeStatus.NoCell"/>, with nothing changed, when
    /// the cell's landblock is missing from the data source or an indoor cell is not one of its block's cells.</returns>
    /// <exception cref="ArgumentException">The cell id is not a valid cell of the world, or the frame is outside the position
    /// domain; nothing changes.</exception>
    /// <exception cref="Format.RetailDataFormatException">An entry's bytes are bad; nothing changes.</exception>
    /// <exception cref="InvalidOperationException">Called from inside a tick of the world; nothing changes.</exception>
    // retail: CellManager::ChangePosition (acclient.c:146645)
    public LandscapeChange ChangePosition(in Position position, bool blocking = false)
    {
        ThrowIfTicking();
        uint cellId = position.ObjCellId;
        if (cellId == 0)
        {
            // retail: CellManager::Reset
            bool had = _landBlocks is not null || _loader.VisibleCells.Count != 0 || _currCell is not null;
            ReleaseAll();
            return had ? LandscapeChange.ReleasedAll : LandscapeChange.SameCell;
        }

        // The frame is not read while the cell stays the same (retail compares the cell id only): the per-frame call costs
        // one compare.
        if (_loadPosCellId == cellId && _currCell is not null)
        {
            return LandscapeChange.SameCell;
        }

        if (!LandDefs.InboundValidCellId(cellId))
        {
            throw new ArgumentException($"Cell 0x{cellId:X8} is not a cell of the world.", nameof(position));
        }

        InputLimits.ThrowIfOutside(position, nameof(position));

        return Change(position, blocking);
    }

    private LandscapeChange Change(in Position position, bool blocking)
    {
        uint cellId = position.ObjCellId;
        uint blockId = LandDefs.BlockIdOf(cellId);
        bool outdoors = (cellId & 0xFFFFu) < LandDefs.FirstEnvCell;

        // 1. Where the grid goes, read before anything changes. An indoor cell is read first: its flags decide.
        WorldLoader.VisibleCell? indoor = null;
        if (!outdoors && (indoor = FindIndoorCell(cellId)) is null)
        {
            return LandscapeChange.NoCell;
        }

        bool seenOutside = indoor is not null && (indoor.Entry.Flags & EnvCellEntry.SeenOutsideFlag) != 0;
        bool releaseGrid = blocking;
        uint loadPoint = 0;
        bool gridMoves = false;
        if (outdoors)
        {
            loadPoint = cellId;
        }
        else if (seenOutside)
        {
            // retail: Position::get_outside_cell_id (acclient.c:143773)
            uint outside = blockId;
            System.Numerics.Vector3 origin = position.Frame.Origin;
            loadPoint = LandDefs.AdjustToOutside(ref outside, ref origin) ? outside : 0u;
            releaseGrid |= loadPoint == 0;
        }
        else if (!KeepLandscapeLoaded)
        {
            releaseGrid = true;
        }

        LandscapeBlock?[]? grid = releaseGrid ? null : _landBlocks;
        SlotPlan[]? plan = null;
        LandscapeBlock[] leaving = Array.Empty<LandscapeBlock>();
        if (loadPoint != 0)
        {
            // retail: LScape::update_loadpoint (acclient.c:308282)
            bool refresh = !GetBlockShift(grid is null ? 0u : LoadedCellId, loadPoint, out int xShift, out int yShift);
            bool checkLoading = grid is not null && Array.IndexOf(grid, null) >= 0;
            gridMoves = xShift != 0 || yShift != 0 || grid is null || refresh || checkLoading;
            if (gridMoves)
            {
                plan = PlanUpdateBlock(grid, loadPoint, xShift, yShift, refresh, out leaving);
            }
        }

        // 2. An outdoor cell's block must be at full detail afterwards.
        if (outdoors && !WillBeFull(plan, grid, blockId))
        {
            return LandscapeChange.NoCell;
        }

        // 3. The visible cells after the change, and the ones to read: the indoor cell and its visible list (retail
        // CEnvCell::grab_visible_cells), then, outdoors or seeing outside, every full-detail block's stab list (the doors of
        // its buildings: LScape::grab_visible_cells' first pass).
        List<uint> visible = _visibleScratch;
        visible.Clear();
        if (indoor is not null)
        {
            AddVisible(visible, cellId);
            foreach (uint id in indoor.Entry.VisibleCells)
            {
                AddVisible(visible, id);
            }
        }

        bool grabLandscape = loadPoint != 0;
        if (grabLandscape)
        {
            AddStabLists(visible, plan, grid);
        }

        Dictionary<uint, WorldLoader.VisibleCell?> read = _readScratch;
        read.Clear();
        if (indoor is not null && _loader.GetVisibleCell(cellId) is null)
        {
            read[cellId] = indoor;
        }

        foreach (uint id in visible)
        {
            if (_loader.GetVisibleCell(id) is null && !read.ContainsKey(id))
            {
                read[id] = _loader.ReadVisibleCell(id);
            }
        }

        // 4. Change the world: the grid (releases, shift, levels of detail), the visible cells, then the landscape's two
        // passes over the full-detail blocks and the flush of the visible cells. Scratch lists kept by the landscape: a cell
        // change without a shift allocates little.
        List<uint> released = _releasedScratch;
        List<WorldLoader.LoadedBlock> built = _builtScratch;
        released.Clear();
        built.Clear();
        if (releaseGrid)
        {
            ReleaseGrid(released);
        }

        uint[] entered = Array.Empty<uint>(), left = Array.Empty<uint>();
        if (plan is not null)
        {
            ApplyGrid(plan, leaving, released, built, out entered, out left);
        }

        if (loadPoint != 0)
        {
            LoadedCellId = loadPoint;
        }

        List<uint> cellsReleased = _cellsReleasedScratch, cellsEntered = _cellsEnteredScratch;
        cellsReleased.Clear();
        cellsEntered.Clear();
        _loader.SetVisibleCells(visible, read, cellsReleased, cellsEntered);
        read.Clear();
        List<WorldLoader.LoadedBlock> grab = _grabScratch;
        grab.Clear();
        if (grabLandscape && _landBlocks is not null)
        {
            foreach (LandscapeBlock? b in _landBlocks)
            {
                if (b?.Loaded is not null)
                {
                    grab.Add(b.Loaded);
                }
            }
        }

        _loader.GrabVisibleCells(grab);
        grab.Clear();
        _loader.FlushCells();
        _currCell = _loader.Cells.GetVisible(cellId);
        _loadPosCellId = cellId;
        if (!gridMoves && built.Count == 0 && released.Count == 0 && cellsEntered.Count == 0 && cellsReleased.Count == 0)
        {
            return LandscapeChange.Moved;
        }

        var builtBlocks = new WorldBlock[built.Count];
        for (int i = 0; i < builtBlocks.Length; i++)
        {
            builtBlocks[i] = built[i].Block!;
        }

        return new LandscapeChange(LandscapeStatus.Updated, entered, left, builtBlocks, released.ToArray(),
            cellsEntered.ToArray(), cellsReleased.ToArray());
    }

    private static void AddVisible(List<uint> visible, uint id)
    {
        if (!visible.Contains(id))
        {
            visible.Add(id);
        }
    }

    // The stab lists of the blocks at full detail after the plan (or in the current grid), in grid order: each block's
    // buildings' doors' visible cells, without repeats.
    // retail: CLandBlock::grab_visible_cells (acclient.c:351600) over the stab list CBuildingObj::add_to_stablist
    // (acclient.c:719040) and CBldPortal::add_to_stablist (acclient.c:362422) built
    private static void AddStabLists(List<uint> visible, SlotPlan[]? plan, LandscapeBlock?[]? grid)
    {
        if (plan is not null)
        {
            foreach (SlotPlan s in plan)
            {
                if (s.Block is not null && s.Size == 1)
                {
                    AddStabList(visible, s.Promote?.Info ?? s.Block.Loaded?.Pending.Info);
                }
            }
        }
        else if (grid is not null)
        {
            foreach (LandscapeBlock? b in grid)
            {
                if (b is not null && b.IsFullDetail)
                {
                    AddStabList(visible, b.Loaded?.Pending.Info);
                }
            }
        }
    }

    private static void AddStabList(List<uint> visible, LandBlockInfoEntry? info)
    {
        if (info is null)
        {
            return;
        }

        foreach (BuildingInfo b in info.Buildings)
        {
            foreach (BldPortalInfo door in b.Portals)
            {
                foreach (uint id in door.VisibleCells)
                {
                    AddVisible(visible, id);
                }
            }
        }
    }

    private readonly List<uint> _visibleScratch = new();
    private readonly List<uint> _cellsReleasedScratch = new();
    private readonly List<uint> _cellsEnteredScratch = new();
    private readonly Dictionary<uint, WorldLoader.VisibleCell?> _readScratch = new();
    private readonly List<uint> _releasedScratch = new();
    private readonly List<WorldLoader.LoadedBlock> _builtScratch = new();
    private readonly List<WorldLoader.LoadedBlock> _grabScratch = new();

    // retail: the generate / notify_change_size pass of LScape::update_block (acclient.c:307785, lines 308169–308205), after
    // its shift: leaving blocks released, the new grid in place, then each slot's level of detail, demoting or building.
    private void ApplyGrid(SlotPlan[] plan, LandscapeBlock[] leaving, List<uint> released, List<WorldLoader.LoadedBlock> built,
        out uint[] entered, out uint[] left)
    {
        left = new uint[leaving.Length];
        for (int i = 0; i < leaving.Length; i++)
        {
            ReleaseBlock(leaving[i], released);
            left[i] = leaving[i].BlockId;
        }

        int w = MidWidth;
        var grid = new LandscapeBlock?[w * w];
        var enteredList = new List<uint>();
        for (int ix = 0; ix < w; ix++)
        {
            for (int iy = 0; iy < w; iy++)
            {
                ref SlotPlan s = ref plan[ix * w + iy];
                LandscapeBlock? b = s.Block;
                grid[ix * w + iy] = b;
                if (b is null)
                {
                    continue;
                }

                if (s.Fetched)
                {
                    enteredList.Add(b.BlockId);
                }

                b.GridX = ix;
                b.GridY = iy;
                b.Size = s.Size;
                b.Direction = s.Dir;
                if (s.Demote)
                {
                    // retail: CLandBlock::notify_change_size (acclient.c:352429)
                    ReleaseBlock(b, released);
                }
                else if (s.Promote is not null)
                {
                    b.Loaded = _loader.AddCells(s.Promote);
                    built.Add(b.Loaded);
                }
            }
        }

        _landBlocks = grid;
        entered = enteredList.ToArray();
    }

    // True when block blockId will be at full detail after the plan (or in the current grid, when the grid does not move).
    private bool WillBeFull(SlotPlan[]? plan, LandscapeBlock?[]? grid, uint blockId)
    {
        if (plan is not null)
        {
            foreach (SlotPlan s in plan)
            {
                if (s.Block is not null && s.Block.BlockId == blockId)
                {
                    return s.Size == 1;
                }
            }

            return false;
        }

        if (grid is null)
        {
            return false;
        }

        foreach (LandscapeBlock? b in grid)
        {
            if (b is not null && b.BlockId == blockId)
            {
                return b.IsFullDetail;
            }
        }

        return false;
    }

    // The indoor cell from the visible-cell table, or read from the source (null when the source lacks it or it is not one
    // of its block's cells).
    private WorldLoader.VisibleCell? FindIndoorCell(uint cellId)
    {
        WorldLoader.VisibleCell? visible = _loader.GetVisibleCell(cellId);
        if (visible is not null)
        {
            return visible;
        }

        uint blockId = LandDefs.BlockIdOf(cellId);
        if (!_source.TryGetEntry(blockId, out ReadOnlyMemory<byte> landBytes) || !LandBlockEntry.UnPack(landBytes.Span).HasInfo
            || !_source.TryGetEntry((blockId & 0xFFFF0000u) | 0xFFFEu, out ReadOnlyMemory<byte> infoBytes))
        {
            return null;
        }

        LandBlockInfoEntry info = LandBlockInfoEntry.UnPack(infoBytes.Span);
        return (uint)((cellId & 0xFFFFu) - LandDefs.FirstEnvCell) >= (uint)info.NumCells ? null : _loader.ReadVisibleCell(cellId);
    }
}
