using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Data;

/// <summary>What <see cref="RetailLandBlockLoader.Load"/> put into the world, and what it read but did not place.</summary>
public sealed class RetailLandBlockContent
{
    internal RetailLandBlockContent(LandBlock landBlock, RetailLandBlockInfo? info, EnvCell[] envCells, BuildingObj[] buildings,
        RetailBuilding[] buildingsWithoutShell, RetailStaticObject[] staticObjects)
    {
        LandBlock = landBlock;
        Info = info;
        EnvCells = envCells;
        Buildings = buildings;
        BuildingsWithoutShell = buildingsWithoutShell;
        StaticObjects = staticObjects;
    }

    /// <summary>The landblock (terrain) now in the world.</summary>
    public LandBlock LandBlock { get; }

    /// <summary>The block's info entry, or null when the block has none.</summary>
    public RetailLandBlockInfo? Info { get; }

    /// <summary>The indoor cells now in the world, in id order.</summary>
    public IReadOnlyList<EnvCell> EnvCells { get; }

    /// <summary>The buildings now standing on the block's land cells.</summary>
    public IReadOnlyList<BuildingObj> Buildings { get; }

    /// <summary>Buildings whose model is not a GfxObj with physics (a Setup model, or a GfxObj without a physics BSP): read,
    /// not placed.</summary>
    public IReadOnlyList<RetailBuilding> BuildingsWithoutShell { get; }

    /// <summary>The static objects of the block and of its cells (ids and landblock-local frames), read, not placed: the client
    /// creates them as objects from their Setups.</summary>
    public IReadOnlyList<RetailStaticObject> StaticObjects { get; }
}

/// <summary>
/// Puts a landblock from the game's data into a world: its terrain (0xXXYYFFFF), its indoor cells (0xXXYY0100 …, the count
/// from 0xXXYYFFFE) with the environments they name, and its buildings with their GfxObj shells and doors, all unpacked by the
/// retail ports and added only once every entry has been read (a format error adds nothing).
/// </summary>
/// <remarks>Retail loads the same entries through <c>CLandBlock::InitLoad</c> / <c>init_buildings</c> and
/// <c>CEnvCell::UnPack</c>; the order of the reads here is the client's contract, described in <c>docs/retail-data.md</c>.</remarks>
public static class RetailLandBlockLoader
{
    /// <summary>
    /// Reads landblock <paramref name="blockId"/> from <paramref name="source"/> and adds it to <paramref name="cells"/>
    /// (replacing a landblock or indoor cells already loaded at the same ids). Each building stands on the land cell under
    /// its frame's origin.
    /// </summary>
    /// <param name="cells">The world's cells (terrain and indoor cells).</param>
    /// <param name="blockId">The landblock id (0xXXYYFFFF; any cell id of the block is accepted).</param>
    /// <param name="source">The client's data files.</param>
    /// <exception cref="ArgumentNullException">An argument is null.</exception>
    /// <exception cref="ArgumentException">The id is not inside the world, or an entry the block needs is missing from the source.</exception>
    /// <exception cref="RetailDataFormatException">An entry's bytes are bad (also: an entry holds another id than the one asked
    /// for); nothing has been added.</exception>
    /// <exception cref="InvalidOperationException">Called from inside a tick of the world these cells serve; nothing has been added.</exception>
    public static RetailLandBlockContent Load(WorldCells cells, uint blockId, IRetailDataSource source)
    {
        ArgumentNullException.ThrowIfNull(cells);
        ArgumentNullException.ThrowIfNull(source);
        uint block = LandDefs.BlockIdOf(blockId);
        if (!LandDefs.BlockIdToLCoord(block, out int lx, out int ly))
        {
            throw new ArgumentException($"Landblock 0x{block:X8} lies outside the world.", nameof(blockId));
        }

        RetailLandBlock land = RetailLandBlock.Unpack(Entry(source, block));
        Expect("CLandBlock", land.Id, block);
        LandBlock landBlock = land.ToLandBlock(cells.Terrain.HeightTable);
        RetailLandBlockInfo? info = null;
        var envCells = new List<EnvCell>();
        var buildings = new List<(BuildingObj Building, uint LandCell)>();
        var noShell = new List<RetailBuilding>();
        var statics = new List<RetailStaticObject>();
        if (land.HasInfo)
        {
            info = RetailLandBlockInfo.Unpack(Entry(source, (block & 0xFFFF0000u) | 0xFFFEu));
            Expect("CLandBlockInfo", info.Id, (block & 0xFFFF0000u) | 0xFFFEu);
            statics.AddRange(info.Objects.ToArray());
            var environments = new Dictionary<uint, RetailEnvironment>();
            for (int i = 0; i < info.NumCells; i++)
            {
                RetailEnvCell cell = RetailEnvCell.Unpack(Entry(source, info.CellId(i)));
                Expect("CEnvCell", cell.Id, info.CellId(i), 8);
                if (!environments.TryGetValue(cell.EnvironmentId, out RetailEnvironment? env))
                {
                    env = RetailEnvironment.Unpack(Entry(source, cell.EnvironmentId));
                    Expect("CEnvironment", env.Id, cell.EnvironmentId);
                    environments.Add(cell.EnvironmentId, env);
                }

                envCells.Add(cell.ToEnvCell(env));
                statics.AddRange(cell.StaticObjects.ToArray());
            }

            var shells = new Dictionary<uint, RetailGfxObj>();
            foreach (RetailBuilding b in info.Buildings)
            {
                if ((b.ModelId >> 24) != 0x01)
                {
                    noShell.Add(b);
                    continue;
                }

                if (!shells.TryGetValue(b.ModelId, out RetailGfxObj? gfx))
                {
                    gfx = RetailGfxObj.Unpack(Entry(source, b.ModelId));
                    Expect("CGfxObj", gfx.Id, b.ModelId);
                    shells.Add(b.ModelId, gfx);
                }

                if (gfx.Physics is null)
                {
                    noShell.Add(b);
                    continue;
                }

                Vector3 o = b.Frame.Origin;
                int cx = Math.Clamp((int)MathF.Floor(o.X / LandDefs.CellLength), 0, LandDefs.BlockSide - 1);
                int cy = Math.Clamp((int)MathF.Floor(o.Y / LandDefs.CellLength), 0, LandDefs.BlockSide - 1);
                uint landCell = LandDefs.LCoordToGid(lx + cx, ly + cy);
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
            cells.Terrain.GetLandCell(buildings[i].LandCell)!.Building = buildings[i].Building;
            placed[i] = buildings[i].Building;
        }

        return new RetailLandBlockContent(landBlock, info, envCells.ToArray(), placed, noShell.ToArray(), statics.ToArray());
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
