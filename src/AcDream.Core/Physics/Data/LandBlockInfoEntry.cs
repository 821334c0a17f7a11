using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Data;

/// <summary>A building's door as stored (retail <c>CBldPortal::UnPack</c>): flags, the indoor cell behind it, that cell's
/// portal index, and the cells seen through it.</summary>
/// <param name="Flags">Bit 1 exact match, bit 2 portal side 0.</param>
/// <param name="OtherCellId">The full id of the indoor cell behind the door.</param>
/// <param name="OtherPortalId">The portal's index in that cell.</param>
/// <param name="VisibleCells">The cells seen through the door (full ids). Retail: <c>stab_list</c>.</param>
public sealed record BldPortalInfo(ushort Flags, uint OtherCellId, short OtherPortalId, uint[] VisibleCells)
{
    /// <summary>Retail <c>exact_match</c>: flag 1.</summary>
    public bool ExactMatch => (Flags & 1) != 0;

    /// <summary>Retail <c>portal_side</c>: 1 unless flag 2 is set.</summary>
    public int PortalSide => (~Flags >> 1) & 1;

    /// <summary>The library's door.</summary>
    public BldPortal ToBldPortal() => new(OtherCellId, OtherPortalId, PortalSide, ExactMatch);
}

/// <summary>A building as stored (retail <c>BuildInfo</c>): its model (a GfxObj 0x01xxxxxx or a Setup 0x02xxxxxx), its frame
/// in the landblock, its leaf count and its doors.</summary>
/// <param name="ModelId">The building's GfxObj or Setup id. Retail: <c>building_id</c>.</param>
/// <param name="Frame">Where it stands, landblock-local. Retail: <c>building_frame</c>.</param>
/// <param name="NumLeaves">Retail <c>num_leaves</c>.</param>
/// <param name="Portals">The doors. Retail: <c>portals</c>.</param>
public sealed record BuildingInfo(uint ModelId, Frame Frame, uint NumLeaves, BldPortalInfo[] Portals);

/// <summary>
/// A landblock's contents (data-file entry 0xXXYYFFFE) as retail's <c>CLandBlockInfo::UnPack</c> reads it: the number of
/// indoor cells (0xXXYY0100 onwards), the static objects, the buildings and the restriction table.
/// </summary>
public sealed class LandBlockInfoEntry
{
    private readonly StaticObjectInfo[] _objects;
    private readonly BuildingInfo[] _buildings;

    private LandBlockInfoEntry(uint id, int numCells, StaticObjectInfo[] objects, BuildingInfo[] buildings, ushort buildingFlags,
        IReadOnlyDictionary<uint, uint> restrictions)
    {
        Id = id;
        NumCells = numCells;
        _objects = objects;
        _buildings = buildings;
        BuildingFlags = buildingFlags;
        RestrictionTable = restrictions;
    }

    /// <summary>The entry id (0xXXYYFFFE).</summary>
    public uint Id { get; }

    /// <summary>How many indoor cells the block has: 0xXXYY0100 … 0xXXYY0100 + NumCells - 1. Retail: <c>num_cells</c>.</summary>
    public int NumCells { get; }

    /// <summary>The static objects. Retail: <c>object_ids</c>, <c>object_frames</c>.</summary>
    public ReadOnlySpan<StaticObjectInfo> Objects => _objects;

    /// <summary>The buildings. Retail: <c>buildings</c>.</summary>
    public ReadOnlySpan<BuildingInfo> Buildings => _buildings;

    /// <summary>The high word of the building count (bit 1: a restriction table follows).</summary>
    public ushort BuildingFlags { get; }

    /// <summary>The restriction table (cell id → restriction object), empty when not stored. Retail: <c>restriction_table</c>.</summary>
    public IReadOnlyDictionary<uint, uint> RestrictionTable { get; }

    /// <summary>The restriction object of <paramref name="landCellId"/>, 0 when it has none. Retail
    /// <c>CLandBlockInfo::GetRestrictionIID</c>.</summary>
    // retail: CLandBlockInfo::GetRestrictionIID (acclient.c:351249)
    public uint GetRestrictionIid(uint landCellId) => RestrictionTable.TryGetValue(landCellId, out uint v) ? v : 0u;

    /// <summary>The ids of the block's indoor cells, in order.</summary>
    public uint CellId(int index) => (Id & 0xFFFF0000u) | (uint)(LandDefs.FirstEnvCell + index);

