using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Data;

/// <summary>What <see cref="LandBlockLoader.Load"/> put into the world, and what it read but did not place.</summary>
public sealed class LandBlockContent
{
    internal LandBlockContent(LandBlock landBlock, LandBlockInfoEntry? info, EnvCell[] envCells, BuildingObj[] buildings)
    {
        LandBlock = landBlock;
        Info = info;
        EnvCells = envCells;
        Buildings = buildings;
    }

    /// <summary>The landblock (terrain) now in the world.</summary>
    public LandBlock LandBlock { get; }

    /// <summary>The block's info entry, or null when the block has none.</summary>
    public LandBlockInfoEntry? Info { get; }

    /// <summary>The indoor cells now in the world, in id order.</summary>
    public IReadOnlyList<EnvCell> EnvCells { get; }

    /// <summary>The GfxObj-shell buildings now hung on the block's land cells (each on the cell under its origin; the first of a
    /// cell wins). Setup-model buildings, static objects and scenery are built by <c>WorldData.WorldLoader</c>.</summary>
    public IReadOnlyList<BuildingObj> Buildings { get; }
}

/// <summary>
/// Puts a landblock's geometry from the game's data into a world: its terrain (0xXXYYFFFF), its indoor cells (0xXXYY0100 …,
/// the count from 0xXXYYFFFE) with the environments they name, and its buildings with GfxObj shells and their doors, all
/// unpacked by the retail ports and added only once every entry has been read (a format error adds nothing). The whole world
/// of a block (Setup buildings, static objects, scenery) is built by <c>WorldData.WorldLoader</c>, the client's door.
/// </summary>
/// <remarks>Retail loads the same entries through <c>CLandBlock::InitLoad</c> / <c>init_buildings</c> and
/// <c>CEnvCell::UnPack</c>; the order of the reads here is the client's contract, described in <c>docs/retail-data.md</c>.</remarks>
public static class LandBlockLoader
{
    /// <summary>
    /// Reads landblock <paramref name="blockId"/> from <paramref name="source"/> and adds it to <paramref name="cells"/>
    /// (replacing a landblock or indoor cells already loaded at the same ids). Each building hangs on the land cell under its
    /// frame's origin (the first of a cell wins, retail <c>CSortCell::add_building</c>); a building whose origin lies outside the
    /// block is dropped (retail <c>CLandBlock::init_buildings</c>).
    /// </summary>
    /// <param name="cells">The world's cells (terrain and indoor cells).</param>
    /// <param name="blockId">The landblock id (0xXXYYFFFF; any cell id of the block is accepted).</param>
    /// <param name="source">The client's data files.</param>
    /// <exception cref="ArgumentNullException">An argument is null.</exception>
    /// <exception cref="ArgumentException">The id is not inside the world, or an entry the block needs is missing from the source.</exception>
    /// <exception cref="RetailDataFormatException">An entry's bytes are bad (also: an entry holds another id than the one asked
    /// for); nothing has been added.</exception>
    /// <exception cref="InvalidOperationException">Called from inside a tick of the world these cells serve; nothing has been added.</exception>
    public static LandBlockContent Load(WorldCells cells, uint blockId, IRetailDataSource source)
    {
        ArgumentNullException.ThrowIfNull(cells);
        ArgumentNullException.ThrowIfNull(source);
        uint block = LandDefs.BlockIdOf(blockId);
        if (!LandDefs.BlockIdToLCoord(block, out _, out _))
        {
            throw new ArgumentException($"Landblock 0x{block:X8} lies outside the world.", nameof(blockId));
        }

        LandBlockEntry land = LandBlockEntry.UnPack(Entry(source, block));
        Expect("CLandBlock", land.Id, block);
        LandBlock landBlock = land.ToLandBlock(cells.Terrain.HeightTable);
        LandBlockInfoEntry? info = null;
        var envCells = new List<EnvCell>();
        var buildings = new List<(BuildingObj Building, uint LandCell)>();
        if (land.HasInfo)
        {
            info = LandBlockInfoEntry.UnPack(Entry(source, (block & 0xFFFF0000u) | 0xFFFEu));
            Expect("CLandBlockInfo", info.Id, (block & 0xFFFF0000u) | 0xFFFEu);
            var environments = new Dictionary<uint, EnvironmentEntry>();
            for (int i = 0; i < info.NumCells; i++)
            {
                EnvCellEntry cell = EnvCellEntry.UnPack(Entry(source, info.CellId(i)));
                Expect("CEnvCell", cell.Id, info.CellId(i), 8);
                if (!environments.TryGetValue(cell.EnvironmentId, out EnvironmentEntry? env))
                {
                    env = EnvironmentEntry.UnPack(Entry(source, cell.EnvironmentId));
                    Expect("CEnvironment", env.Id, cell.EnvironmentId);
                    environments.Add(cell.EnvironmentId, env);
                }

                envCells.Add(cell.ToEnvCell(env));
            }

            var shells = new Dictionary<uint, GfxObjEntry>();
            foreach (BuildingInfo b in info.Buildings)
            {
                if ((b.ModelId >> 24) != 0x01)
                {
                    continue;
                }

                if (!shells.TryGetValue(b.ModelId, out GfxObjEntry? gfx))
                {
                    gfx = GfxObjEntry.UnPack(Entry(source, b.ModelId));
                    Expect("CGfxObj", gfx.Id, b.ModelId);
                    shells.Add(b.ModelId, gfx);
                }

                if (gfx.Physics is null)
                {
                    continue;
                }

                // retail: CLandBlock::init_buildings (acclient.c:352113): adjust_to_outside, then this block's land cell
                uint landCell = block;
                Vector3 o = b.Frame.Origin;
                if (!LandDefs.AdjustToOutside(ref landCell, ref o) || LandDefs.BlockIdOf(landCell) != block)
                {
                    continue;
                }

                var doors = new BldPortal[b.Portals.Length];
                for (int p = 0; p < doors.Length; p++)
                {
                    doors[p] = b.Portals[p].ToBldPortal();
                }

                var part = new PhysicsPart(gfx.Physics, new Position(landCell, b.Frame), Vector3.One);
                buildings.Add((new BuildingObj(part, doors), landCell));
            }
        }

        // Everything is read: now change the world.
        cells.Terrain.AddLandBlock(landBlock);
        foreach (EnvCell c in envCells)
        {
            cells.AddEnvCell(c);
        }

        var placed = new BuildingObj[buildings.Count];
        for (int i = 0; i < buildings.Count; i++)
        {
            buildings[i].Building.AddToCell(cells.Terrain.GetLandCell(buildings[i].LandCell)!);
            placed[i] = buildings[i].Building;
        }

        return new LandBlockContent(landBlock, info, envCells.ToArray(), placed);
    }

    // An entry whose own id is not the id it was asked for is not that entry.
    private static void Expect(string structure, uint got, uint asked, int offset = 0)
    {
        if (got != asked)
        {
            throw new RetailDataFormatException(structure, offset, $"the entry asked for as 0x{asked:X8} holds 0x{got:X8}");
        }
    }

    private static ReadOnlySpan<byte> Entry(IRetailDataSource source, uint id)
    {
        if (!source.TryGetEntry(id, out ReadOnlyMemory<byte> bytes))
        {
            throw new ArgumentException($"The data source holds no entry 0x{id:X8}, which the landblock needs.", nameof(source));
        }

        return bytes.Span;
    }
}
