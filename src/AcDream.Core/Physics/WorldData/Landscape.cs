using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.WorldData;

/// <summary>
/// The world that follows the player, as retail's landscape does (<c>LScape</c> driven by
/// <c>CellManager::ChangePosition</c>): a grid of landblocks around the load point at falling levels of detail, of which the
/// 3 × 3 around the player are built into the world (terrain, indoor cells, buildings, static objects, scenery); a dungeon
/// holds only its own indoor cells; a building's interior that sees outside keeps the landscape.
/// </summary>
/// <remarks>
/// <para>Call <see cref="ChangePosition"/> every frame before the world's tick with the player's position (retail calls it
/// from <c>SmartBox::UseTime</c>); it does nothing until the player's cell changes. Place the player after the first call (its
/// cells exist only then).</para>
/// <para>Every entry a change needs is read before the world changes: a data source that throws or answers bad bytes leaves
/// the landscape and the world as they were, and the next call can succeed. docs/world.md, "The world follows the player",
/// is the client's guide.</para>
/// </remarks>
public sealed partial class Landscape
{
    /// <summary>Retail's default mid radius (the <c>LScape</c> constructor): a grid of 11 × 11 blocks.</summary>
    public const int DefaultMidRadius = 5;

    /// <summary>The largest mid radius accepted (a grid of 129 × 129 blocks).</summary>
    // non-retail: retail's SetMidRadius has no upper bound; 64 keeps the grid a reasonable size (docs/divergences.md)
    public const int MaxMidRadius = 64;

    private readonly WorldLoader _loader;
    private readonly PhysicsWorld _world;
    private readonly IRetailDataSource _source;

    // Retail land_blocks, [x * MidWidth + y]; null while there is no grid.
    private LandscapeBlock?[]? _landBlocks;

    // CellManager's load_pos cell and curr_cell.
    private uint _loadPosCellId;
    private ObjCell? _currCell;

    /// <summary>Creates the landscape over <paramref name="loader"/>'s world and data source. The landscape decides which
    /// blocks the loader holds from now on: the loader's own <see cref="WorldLoader.Load"/> and <see cref="WorldLoader.Unload"/>
    /// are refused.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="loader"/> is null.</exception>
    /// <exception cref="ArgumentException">The loader already holds blocks, or belongs to another landscape.</exception>
    // retail: LScape::LScape (acclient.c:306925)
    public Landscape(WorldLoader loader)
    {
        ArgumentNullException.ThrowIfNull(loader);
        if (loader.Landscape is not null || loader.LoadedBlockIds.Count != 0)
        {
            throw new ArgumentException("The loader already holds blocks or belongs to another landscape.", nameof(loader));
        }

        _loader = loader;
        _world = loader.World;
        _source = loader.Source;
        loader.Landscape = this;
    }

    /// <summary>The door the landscape builds blocks with (its <see cref="WorldLoader.Objects"/> makes creatures and items).</summary>
    public WorldLoader Loader => _loader;

    /// <summary>Blocks from the load point to the grid's edge (retail <c>mid_radius</c>).</summary>
    public int MidRadius { get; private set; } = DefaultMidRadius;

    /// <summary>Blocks along the grid's side, <c>2 × MidRadius + 1</c> (retail <c>mid_width</c>).</summary>
    public int MidWidth => 2 * MidRadius + 1;

    /// <summary>When true, a dungeon cell keeps the landscape loaded (retail <c>keep_lscape_loaded</c>); default false.</summary>
    public bool KeepLandscapeLoaded { get; set; }

    /// <summary>The outdoor cell the grid is centred on (retail <c>loaded_cell_id</c>); 0 without a grid.</summary>
    public uint LoadedCellId { get; private set; }

    /// <summary>The cell of the last position given, when it was found (retail <c>CellManager::curr_cell</c>); 0 otherwise.</summary>
    public uint CurrentCellId => _currCell?.Id ?? 0;

    /// <summary>True while there is a grid.</summary>
    public bool HasGrid => _landBlocks is not null;

    /// <summary>The indoor cells the world holds (retail's visible-cell table): the cells the doors of the full-detail blocks'
    /// buildings see (their stab lists) and, in an indoor cell, that cell and the cells it sees; in the order they came.</summary>
    public IReadOnlyList<EnvCell> VisibleCells => _loader.VisibleEnvCells;

    /// <summary>The static objects of the visible indoor cell <paramref name="cellId"/> (for a renderer), empty when the cell
    /// is not visible.</summary>
    public IReadOnlyList<WorldObject> GetCellObjects(uint cellId) =>
        _loader.GetVisibleCell(cellId)?.Objects ?? (IReadOnlyList<WorldObject>)Array.Empty<WorldObject>();

