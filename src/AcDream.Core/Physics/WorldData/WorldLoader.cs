using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.WorldData;

/// <summary>
/// The client's one door to the world as retail builds it from its data: give it landblock ids and it reads, from the
/// client's <see cref="IRetailDataSource"/>, each block's terrain, indoor cells, buildings, static objects and scenery, and
/// builds them into the world in retail's order — the buildings of every block first, then each block's static objects and
/// scenery (<c>LScape::grab_visible_cells</c>'s two passes). It returns what it built (<see cref="WorldBlock"/>) for a
/// renderer. Every entry is read and every object's shape built before the world changes, so a bad entry changes nothing.
/// </summary>
/// <remarks>The world must sweep with a <see cref="RetailSweep"/> over <see cref="WorldCells"/> (its objects collide through
/// the cells' shadow lists). Call between ticks. docs/world.md is the client's guide.</remarks>
public sealed partial class WorldLoader
{
    private readonly PhysicsWorld _world;
    private readonly WorldCells _cells;
    private readonly RetailSweep _sweep;
    private readonly IRetailDataSource _source;
    private readonly Dictionary<uint, LoadedBlock> _blocks = new();

    /// <summary>Creates the door for <paramref name="world"/>, reading <paramref name="source"/>.</summary>
    /// <exception cref="ArgumentNullException">An argument is null.</exception>
    /// <exception cref="ArgumentException">The world does not sweep with a <see cref="RetailSweep"/> over
    /// <see cref="WorldCells"/>.</exception>
    /// <exception cref="RetailDataFormatException">The source's region entry (<see cref="DerethRegionId"/>) has bad bytes.</exception>
    public WorldLoader(PhysicsWorld world, IRetailDataSource source)
    {
        ArgumentNullException.ThrowIfNull(world);
        ArgumentNullException.ThrowIfNull(source);
        if (world.Sweep is not RetailSweep { Cells: WorldCells cells } sweep)
        {
            throw new ArgumentException("The world must sweep with a RetailSweep over WorldCells.", nameof(world));
        }

        _world = world;
        _cells = cells;
        _sweep = sweep;
        _source = source;
        Objects = new ObjectFactory(source);
        Region = ReadRegion(source);
    }

    /// <summary>The landscape that decides which blocks this door holds, or null (the client loads and unloads blocks).</summary>
    internal Landscape? Landscape { get; set; }

    internal PhysicsWorld World => _world;

    internal IRetailDataSource Source => _source;

    /// <summary>The factory the door makes objects with (a client makes creatures and items with it too).</summary>
    public ObjectFactory Objects { get; }

    /// <summary>The world's cells.</summary>
    public WorldCells Cells => _cells;

    /// <summary>The blocks loaded by this door, by id.</summary>
    public IReadOnlyCollection<uint> LoadedBlockIds => _blocks.Keys;

    /// <summary>The scenery of a block (retail <c>get_land_scenes</c> up to <c>makeObject</c>), or null for none: a test seam
    /// that replaces the region's placement (<see cref="Region"/>).</summary>
    internal Func<uint, LandBlock, IReadOnlyList<SceneryItem>>? ScenerySource { get; set; }

    /// <summary>
    /// Builds landblocks <paramref name="blockIds"/> into the world: terrain and indoor cells, then every block's
    /// buildings, then each block's static objects (with the restriction table applied to its land cells), scenery and
    /// indoor cells' static objects.
    /// </summary>
    /// <param name="blockIds">Landblock ids (0xXXYYFFFF; any cell id of the block is accepted), each at most once, none loaded
    /// by this door already.</param>
    /// <returns>One <see cref="WorldBlock"/> per id, in the order given.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="blockIds"/> is null.</exception>
    /// <exception cref="ArgumentException">An id is outside the world, repeated or already loaded, or an entry the terrain or
    /// cells need (0xXXYYFFFF, 0xXXYYFFFE, an indoor cell, an environment) is missing from the source; nothing has been
    /// added. (A missing Setup or GfxObj only fails its object: <see cref="WorldBlock.MissingIds"/>.)</exception>
    /// <exception cref="RetailDataFormatException">An entry's bytes are bad; nothing has been added.</exception>
    /// <exception cref="InvalidOperationException">Called from inside a tick of the world, or the door belongs to a
    /// <see cref="WorldData.Landscape"/> (which decides the blocks); nothing has been added.</exception>
    public IReadOnlyList<WorldBlock> Load(params uint[] blockIds)
    {
        ArgumentNullException.ThrowIfNull(blockIds);
        if (_world.IsTicking)
        {
            throw new InvalidOperationException("The world cannot be built from inside its tick.");
        }

        ThrowIfLandscape();

        // Read everything first: a bad or missing entry throws before the world changes.
        var pending = new PendingBlock[blockIds.Length];
        var seen = new HashSet<uint>();
        for (int i = 0; i < blockIds.Length; i++)
        {
            uint block = LandDefs.BlockIdOf(blockIds[i]);
            if (!LandDefs.BlockIdToLCoord(block, out _, out _))
            {
                throw new ArgumentException($"Landblock 0x{block:X8} lies outside the world.", nameof(blockIds));
            }

            if (!seen.Add(block) || _blocks.ContainsKey(block))
            {
                throw new ArgumentException($"Landblock 0x{block:X8} is repeated or already loaded.", nameof(blockIds));
            }

            pending[i] = Read(block, withEnvCells: true);
        }

        // Now change the world: the terrain and cells of every block, so that shadows reach across block edges; then
        // LScape::grab_visible_cells' two passes.
        var loaded = new LoadedBlock[pending.Length];
        for (int i = 0; i < pending.Length; i++)
        {
            loaded[i] = AddCells(pending[i]);
        }

        GrabVisibleCells(loaded);
        var result = new WorldBlock[pending.Length];
        for (int i = 0; i < pending.Length; i++)
        {
            result[i] = loaded[i].Block!;
        }

        return result;
    }

    /// <summary>
    /// Takes landblock <paramref name="blockId"/> out of the world: its static objects and scenery leave the world, its
    /// buildings leave their cells, then its indoor cells and terrain go (objects standing on them go to the lost cell).
    /// </summary>
    /// <returns>False when this door has not loaded the block.</returns>
    /// <exception cref="InvalidOperationException">Called from inside a tick of the world, or the door belongs to a
    /// <see cref="WorldData.Landscape"/>; nothing changes.</exception>
    // retail: CLandBlock::Destroy (acclient.c:351958)
    public bool Unload(uint blockId)
    {
        if (_world.IsTicking)
        {
            throw new InvalidOperationException("The world cannot be changed from inside its tick.");
        }

        ThrowIfLandscape();
        uint block = LandDefs.BlockIdOf(blockId);
        if (!_blocks.TryGetValue(block, out LoadedBlock? b))
        {
            return false;
        }

        Release(b);
        return true;
    }

    private void ThrowIfLandscape()
    {
        if (Landscape is not null)
        {
            throw new InvalidOperationException("This door belongs to a Landscape, which loads and releases its blocks.");
        }
    }
}
