using System;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Data;

/// <summary>One level of detail of a <see cref="GfxObjDegradeInfoEntry"/> (retail <c>GfxObjInfo</c>): the GfxObj drawn at
/// that level, how it is drawn, and the distances between which it is drawn.</summary>
/// <param name="GfxObjId">The GfxObj of this level (0x01xxxxxx; 0 for none). Retail: <c>gfxobj_id</c>.</param>
/// <param name="DegradeMode">How it is drawn (1: a 3-D mesh; any other value a 2-D sprite). Retail: <c>degrade_mode</c>.</param>
/// <param name="MinDistance">Retail <c>min_dist</c>, metres.</param>
/// <param name="IdealDistance">Retail <c>ideal_dist</c>, metres.</param>
/// <param name="MaxDistance">Retail <c>max_dist</c>, metres.</param>
public readonly record struct GfxObjDegradeLevel(uint GfxObjId, uint DegradeMode, float MinDistance, float IdealDistance, float MaxDistance);

/// <summary>
/// A GfxObj's table of levels of detail (data-file entry 0x11xxxxxx, named by a GfxObj's degrade id) as retail's
/// <c>GfxObjDegradeInfo::UnPack</c> reads it: the entry id, the level count, and each level's GfxObj id, mode and distances.
/// Physics uses the first level: a part whose GfxObj names a degrade table collides with <c>degrades[0]</c>'s GfxObj
/// (<c>CPhysicsPart::LoadGfxObjArray</c>).
/// </summary>
public sealed class GfxObjDegradeInfoEntry
{
    private readonly GfxObjDegradeLevel[] _degrades;

    private GfxObjDegradeInfoEntry(uint id, GfxObjDegradeLevel[] degrades)
    {
        Id = id;
        _degrades = degrades;
    }

    /// <summary>The entry id (0x11xxxxxx).</summary>
    public uint Id { get; }

    /// <summary>The levels, finest first. Retail: <c>degrades</c> (<c>num_degrades</c> long).</summary>
    public ReadOnlySpan<GfxObjDegradeLevel> Degrades => _degrades;

    /// <summary>Unpacks one degrade table's bytes: the id, the level count, then each level (20 bytes: GfxObj id, mode, minimum,
    /// ideal and maximum distance).</summary>
    /// <exception cref="RetailDataFormatException">The bytes are not a degrade table (truncated, a count past the end, or an id
    /// whose high byte is not 0x11).</exception>
    // retail: GfxObjDegradeInfo::UnPack (acclient.c:332293)
    public static GfxObjDegradeInfoEntry UnPack(ReadOnlySpan<byte> data)
    {
        var r = new RetailDataReader(data, "GfxObjDegradeInfo");
        uint id = r.ReadUInt32("id");
        if ((id >> 24) != 0x11)
        {
            throw r.ErrorAt(0, $"0x{id:X8} is not a degrade table id (0x11xxxxxx)");
        }

        int n = r.ReadCount("degrade count", 20);
        var levels = new GfxObjDegradeLevel[n];
        for (int i = 0; i < n; i++)
        {
            uint gfx = r.ReadUInt32("degrade gfxobj id");
            uint mode = r.ReadUInt32("degrade mode");
            float min = r.ReadSingle("degrade min distance");
            float ideal = r.ReadSingle("degrade ideal distance");
            levels[i] = new GfxObjDegradeLevel(gfx, mode, min, ideal, r.ReadSingle("degrade max distance"));
        }

        return new GfxObjDegradeInfoEntry(id, levels);
    }
}
