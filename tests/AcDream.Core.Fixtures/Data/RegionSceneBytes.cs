using System;
using System.Collections.Generic;
using System.Text;
using AcDream.Core.Physics.Data;

namespace AcDream.Core.Fixtures.Data;

/// <summary>A scene type to write: its sound table index (-1: none) and its scene ids (retail <c>CSceneType</c>).</summary>
internal sealed record SceneTypeDef(int SoundTable, uint[] Scenes);

/// <summary>A terrain type to write: name, colour, and each slot's scene type index (-1: none) (retail <c>CTerrainType</c>).</summary>
internal sealed record TerrainTypeDef(string Name, uint Color, int[] Slots);

/// <summary>
/// A region to write. The calendar, sky and sounds are filled with a few records of each kind (names of every length
/// modulo four, so that each alignment pad is exercised) unless switched off; <see cref="Tail"/> stands for the land surfaces
/// and the rest, which the library does not read.
/// </summary>
internal sealed record RegionDef(
    SceneTypeDef[] SceneTypes,
    TerrainTypeDef[] TerrainTypes,
    uint Id = 0x13000000,
    uint Number = 1,
    uint Version = 3,
    string Name = "Dereth",
    float[]? Heights = null,
    bool Sky = true,
    int SoundTables = 2,
    bool ScenePart = true,
    uint ExtraMask = 0,
    byte[]? Tail = null,
    uint SkyReplaceIndex = 1);

/// <summary>
/// Writes region (0x13…) and scene (0x12…) entries in retail's byte layouts, field by field in the order the decompiled
/// <c>CRegionDesc::UnPack</c> (acclient.c:299775), <c>Scene::UnPack</c> (463119) and <c>ObjectDesc::UnPack</c> (462929) read
/// them (retail's <c>Scene::Pack</c>, 463063, writes the same). Every entry starts with its id (read by <c>DBObj</c> before
/// the <c>UnPack</c>). Alignment: a name pads to a multiple of four counted from the entry's first byte
/// (<c>PStringBase&lt;char&gt;::UnPack</c> pads the pointer, acclient.c:296508, of a heap buffer holding the entry; every other
/// field is a whole 32- or 64-bit word, so nothing else pads). The data files are not word-aligned
/// (<c>Archive::CheckAlignment</c>, acclient.c:70280, pads only archives with its alignment flag), so no pad is counted from a
/// file offset.
/// </summary>
internal static class RegionSceneBytes
{
    /// <summary>The heights <c>2 · i</c> metres (the real table's first 201 entries have this form).</summary>
    public static float[] MetreHeights()
    {
        var h = new float[256];
        for (int i = 0; i < h.Length; i++)
        {
            h[i] = 2f * i;
        }

        return h;
    }

    /// <summary>One scene entry: id, count, then each spot in <c>ObjectDesc::UnPack</c> order (76 bytes).</summary>
    public static byte[] Scene(uint id, IReadOnlyList<ObjectDesc> spots)
    {
        var w = new RetailDataWriter();
        w.UInt32(id).UInt32((uint)spots.Count);
        foreach (ObjectDesc d in spots)
        {
            ObjectSpot(w, d);
        }

        return w.ToArray();
    }

    /// <summary>One spot: id, frame (origin, w x y z), freq, displace x y, min max scale, max rotation, min max slope, align,
    /// orient, weenie object.</summary>
    public static void ObjectSpot(RetailDataWriter w, ObjectDesc d)
    {
        w.UInt32(d.ObjectId).Frame(d.BaseFrame).Single(d.Frequency).Single(d.DisplaceX).Single(d.DisplaceY)
         .Single(d.MinScale).Single(d.MaxScale).Single(d.MaxRotation).Single(d.MinSlope).Single(d.MaxSlope)
         .UInt32(d.Align).UInt32(d.Orient).UInt32(d.WeenieObj);
    }

    /// <summary>A legacy string: 16-bit length (0xFFFF then a 32-bit length when longer), the characters, the pad.</summary>
    public static void PString(RetailDataWriter w, string s)
    {
        byte[] b = Encoding.Latin1.GetBytes(s);
        if (b.Length >= 0xFFFF)
        {
            w.UInt16(0xFFFF).UInt32((uint)b.Length);
        }
        else
        {
            w.UInt16((ushort)b.Length);
        }

        w.Bytes(b).Align4();
    }

