using System;

namespace AcDream.Core.Physics.Terrain;

/// <summary>
/// The surface character of a terrain type: solid ground or water. Retail: <c>enum SURFCHAR</c> (acclient.h:3618).
/// </summary>
public enum SurfChar
{
    /// <summary>Solid ground. Retail: <c>SOLID = 0</c>.</summary>
    Solid = 0,

    /// <summary>Water. Retail: <c>WATER = 1</c>.</summary>
    Water = 1,
}

/// <summary>
/// Terrain-type helpers: the 32 terrain types and their surface character, and the packing of the 16-bit terrain word.
/// </summary>
/// <remarks>The terrain word of a landblock vertex packs the road bits (0-1), the terrain type (bits 2-6) and the scene type
/// (bits 11-15). Retail reads the type as <c>(LOBYTE(word) &gt;&gt; 2) &amp; 0x1F</c>.</remarks>
public static class TerrainTypes
{
    /// <summary>The number of terrain types (5 bits).</summary>
    public const int Count = 32;

    /// <summary>The first water terrain type (16). Types 16..20 are water in <c>TERRAIN_SURF_CHAR</c>.</summary>
    public const int FirstWaterType = 16;

    /// <summary>The last water terrain type (20).</summary>
    public const int LastWaterType = 20;

    /// <summary>
    /// The surface character of terrain type <paramref name="terrainType"/> (0..31): types 16..20 are
    /// <see cref="SurfChar.Water"/>, all others <see cref="SurfChar.Solid"/>.
    /// Retail: the table <c>TERRAIN_SURF_CHAR[32]</c> (acclient_data.h:2356; a second copy at :2395).
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="terrainType"/> is outside 0..31.</exception>
    public static SurfChar SurfCharOf(int terrainType)
    {
        if ((uint)terrainType >= Count)
        {
            throw new ArgumentOutOfRangeException(nameof(terrainType), terrainType, "Terrain types are 0..31.");
        }

        return terrainType >= FirstWaterType && terrainType <= LastWaterType ? SurfChar.Water : SurfChar.Solid;
    }

    /// <summary>The terrain type (0..31) packed in a terrain word: <c>(word &gt;&gt; 2) &amp; 0x1F</c>.</summary>
    public static int TypeOf(ushort terrainWord) => (terrainWord >> 2) & 0x1F;

    /// <summary>The road bits (0..3) packed in a terrain word.</summary>
    public static int RoadOf(ushort terrainWord) => terrainWord & 3;

    /// <summary>The scene type (0..31) packed in a terrain word: <c>word &gt;&gt; 11</c>.</summary>
    public static int SceneOf(ushort terrainWord) => terrainWord >> 11;

    /// <summary>Packs a terrain word from its road bits, terrain type and scene type.</summary>
    /// <exception cref="ArgumentOutOfRangeException">A field is out of its range (road 0..3, type 0..31, scene 0..31).</exception>
    public static ushort MakeWord(int road, int terrainType, int scene = 0)
    {
        if ((uint)road > 3)
        {
            throw new ArgumentOutOfRangeException(nameof(road), road, "Road bits are 0..3.");
        }

        if ((uint)terrainType >= Count)
        {
            throw new ArgumentOutOfRangeException(nameof(terrainType), terrainType, "Terrain types are 0..31.");
        }

        if ((uint)scene > 31)
        {
            throw new ArgumentOutOfRangeException(nameof(scene), scene, "Scene types are 0..31.");
        }

        return (ushort)(road | (terrainType << 2) | (scene << 11));
    }

    /// <summary>True when the terrain word's type is water (its surface character is <see cref="SurfChar.Water"/>).</summary>
    internal static bool IsWater(ushort terrainWord)
    {
        int t = TypeOf(terrainWord);
        return t >= FirstWaterType && t <= LastWaterType;
    }
}
