using System;
using System.Text;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Core.Physics.Data;

// Reading the region's bytes: the header, the height table, then (RegionEntry.Walk.cs) the calendar, sky and sounds, then the
// scene and terrain types.
public sealed partial class RegionEntry
{
    /// <summary>
    /// Unpacks a region entry's bytes as far as the terrain types: id, region number, version (3), name, the eight LandDefs
    /// values (read and discarded: retail's compiled-in values win), the 256 land heights, the calendar (<c>GameTime</c>),
    /// the parts mask, the sky (bit 0x10), the ambient sound tables (bit 0x01), the scene types (bit 0x02), and the terrain
    /// types. The calendar, sky and sounds are checked and skipped; the land surfaces and the rest are not read.
    /// </summary>
    /// <remarks>
    /// A name is a 16-bit length (0xFFFF: a 32-bit length follows), the characters, then zeros to a multiple of four.
    /// Retail's <c>PStringBase&lt;char&gt;::UnPack</c> (acclient.c:296508) pads the pointer (<c>*addr % 4</c>) and
    /// <c>CRegionDesc::UnPack</c>'s size bookkeeping pads <c>2 + length</c> (acclient.c:299884); both agree because every field
    /// before a name is whole 32-bit words, so a name starts on a multiple of four from the entry's first byte, and the entry's
    /// buffer is a heap block. The data files themselves are not word-aligned (<c>Archive::CheckAlignment</c>,
    /// acclient.c:70280, pads only archives opened with its alignment flag), so the padding is counted from the entry's
    /// first byte (the id), never from a file offset.
    /// </remarks>
    /// <exception cref="RetailDataFormatException">The bytes are not a region: truncated, the id is not 0x13xxxxxx, the
    /// version is not 3, a land height is outside the library's 0–800 m, a count larger than the bytes that remain, a sky
    /// replacement naming a sky object past its day group's list, a scene type naming a sound table the region does not
    /// have, or a terrain slot naming a scene type the region does not have (retail reads through a bad pointer
    /// there).</exception>
    // retail: CRegionDesc::UnPack (acclient.c:299775)
    public static RegionEntry UnPack(ReadOnlySpan<byte> data)
    {
        var r = new RetailDataReader(data, "CRegionDesc");
        uint id = r.ReadUInt32("id");
        if (id >> 24 != 0x13)
        {
            throw r.ErrorAt(0, $"0x{id:X8} is not a region id (0x13xxxxxx)");
        }

        uint number = r.ReadUInt32("region number");
        int versionAt = r.Offset;
        uint version = r.ReadUInt32("version");
        if (version != RetailVersion)
        {
            throw r.ErrorAt(versionAt, $"version {version} is not {RetailVersion} (retail: a modal error)");
        }

        string name = ReadPString(ref r, "region name", keep: true);
        r.Skip(8 * 4, "LandDefs values");
        var heights = new float[LandHeightTable.Count];
        for (int i = 0; i < heights.Length; i++)
        {
            int at = r.Offset;
            float h = r.ReadSingle("land height");
            if (!(h >= 0f && LandHeightTable.MaxHeight >= h))
            {
                throw r.ErrorAt(at, $"land height {i} ({h}) is outside 0..{LandHeightTable.MaxHeight} m");
            }

            heights[i] = h;
        }

        var table = new LandHeightTable(heights);
        WalkGameTime(ref r);
        r.Structure = "CRegionDesc";
        uint mask = r.ReadUInt32("parts mask");
        if ((mask & SkyPart) != 0)
        {
            WalkSkyDesc(ref r);
        }

        int soundTables = 0;
        if ((mask & SoundPart) != 0)
        {
            soundTables = WalkSoundDesc(ref r);
        }

        SceneTypeInfo[] sceneTypes = (mask & ScenePart) != 0 ? ReadSceneTypes(ref r, soundTables) : [];
        TerrainTypeInfo[] terrainTypes = ReadTerrainTypes(ref r, sceneTypes.Length);
        return new RegionEntry(id, number, name, table, mask, soundTables, sceneTypes, terrainTypes);
    }