    /// <summary>A whole region entry.</summary>
    public static byte[] Region(RegionDef def)
    {
        var w = new RetailDataWriter();
        w.UInt32(def.Id).UInt32(def.Number).UInt32(def.Version);
        PString(w, def.Name);
        // The eight LandDefs values retail reads and discards: blocks per side (twice), square length, cells per block,
        // vertices per cell, max object height, sky height, road width.
        w.UInt32(255).UInt32(255).Single(24f).UInt32(8).UInt32(1).Single(200f).Single(1000f).Single(5f);
        foreach (float h in def.Heights ?? MetreHeights())
        {
            w.Single(h);
        }

        GameTime(w);
        uint mask = def.ExtraMask | (def.Sky ? 0x10u : 0u) | (def.SoundTables > 0 ? 0x01u : 0u) | (def.ScenePart ? 0x02u : 0u);
        w.UInt32(mask);
        if (def.Sky)
        {
            Sky(w, def.SkyReplaceIndex);
        }

        if (def.SoundTables > 0)
        {
            w.UInt32((uint)def.SoundTables);
            for (int t = 0; t < def.SoundTables; t++)
            {
                // AmbientSTBDesc: table id, count, then type, volume, base chance, min rate, max rate.
                w.UInt32(0x20000001u + (uint)t).UInt32(2);
                for (int s = 0; s < 2; s++)
                {
                    w.UInt32((uint)(s + 1)).Single(0.5f).Single(0.25f).Single(1f).Single(4f);
                }
            }
        }

        if (def.ScenePart)
        {
            w.UInt32((uint)def.SceneTypes.Length);
            foreach (SceneTypeDef st in def.SceneTypes)
            {
                w.Int32(st.SoundTable).UInt32((uint)st.Scenes.Length);
                foreach (uint s in st.Scenes)
                {
                    w.UInt32(s);
                }
            }
        }

        w.UInt32((uint)def.TerrainTypes.Length);
        foreach (TerrainTypeDef tt in def.TerrainTypes)
        {
            PString(w, tt.Name);
            w.UInt32(tt.Color).UInt32((uint)tt.Slots.Length);
            foreach (int s in tt.Slots)
            {
                w.Int32(s);
            }
        }

        return w.Bytes(def.Tail ?? [0x4C, 0x53, 0x55, 0x52]).ToArray();
    }

    /// <summary>The calendar (<c>GameTime::UnPack</c>, acclient.c:464013): zero time (f64), zero year, day length, days per
    /// year, year name; three times of day (start, night flag, name), two week days, four seasons (first day, name).</summary>
    private static void GameTime(RetailDataWriter w)
    {
        w.Int32(0).Int32(0x40000000).UInt32(10).Single(7620f).UInt32(360);
        PString(w, "P.Y.");
        string[] times = ["Morning", "Midsong", "Darktide"];
        w.UInt32((uint)times.Length);
        for (int i = 0; i < times.Length; i++)
        {
            w.Single(0.25f * i).UInt32(i == 2 ? 1u : 0u);
            PString(w, times[i]);
        }

        w.UInt32(2);
        PString(w, "Gaerlan");
        PString(w, "Wi");
        string[] seasons = ["Snow", "Cold", "Thaw", "Spring"];
        w.UInt32((uint)seasons.Length);
        for (int i = 0; i < seasons.Length; i++)
        {
            w.UInt32((uint)(90 * i));
            PString(w, seasons[i]);
        }
    }

    /// <summary>The sky (<c>SkyDesc::UnPack</c>, acclient.c:302821): two tick sizes (f64), one day group (chance, name, two
    /// sky objects of nine words, one sky time of eleven words with one replacement of six words naming a sky object).</summary>
    private static void Sky(RetailDataWriter w, uint replaceIndex)
    {
        w.Int32(0).Int32(0x3FF00000).Int32(0).Int32(0x3FF00000).UInt32(1);
        w.Single(1f);
        PString(w, "Sunny");
        w.UInt32(2);
        for (int i = 0; i < 2 * 9; i++)
        {
            w.UInt32((uint)i);
        }

        w.UInt32(1);
        for (int i = 0; i < 11; i++)
        {
            w.UInt32((uint)(100 + i));
        }

        w.UInt32(1).UInt32(replaceIndex).UInt32(0x01000001).Single(0f).Single(0f).Single(1f).Single(1f);
    }
}