    /// <summary>
    /// Unpacks one landblock info entry's bytes: the id, the cell count, the object count and each object (id and frame),
    /// the building count (low word) with its flags (high word), each building (id, frame, leaf count, door count, doors),
    /// and the restriction table when flag 1 is set.
    /// </summary>
    /// <exception cref="RetailDataFormatException">The bytes are not a landblock info (also: the id is not 0xXXYYFFFE, or the
    /// cell count runs past cell 0xFFFD).</exception>
    // retail: CLandBlockInfo::UnPack (acclient.c:351048)
    public static LandBlockInfoEntry UnPack(ReadOnlySpan<byte> data)
    {
        var r = new RetailDataReader(data, "CLandBlockInfo");
        uint id = r.ReadUInt32("id");
        if ((id & 0xFFFF) != 0xFFFE)
        {
            throw r.ErrorAt(0, $"0x{id:X8} is not a landblock info id (0xXXYYFFFE)");
        }

        int cellsAt = r.Offset;
        uint numCells = r.ReadUInt32("cell count");
        if (numCells > LandDefs.LastEnvCell - LandDefs.FirstEnvCell + 1)
        {
            throw r.ErrorAt(cellsAt, $"cell count {numCells} runs past cell 0xFFFD");
        }

        int numObjects = r.ReadCount("object count", 32);
        var objects = new StaticObjectInfo[numObjects];
        for (int i = 0; i < numObjects; i++)
        {
            uint objId = r.ReadUInt32("object id");
            objects[i] = new StaticObjectInfo(objId, r.ReadFrame("object frame"));
        }

        uint blockMask = id & 0xFFFF0000u;
        int packedAt = r.Offset;
        uint packed = r.ReadUInt32("building count");
        int numBuildings = r.CheckCount(packed & 0xFFFF, "building count", 40, packedAt);
        ushort packMask = (ushort)(packed >> 16);
        var buildings = new BuildingInfo[numBuildings];
        for (int i = 0; i < numBuildings; i++)
        {
            uint model = r.ReadUInt32("building id");
            Frame frame = r.ReadFrame("building frame");
            uint numLeaves = r.ReadUInt32("building leaf count");
            int numPortals = r.ReadCount("building portal count", 8);
            var portals = new BldPortalInfo[numPortals];
            for (int p = 0; p < numPortals; p++)
            {
                portals[p] = UnPackBldPortal(ref r, blockMask);
            }

            buildings[i] = new BuildingInfo(model, frame, numLeaves, portals);
        }

        IReadOnlyDictionary<uint, uint> restrictions = (packMask & 1) != 0 ? UnPackTable(ref r) : new Dictionary<uint, uint>();
        return new LandBlockInfoEntry(id, (int)numCells, objects, buildings, packMask, restrictions);
    }

    /// <summary>A door: flags, the other cell's low word, the other portal's index, the visible-cell count and ids, and two
    /// bytes of padding after an odd count.</summary>
    // retail: CBldPortal::UnPack (acclient.c:362498)
    private static BldPortalInfo UnPackBldPortal(ref RetailDataReader r, uint blockMask)
    {
        ushort flags = r.ReadUInt16("door flags");
        uint other = blockMask | r.ReadUInt16("door other cell");
        short otherPortal = r.ReadInt16("door other portal id");
        int numStabs = r.ReadCount16("door visible cell count", 2);
        var stabs = new uint[numStabs];
        for (int i = 0; i < stabs.Length; i++)
        {
            stabs[i] = blockMask | r.ReadUInt16("door visible cell");
        }

        if ((numStabs & 1) != 0)
        {
            r.Skip(2, "door padding");
        }

        return new BldPortalInfo(flags, other, otherPortal, stabs);
    }

    /// <summary>A hash table of 32-bit keys and values: the entry count (low word) and table size (high word), then the pairs.
    /// A zero table size holds no entries; sizes above 0x10000 are refused, as retail refuses them.</summary>
    // retail: PackableHashTable<unsigned long,int>::UnPack (acclient.c:440980), the shape the unsigned-long table shares
    private static Dictionary<uint, uint> UnPackTable(ref RetailDataReader r)
    {
        r.Structure = "PackableHashTable";
        int at = r.Offset;
        uint head = r.ReadUInt32("table header");
        uint tableSize = head >> 16;
        int count = (int)(head & 0xFFFF);
        if (tableSize == 0 && count != 0)
        {
            throw r.ErrorAt(at, $"{count} entries in a table of size 0");
        }

        r.CheckCount((uint)count, "table entry count", 8, at);
        var table = new Dictionary<uint, uint>(count);
        for (int i = 0; i < count; i++)
        {
            uint key = r.ReadUInt32("table key");
            // Retail's add refuses a duplicate key (and the unpack fails unless duplicates are thrown away).
            int keyAt = r.Offset - 4;
            if (!table.TryAdd(key, r.ReadUInt32("table value")))
            {
                throw r.ErrorAt(keyAt, $"duplicate key 0x{key:X8}");
            }
        }

        return table;
    }
}