    /// <summary>The scene types: a count, then per type the sound table index (-1 none) and the <c>CSceneType</c>.</summary>
    private static SceneTypeInfo[] ReadSceneTypes(ref RetailDataReader r, int soundTables)
    {
        r.Structure = "CSceneDesc";
        int count = r.ReadCount("scene type count", 8);
        var types = new SceneTypeInfo[count];
        for (int i = 0; i < count; i++)
        {
            r.Structure = "CSceneDesc";
            int at = r.Offset;
            uint sound = r.ReadUInt32("scene type sound table index");
            if (sound != uint.MaxValue && sound >= (uint)soundTables)
            {
                throw r.ErrorAt(at, $"sound table index {sound} is past the region's {soundTables} sound tables");
            }

            types[i] = new SceneTypeInfo(sound == uint.MaxValue ? -1 : (int)sound, UnPackSceneType(ref r));
        }

        return types;
    }

    /// <summary>A scene type's scene ids: a count, then the ids.</summary>
    // retail: CSceneType::unpack (acclient.c:304484)
    private static System.Collections.Generic.IReadOnlyList<uint> UnPackSceneType(ref RetailDataReader r)
    {
        r.Structure = "CSceneType";
        int count = r.ReadCount("scene count", 4);
        var scenes = new uint[count];
        for (int i = 0; i < count; i++)
        {
            scenes[i] = r.ReadUInt32("scene id");
        }

        return Array.AsReadOnly(scenes);
    }

    /// <summary>The terrain types (<c>CTerrainDesc</c>, read inline by <c>CRegionDesc::UnPack</c>, acclient.c:300073): a
    /// count, then per type the name, colour, slot count and each slot's scene type index (-1: none).</summary>
    private static TerrainTypeInfo[] ReadTerrainTypes(ref RetailDataReader r, int sceneTypes)
    {
        r.Structure = "CTerrainDesc";
        int count = r.ReadCount("terrain type count", 12);
        var types = new TerrainTypeInfo[count];
        for (int i = 0; i < count; i++)
        {
            string name = ReadPString(ref r, "terrain type name", keep: true);
            uint color = r.ReadUInt32("terrain type colour");
            int slots = r.ReadCount("terrain type scene type count", 4);
            var indices = new int[slots];
            for (int s = 0; s < slots; s++)
            {
                int at = r.Offset;
                uint index = r.ReadUInt32("terrain type scene type index");
                if (index != uint.MaxValue && index >= (uint)sceneTypes)
                {
                    throw r.ErrorAt(at, $"scene type index {index} is past the region's {sceneTypes} scene types");
                }

                indices[s] = index == uint.MaxValue ? -1 : (int)index;
            }

            types[i] = new TerrainTypeInfo(name, color, Array.AsReadOnly(indices));
        }

        return types;
    }

    /// <summary>A legacy string: a 16-bit length (0xFFFF: a 32-bit length follows), the characters, zeros to a multiple of
    /// four from the entry's start. A trailing zero character is dropped, as retail drops it.</summary>
    // retail: AC1Legacy::PStringBase<char>::UnPack (acclient.c:296508)
    private static string ReadPString(ref RetailDataReader r, string what, bool keep)
    {
        int lengthAt = r.Offset;
        int length = r.ReadUInt16(what);
        if (length == 0xFFFF)
        {
            lengthAt = r.Offset;
            length = r.CheckCount(r.ReadUInt32(what), what, 1, lengthAt);
        }
        else
        {
            r.CheckCount((uint)length, what, 1, lengthAt);
        }

        ReadOnlySpan<byte> chars = r.Rest.Slice(0, length);
        r.Skip(length, what);
        r.Align4();
        if (!keep)
        {
            return string.Empty;
        }

        if (chars.Length > 0 && chars[^1] == 0)
        {
            chars = chars[..^1];
        }

        return Encoding.Latin1.GetString(chars);
    }
}
