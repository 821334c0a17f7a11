using System;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Data;

/// <summary>A portal of an indoor cell as stored (retail <c>CCellPortal::UnPack</c>): the flags, the portal polygon's id in
/// the cell's structure, the cell behind it and the matching portal's index there.</summary>
/// <param name="Flags">Bit 1 exact match, bit 2 the other cell lies on the polygon's negative side (retail portal_side 0),
/// bit 4 the portal opens to the outdoors.</param>
/// <param name="PolyId">The portal polygon's id in the structure (retail <c>CCellStruct::get_portal</c> looks it up).</param>
/// <param name="OtherCellId">The full id of the cell behind (the block's prefix and the stored low word), or
/// <see cref="CellPortal.OutsideCellId"/> for flag 4.</param>
/// <param name="OtherPortalId">The matching portal's index in the other cell.</param>
public readonly record struct CellPortalInfo(ushort Flags, short PolyId, uint OtherCellId, short OtherPortalId)
{
    /// <summary>Retail <c>exact_match</c>: flag 1.</summary>
    public bool ExactMatch => (Flags & 1) != 0;

    /// <summary>Retail <c>portal_side</c>: 1 unless flag 2 is set.</summary>
    public int PortalSide => (~Flags >> 1) & 1;
}

/// <summary>A static object of a cell or a landblock: its Setup or GfxObj id and its frame (landblock-local).</summary>
/// <param name="Id">The object's Setup (0x02xxxxxx) or GfxObj (0x01xxxxxx) id.</param>
/// <param name="Frame">Where it stands in its landblock.</param>
public readonly record struct StaticObjectInfo(uint Id, Frame Frame);

/// <summary>
/// An indoor cell (data-file entry 0xXXYY0100 and up) as retail's <c>CEnvCell::UnPack</c> reads it: its environment and
/// structure, its frame in the landblock, its portals, the cells it sees, its static objects. Build the library's cell with
/// <see cref="ToEnvCell"/> from the environment it names.
/// </summary>
public sealed class EnvCellEntry
{
    /// <summary>Retail flag 1: the cell sees the outdoors (<c>seen_outside</c>).</summary>
    public const uint SeenOutsideFlag = 1;

    /// <summary>Retail flag 2: static objects follow.</summary>
    public const uint HasStaticObjectsFlag = 2;

    /// <summary>Retail flag 8: a restriction object id follows.</summary>
    public const uint HasRestrictionObjectFlag = 8;

    private readonly uint[] _surfaceIds;
    private readonly CellPortalInfo[] _portals;
    private readonly uint[] _visibleCells;
    private readonly StaticObjectInfo[] _staticObjects;
    private readonly int _environmentOffset;
    private readonly int[] _portalOffsets;

    private EnvCellEntry(uint id, uint flags, uint[] surfaceIds, uint environmentId, int cellStructIndex, Frame frame,
        CellPortalInfo[] portals, uint[] visibleCells, StaticObjectInfo[] staticObjects, uint restrictionObject,
        int environmentOffset, int[] portalOffsets)
    {
        _environmentOffset = environmentOffset;
        _portalOffsets = portalOffsets;
        Id = id;
        Flags = flags;
        _surfaceIds = surfaceIds;
        EnvironmentId = environmentId;
        CellStructIndex = cellStructIndex;
        Frame = frame;
        _portals = portals;
        _visibleCells = visibleCells;
        _staticObjects = staticObjects;
        RestrictionObject = restrictionObject;
    }

    /// <summary>The cell id (0xXXYYCCCC, CCCC from 0x0100). Retail: <c>m_DID</c>.</summary>
    public uint Id { get; }

    /// <summary>The stored flags (<see cref="SeenOutsideFlag"/>, <see cref="HasStaticObjectsFlag"/>,
    /// <see cref="HasRestrictionObjectFlag"/>).</summary>
    public uint Flags { get; }

    /// <summary>The surfaces' ids (0x08000000 and the stored word).</summary>
    public ReadOnlySpan<uint> SurfaceIds => _surfaceIds;

    /// <summary>The environment's id (0x0D000000 and the stored word).</summary>
    public uint EnvironmentId { get; }

    /// <summary>The structure's index in the environment (<c>CEnvironment::get_cellstruct</c>).</summary>
    public int CellStructIndex { get; }

    /// <summary>The cell's local frame in its landblock. Retail: <c>pos.frame</c>.</summary>
    public Frame Frame { get; }

    /// <summary>The portals, in stored order (portal indices elsewhere refer to this order).</summary>
    public ReadOnlySpan<CellPortalInfo> Portals => _portals;

    /// <summary>The cells this one sees, full ids. Retail: <c>stab_list</c>.</summary>
    public ReadOnlySpan<uint> VisibleCells => _visibleCells;

    /// <summary>The static objects (ids and frames). Retail: <c>static_object_ids</c>, <c>static_object_frames</c>.</summary>
    public ReadOnlySpan<StaticObjectInfo> StaticObjects => _staticObjects;

    /// <summary>The restriction object id, 0 when not stored. Retail: <c>restriction_obj</c>.</summary>
    public uint RestrictionObject { get; }

