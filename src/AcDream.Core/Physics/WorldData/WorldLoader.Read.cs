using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Core.Physics.WorldData;

// Reading a block's entries before the world changes, and what the door keeps of a block it built.
public sealed partial class WorldLoader
{
    // One block's entries, read and unpacked, with the shape of every object it will make; its indoor cells too unless the
    // landscape reads them through its visible-cell table (withEnvCells false).
    internal PendingBlock Read(uint block, bool withEnvCells)
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
            for (int i = 0; withEnvCells && i < info.NumCells; i++)
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
    internal static void Expect(string structure, uint got, uint asked, int offset = 0)
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

    internal sealed record PendingBlock(uint BlockId, LandBlock LandBlock, LandBlockInfoEntry? Info, EnvCell[] EnvCells,
        EnvCellEntry[] EnvEntries, IReadOnlyList<SceneryItem> Scenery);

    // A block in the world: what retail's CLandBlock holds of it (static_objects, buildings, dyn_objs_init_done).
    internal sealed class LoadedBlock(PendingBlock pending)
    {
        public PendingBlock Pending { get; } = pending;

        public List<WorldObject> Objects { get; } = new();

        public List<Objects.PhysicsObj> StaticObjects { get; } = new();

        public List<BuildingObj> Buildings { get; } = new();

        public List<uint> Missing { get; } = new();

        /// <summary>Retail <c>buildings</c> not null: init_buildings ran.</summary>
        public bool BuildingsDone { get; set; }

        /// <summary>Retail <c>num_static_objects</c> not 0: init_static_objs' first call ran.</summary>
        public bool StaticsDone { get; set; }

        /// <summary>Retail <c>dyn_objs_init_done</c>.</summary>
        public bool DynObjsInitDone { get; set; }

        /// <summary>The record for the renderer, made when the statics are first built.</summary>
        public WorldBlock? Block { get; set; }
    }
}