    /// <summary>Sets the grid's radius, while there is no grid (before the first change, or after <see cref="ReleaseAll"/>).</summary>
    /// <returns>False, with nothing changed, when there is a grid.</returns>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="radius"/> is below 1 or above <see cref="MaxMidRadius"/>.</exception>
    // retail: LScape::SetMidRadius (acclient.c:306428)
    public bool SetMidRadius(int radius)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(radius, 1);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(radius, MaxMidRadius);
        if (_landBlocks is not null)
        {
            return false;
        }

        MidRadius = radius;
        return true;
    }

    /// <summary>The grid's block at column <paramref name="x"/>, row <paramref name="y"/>; null outside the grid, without a
    /// grid, or where the world ends or the data source has no block.</summary>
    public LandscapeBlock? GetBlock(int x, int y)
    {
        LandscapeBlock?[]? grid = _landBlocks;
        int w = MidWidth;
        return grid is null || (uint)x >= (uint)w || (uint)y >= (uint)w ? null : grid[x * w + y];
    }

    /// <summary>The grid's full-detail block holding outdoor cell <paramref name="cellId"/> (or the block id
    /// <c>0xXXYYFFFF</c>), or null (also for an indoor cell id, as retail).</summary>
    // retail: LScape::get_landblock (acclient.c:307460)
    public LandscapeBlock? GetLandBlock(uint cellId)
    {
        if ((cellId & 0xFFFFu) == 0xFFFFu)
        {
            cellId = (cellId & 0xFFFF0000u) | 1u; // a block id: its first cell
        }

        LandscapeBlock?[]? grid = _landBlocks;
        if (grid is null || !LandDefs.InboundValidCellId(cellId) || (cellId & 0xFFFFu) >= LandDefs.FirstEnvCell
            || !LandDefs.BlockIdToLCoord(LoadedCellId, out int lx, out int ly) || !LandDefs.GidToLCoord(cellId, out int x, out int y))
        {
            return null;
        }

        int ix = (x + 8 * MidRadius - lx) >> 3;
        int iy = (y + 8 * MidRadius - ly) >> 3;
        int w = MidWidth;
        if (ix < 0 || iy < 0 || ix >= w || iy >= w)
        {
            return null;
        }

        LandscapeBlock? b = grid[ix * w + iy];
        return b is not null && b.IsFullDetail ? b : null;
    }

    /// <summary>The grid's blocks, column by column (null slots skipped).</summary>
    public IEnumerable<LandscapeBlock> Blocks
    {
        get
        {
            LandscapeBlock?[]? grid = _landBlocks;
            if (grid is null)
            {
                yield break;
            }

            foreach (LandscapeBlock? b in grid)
            {
                if (b is not null)
                {
                    yield return b;
                }
            }
        }
    }

    /// <summary>Releases everything: every block of the grid (its objects destroyed, the objects standing in it sent to their
    /// lost cells) and a dungeon's interior. The next <see cref="ChangePosition"/> builds again.</summary>
    /// <exception cref="InvalidOperationException">Called from inside a tick of the world; nothing changes.</exception>
    // retail: CellManager::Reset -> LScape::release_all (acclient.c:306380)
    public void ReleaseAll()
    {
        ThrowIfTicking();
        var released = new List<uint>();
        ReleaseGrid(released);
        _loader.ReleaseVisibleCells(new List<uint>());
        _loadPosCellId = 0;
        _currCell = null;
    }

    private void ThrowIfTicking()
    {
        if (_world.IsTicking)
        {
            throw new InvalidOperationException("The landscape cannot change inside a tick of its world.");
        }
    }

    // retail: LScape::release_all (acclient.c:306380): every block released, the grid dropped
    private void ReleaseGrid(List<uint> released)
    {
        LandscapeBlock?[]? grid = _landBlocks;
        if (grid is not null)
        {
            foreach (LandscapeBlock? b in grid)
            {
                if (b is not null)
                {
                    ReleaseBlock(b, released);
                }
            }
        }

        _landBlocks = null;
        LoadedCellId = 0;
    }

    // retail: CLandBlock::release_all (acclient.c:352086): the block's world part goes
    private void ReleaseBlock(LandscapeBlock b, List<uint> released)
    {
        if (b.Loaded is not null)
        {
            _loader.Release(b.Loaded);
            b.Loaded = null;
            released.Add(b.BlockId);
        }
    }
}