    /// <summary>
    /// Unpacks one indoor cell entry's bytes: the entry id, then the flags, the cell id, the surface and portal counts (bytes)
    /// and the visible-cell count (word), the surfaces, the environment and structure index, the frame, the portals, the
    /// visible cells, the static objects (flag 2) and the restriction object (flag 8). Retail <c>CEnvCell::UnPack</c>.
    /// </summary>
    /// <exception cref="RetailDataFormatException">The bytes are not an indoor cell (also: its id is not an indoor cell id).</exception>
    // retail: CEnvCell::UnPack (acclient.c:349133)
    public static EnvCellEntry UnPack(ReadOnlySpan<byte> data)
    {
        var r = new RetailDataReader(data, "CEnvCell");
        r.ReadUInt32("entry id");
        uint flags = r.ReadUInt32("flags");
        int idAt = r.Offset;
        uint id = r.ReadUInt32("cell id");
        if (!LandDefs.IsEnvCell(id) || (id & 0xFFFF) > 0xFFFD)
        {
            throw r.ErrorAt(idAt, $"0x{id:X8} is not an indoor cell id");
        }

        uint blockMask = id & 0xFFFF0000;
        int countsAt = r.Offset;
        byte numSurfaces = r.ReadByte("surface count");
        byte numPortals = r.ReadByte("portal count");
        ushort numStabs = r.ReadUInt16("visible cell count");
        r.CheckCount(numSurfaces, "surface count", 2, countsAt);
        var surfaces = new uint[numSurfaces];
        for (int i = 0; i < surfaces.Length; i++)
        {
            surfaces[i] = r.ReadUInt16("surface id") | 0x08000000u;
        }

        int envAt = r.Offset;
        uint environmentId = r.ReadUInt16("environment id") | 0x0D000000u;
        int structIndex = r.ReadUInt16("cell struct index");
        Frame frame = r.ReadFrame("cell frame");
        r.CheckCount(numPortals, "portal count", 8, countsAt + 1);
        var portals = new CellPortalInfo[numPortals];
        var portalAt = new int[numPortals];
        for (int i = 0; i < portals.Length; i++)
        {
            portalAt[i] = r.Offset;
            portals[i] = UnPackPortal(ref r, blockMask);
        }

        r.CheckCount(numStabs, "visible cell count", 2, countsAt + 2);
        var visible = new uint[numStabs];
        for (int i = 0; i < visible.Length; i++)
        {
            visible[i] = blockMask | r.ReadUInt16("visible cell id");
        }

        StaticObjectInfo[] statics = [];
        if ((flags & HasStaticObjectsFlag) != 0)
        {
            int n = r.ReadCount("static object count", 32);
            statics = new StaticObjectInfo[n];
            for (int i = 0; i < n; i++)
            {
                uint objId = r.ReadUInt32("static object id");
                statics[i] = new StaticObjectInfo(objId, r.ReadFrame("static object frame"));
            }
        }

        uint restriction = (flags & HasRestrictionObjectFlag) != 0 ? r.ReadUInt32("restriction object") : 0u;
        return new EnvCellEntry(id, flags, surfaces, environmentId, structIndex, frame, portals, visible, statics, restriction, envAt,
            portalAt);
    }

    /// <summary>One portal: flags, polygon id, the other cell's low word (ignored with flag 4: the outdoors), the other
    /// portal's index.</summary>
    // retail: CCellPortal::UnPack (acclient.c:362378)
    private static CellPortalInfo UnPackPortal(ref RetailDataReader r, uint blockMask)
    {
        ushort flags = r.ReadUInt16("portal flags");
        short polyId = r.ReadInt16("portal polygon id");
        ushort other = r.ReadUInt16("portal other cell");
        short otherPortal = r.ReadInt16("portal other portal id");
        uint otherCell = (flags & 4) != 0 ? CellPortal.OutsideCellId : blockMask | other;
        return new CellPortalInfo(flags, polyId, otherCell, otherPortal);
    }

    /// <summary>
    /// The library's indoor cell: the structure <see cref="CellStructIndex"/> of <paramref name="environment"/> placed at
    /// <see cref="Frame"/>, with each portal's polygon looked up by id in the structure's portals
    /// (<c>CCellStruct::get_portal</c>, as the unpack does).
    /// </summary>
    /// <exception cref="ArgumentNullException"><paramref name="environment"/> is null.</exception>
    /// <exception cref="RetailDataFormatException">The environment is not the one the cell names, the structure index is out of
    /// range, or a portal's polygon is not among the structure's portals (the offset is that field's in the cell's bytes).</exception>
    public EnvCell ToEnvCell(EnvironmentEntry environment)
    {
        ArgumentNullException.ThrowIfNull(environment);
        if (environment.Id != EnvironmentId)
        {
            throw new RetailDataFormatException("CEnvCell", _environmentOffset, $"cell 0x{Id:X8} names environment 0x{EnvironmentId:X8}, not 0x{environment.Id:X8}");
        }

        CellStructEntry s = environment.GetCellStruct(CellStructIndex)
            ?? throw new RetailDataFormatException("CEnvCell", _environmentOffset + 2, $"cell 0x{Id:X8}: structure index {CellStructIndex} is outside environment 0x{EnvironmentId:X8} ({environment.CellStructs.Length} structures)");
        var portals = new CellPortal[_portals.Length];
        for (int i = 0; i < portals.Length; i++)
        {
            CellPortalInfo p = _portals[i];
            Polygon poly = s.Structure.GetPortal(p.PolyId)
                ?? throw new RetailDataFormatException("CEnvCell", _portalOffsets[i] + 2, $"cell 0x{Id:X8}: portal {i} names polygon {p.PolyId}, not a portal of its structure");
            portals[i] = new CellPortal(p.OtherCellId, poly, p.PortalSide, p.OtherPortalId, p.ExactMatch);
        }

        return new EnvCell(Id, Frame, s.Structure, portals);
    }
}
