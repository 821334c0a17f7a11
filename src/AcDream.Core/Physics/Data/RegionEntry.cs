using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Core.Physics.Data;

/// <summary>A scene type of the region (retail <c>CSceneType</c>, acclient.h:53051): the scenes a terrain vertex of this
/// type picks from, and its ambient sound table.</summary>
/// <param name="SoundTableIndex">Index into the region's ambient sound tables, -1 for none. Retail: <c>sound_table_desc</c>
/// (a pointer, resolved from this index by <c>CRegionDesc::UnPack</c>).</param>
/// <param name="Scenes">The scene ids (0x12xxxxxx). Retail: <c>scenes</c>.</param>
public sealed record SceneTypeInfo(int SoundTableIndex, IReadOnlyList<uint> Scenes);

/// <summary>A terrain type of the region (retail <c>CTerrainType</c>, acclient.h:53067): its name, colour, and the scene
/// type of each scene-type slot (bits 11–15 of a terrain word).</summary>
/// <param name="Name">Retail: <c>terrain_name</c>.</param>
/// <param name="Color">Retail: <c>terrain_color</c> (ARGB).</param>
/// <param name="SceneTypes">Per slot, the index into <see cref="RegionEntry.SceneTypes"/>, or -1 for none (retail's null
/// pointer). Retail: <c>scene_types</c>.</param>
public sealed record TerrainTypeInfo(string Name, uint Color, IReadOnlyList<int> SceneTypes);

/// <summary>
/// The region (data-file entry 0x13xxxxxx; Dereth is 0x13000000) as retail's <c>CRegionDesc::UnPack</c> reads it, as far
/// as the physics and the scenery need: the land height table, the scene types and the terrain types. The calendar, the
/// sky and the ambient sounds before them are walked byte for byte and not kept; nothing after the terrain types (the land
/// surfaces, <c>RegionMisc</c>) is read.
/// </summary>
public sealed partial class RegionEntry
{
    /// <summary>The only region version retail accepts (acclient.c:299775, a modal error otherwise).</summary>
    public const uint RetailVersion = 3;

    /// <summary>Parts-mask bit: a sky description follows the calendar.</summary>
    public const uint SkyPart = 0x10;

    /// <summary>Parts-mask bit: the ambient sound tables follow.</summary>
    public const uint SoundPart = 0x01;

    /// <summary>Parts-mask bit: the scene types follow.</summary>
    public const uint ScenePart = 0x02;

    private readonly SceneTypeInfo[] _sceneTypes;
    private readonly TerrainTypeInfo[] _terrainTypes;

    private RegionEntry(uint id, uint number, string name, LandHeightTable heights, uint partsMask, int soundTableCount,
        SceneTypeInfo[] sceneTypes, TerrainTypeInfo[] terrainTypes)
    {
        Id = id;
        RegionNumber = number;
        Name = name;
        LandHeightTable = heights;
        PartsMask = partsMask;
        SoundTableCount = soundTableCount;
        _sceneTypes = sceneTypes;
        _terrainTypes = terrainTypes;
        SceneTypes = Array.AsReadOnly(sceneTypes);
        TerrainTypes = Array.AsReadOnly(terrainTypes);
    }

    /// <summary>The entry id (0x13xxxxxx).</summary>
    public uint Id { get; }

    /// <summary>Retail: <c>region_number</c> (1 for Dereth).</summary>
    public uint RegionNumber { get; }

    /// <summary>Retail: <c>region_name</c> ("Dereth").</summary>
    public string Name { get; }

    /// <summary>The 256 land heights, in metres, as the library's table (retail <c>LandDefs::set_height_table</c>,
    /// acclient.c:467321, called from the unpack).</summary>
    public LandHeightTable LandHeightTable { get; }

    /// <summary>Which optional parts the entry holds (<see cref="SkyPart"/>, <see cref="SoundPart"/>,
    /// <see cref="ScenePart"/>, …). Retail: <c>parts_mask</c>.</summary>
    public uint PartsMask { get; }

    /// <summary>How many ambient sound tables the entry holds (walked, not kept).</summary>
    public int SoundTableCount { get; }

    /// <summary>The scene types (retail <c>scene_info</c>, a <c>CSceneDesc</c>).</summary>
    public IReadOnlyList<SceneTypeInfo> SceneTypes { get; }

    /// <summary>The terrain types, by terrain type number 0–31 (retail <c>terrain_info</c>'s <c>terrain_types</c>).</summary>
    public IReadOnlyList<TerrainTypeInfo> TerrainTypes { get; }

    /// <summary>The number of scene-type slots of <paramref name="terrainType"/>; 0 for a type the region does not have.</summary>
    // retail: CRegionDesc::NumSceneType (acclient.c:298924) -> CTerrainDesc::NumSceneType (acclient.c:303305)
    public int NumSceneType(uint terrainType) =>
        terrainType < (uint)_terrainTypes.Length ? _terrainTypes[terrainType].SceneTypes.Count : 0;

    /// <summary>The number of scenes of slot <paramref name="sceneTypeSlot"/> of <paramref name="terrainType"/>; 0 for a
    /// type or slot the region does not have, and for a slot with no scene type.</summary>
    // retail: CRegionDesc::SceneCount (acclient.c:298930) -> CTerrainDesc::SceneCount (acclient.c:303317)
    public int SceneCount(uint terrainType, uint sceneTypeSlot)
    {
        SceneTypeInfo? st = SceneTypeOf(terrainType, sceneTypeSlot);
        return st is null ? 0 : st.Scenes.Count;
    }

    /// <summary>The id of scene <paramref name="sceneIndex"/> of slot <paramref name="sceneTypeSlot"/> of
    /// <paramref name="terrainType"/>; 0 (retail's null id) when the index is past the list, and (where retail would read
    /// through a null pointer) when the type or slot does not exist or has no scene type.</summary>
    // retail: CRegionDesc::GetScene (acclient.c:299037) -> CTerrainDesc::GetScene (acclient.c:303333)
    public uint GetScene(uint terrainType, uint sceneTypeSlot, uint sceneIndex)
    {
        SceneTypeInfo? st = SceneTypeOf(terrainType, sceneTypeSlot);
        return st is not null && sceneIndex < (uint)st.Scenes.Count ? st.Scenes[(int)sceneIndex] : 0u;
    }

    private SceneTypeInfo? SceneTypeOf(uint terrainType, uint slot)
    {
        if (terrainType >= (uint)_terrainTypes.Length)
        {
            return null;
        }

        IReadOnlyList<int> slots = _terrainTypes[terrainType].SceneTypes;
        if (slot >= (uint)slots.Count)
        {
            return null;
        }

        int index = slots[(int)slot];
        return index < 0 ? null : _sceneTypes[index];
    }
}
