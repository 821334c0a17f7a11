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
    /// <exception cref="InvalidOperationException">Called from inside a tick of the world; nothing has been added.</exception>
    public IReadOnlyList<WorldBlock> Load(params uint[] blockIds)
    {
        ArgumentNullException.ThrowIfNull(blockIds);
        if (_world.IsTicking)
        {
            throw new InvalidOperationException("The world cannot be built from inside its tick.");
        }

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

            pending[i] = Read(block);
        }

        // Now change the world: the terrain and cells of every block, so that shadows reach across block edges.
        foreach (PendingBlock p in pending)
        {
            _cells.Terrain.AddLandBlock(p.LandBlock);
            foreach (EnvCell c in p.EnvCells)
            {
                _cells.AddEnvCell(c);
            }
        }

        var result = new WorldBlock[pending.Length];
        var loaded = new LoadedBlock[pending.Length];
        for (int i = 0; i < pending.Length; i++)
        {
            loaded[i] = new LoadedBlock(pending[i]);
            _blocks.Add(pending[i].BlockId, loaded[i]);
            InitBuildings(loaded[i]);
        }

        for (int i = 0; i < pending.Length; i++)
        {
            InitStaticObjs(loaded[i]);
            InitEnvCellStatics(loaded[i]);
            PendingBlock p = pending[i];
            result[i] = new WorldBlock(p.BlockId, p.LandBlock, p.Info, p.EnvCells, loaded[i].Objects, loaded[i].Missing.ToArray());
        }

        return result;
    }

    /// <summary>
    /// Takes landblock <paramref name="blockId"/> out of the world: its static objects and scenery leave the world, its
    /// buildings leave their cells, then its indoor cells and terrain go (objects standing on them go to the lost cell).
    /// </summary>
    /// <returns>False when this door has not loaded the block.</returns>
    /// <exception cref="InvalidOperationException">Called from inside a tick of the world; nothing changes.</exception>
    // retail: CLandBlock::Destroy (acclient.c:351958)
    public bool Unload(uint blockId)
    {
        if (_world.IsTicking)
        {
            throw new InvalidOperationException("The world cannot be changed from inside its tick.");
        }

        uint block = LandDefs.BlockIdOf(blockId);
        if (!_blocks.Remove(block, out LoadedBlock? b))
        {
            return false;
        }

        DestroyStaticObjects(b);
        DestroyBuildings(b);
        foreach (EnvCell c in b.Pending.EnvCells)
        {
            _cells.RemoveEnvCell(c.CellId);
        }

        _cells.Terrain.RemoveLandBlock(block);
        return true;
    }

    // One block's entries, read and unpacked, with the shape of every object it will make.
    private PendingBlock Read(uint block)
    {
        LandBlockEntry land = LandBlockEntry.UnPack(Entry(block));
        Expect("CLandBlock", land.Id, block);
        LandBlock landBlock = land.ToLandBlock(_cells.Terrain.HeightTable);
        LandBlockInfoEntry? info = null;
        var envCells = new List<EnvCell>();
        var envEntries = new List<EnvCellEntry>();
        if (land.HasInfo)
        {
            uint infoId = (block & 0xFFFF0000u) | 0xFFFEu;
            info = LandBlockInfoEntry.UnPack(Entry(infoId));
            Expect("CLandBlockInfo", info.Id, infoId);
            var environments = new Dictionary<uint, EnvironmentEntry>();
            for (int i = 0; i < info.NumCells; i++)
            {
                EnvCellEntry cell = EnvCellEntry.UnPack(Entry(info.CellId(i)));
                Expect("CEnvCell", cell.Id, info.CellId(i), 8);
                if (!environments.TryGetValue(cell.EnvironmentId, out EnvironmentEntry? env))
                {
                    env = EnvironmentEntry.UnPack(Entry(cell.EnvironmentId));
                    Expect("CEnvironment", env.Id, cell.EnvironmentId);
                    environments.Add(cell.EnvironmentId, env);
                }

                envCells.Add(cell.ToEnvCell(env));
                envEntries.Add(cell);
            }

            // Every object's shape, so that a bad Setup or GfxObj throws now (a missing one fails its object later).
            foreach (BuildingInfo b in info.Buildings)
            {
                Objects.InitPartArrayModel(b.ModelId, out _);
            }

            foreach (StaticObjectInfo o in info.Objects)
            {
                Objects.InitPartArrayModel(o.Id, out _);
            }

            foreach (EnvCellEntry c in envEntries)
            {
                foreach (StaticObjectInfo o in c.StaticObjects)
                {
                    Objects.InitPartArrayModel(o.Id, out _);
                }
            }
        }

        IReadOnlyList<SceneryItem> scenery = ScenerySource is not null
            ? ScenerySource(block, landBlock) ?? Array.Empty<SceneryItem>()
            : RegionScenery(block, landBlock, info);
        foreach (SceneryItem s in scenery)
        {
            // non-retail: a placement outside the library's domains is refused before the world changes
            if (!InputLimits.IsScaleInDomain(s.Scale) || !s.Frame.IsValid() || !Spatial.VectorMath.IsFinite(s.Frame.Origin))
            {
                throw new ArgumentException($"Scenery 0x{s.ObjectId:X8} of block 0x{block:X8} has a scale outside [0.01, 100] or a bad frame.",
                    nameof(ScenerySource));
            }

            Objects.InitPartArrayModel(s.ObjectId, out _);
        }

        return new PendingBlock(block, landBlock, info, envCells.ToArray(), envEntries.ToArray(), scenery);
    }

    // An entry whose own id is not the id it was asked for is not that entry.
    private static void Expect(string structure, uint got, uint asked, int offset = 0)
    {
        if (got != asked)
        {
            throw new RetailDataFormatException(structure, offset, $"the entry asked for as 0x{asked:X8} holds 0x{got:X8}");
        }
    }

    private ReadOnlySpan<byte> Entry(uint id)
    {
        if (!_source.TryGetEntry(id, out ReadOnlyMemory<byte> bytes))
        {
            throw new ArgumentException($"The data source holds no entry 0x{id:X8}, which the landblock needs.", "source");
        }

        return bytes.Span;
    }

    private sealed record PendingBlock(uint BlockId, LandBlock LandBlock, LandBlockInfoEntry? Info, EnvCell[] EnvCells,
        EnvCellEntry[] EnvEntries, IReadOnlyList<SceneryItem> Scenery);

    // A block in the world: what retail's CLandBlock holds of it (static_objects, buildings).
    private sealed class LoadedBlock(PendingBlock pending)
    {
        public PendingBlock Pending { get; } = pending;

        public List<WorldObject> Objects { get; } = new();

        public List<Objects.PhysicsObj> StaticObjects { get; } = new();

        public List<BuildingObj> Buildings { get; } = new();

        public List<uint> Missing { get; } = new();
    }
}
