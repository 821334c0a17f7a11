using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Scenery;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Core.Tests.Support;

/// <summary>
/// Synthetic scenery scenes: a region whose terrain type 1 has slots [none, scene type 0, scene type 1] (scene type 0 holds
/// one scene, 0x12000010; scene type 1 holds three, 0x12000020–22), scenes built from spots, and landblocks of block
/// 0xA9B4 (vertex (0, 0) is global (1352, 1440)) with chosen heights, slots and roads. Written through the fixtures'
/// byte writers and read back, as a client's data would be.
/// </summary>
internal static class SceneryScene
{
    public const uint BlockId = 0xA9B4FFFF;
    public const uint SingleScene = 0x12000010;
    public static readonly uint[] TripleScenes = [0x12000020, 0x12000021, 0x12000022];

    public static RegionEntry Region() => RegionEntry.UnPack(RegionBytes());

    /// <summary>The region's bytes (see <see cref="Region"/>), for a data source.</summary>
    public static byte[] RegionBytes() => RegionSceneBytes.Region(new RegionDef(
        SceneTypes: [new SceneTypeDef(-1, [SingleScene]), new SceneTypeDef(-1, TripleScenes)],
        TerrainTypes:
        [
            new TerrainTypeDef("Water", 0, []),
            new TerrainTypeDef("Grassland", 0, [-1, 0, 1]),
        ],
        Sky: false,
        SoundTables: 0));

    /// <summary>The terrain word of type <paramref name="type"/>, scene slot <paramref name="slot"/>, road bits
    /// <paramref name="road"/>.</summary>
    public static ushort Word(int type, int slot, int road = 0) => (ushort)((slot << 11) | (type << 2) | road);

    /// <summary>A block of block 0xA9B4 with every terrain word <paramref name="word"/> and height index
    /// <c>height(i, j)</c>, heights 2 · index metres.</summary>
    public static LandBlock Block(ushort word, Func<int, int, int>? height = null, Func<int, int, ushort>? words = null)
    {
        var h = new byte[81];
        var t = new ushort[81];
        for (int i = 0; i < 9; i++)
        {
            for (int j = 0; j < 9; j++)
            {
                h[i * 9 + j] = (byte)(height?.Invoke(i, j) ?? 10);
                t[i * 9 + j] = words?.Invoke(i, j) ?? word;
            }
        }

        return new LandBlock(BlockId, h, t, new LandHeightTable(RegionSceneBytes.MetreHeights()));
    }

    /// <summary>A spot (see <c>ObjectDesc</c>), defaults: always placed, no displacement, scale 1, no rotation, any slope.</summary>
    public static ObjectDesc Spot(Vector3 origin, uint id = 0x02000001, float freq = 1f, float dx = 0f, float dy = 0f,
        float minScale = 1f, float maxScale = 1f, float maxRot = 0f, float minSlope = 0f, float maxSlope = 1f, uint align = 0,
        uint weenie = 0)
    {
        Frame f = Frame.Identity;
        f.Origin = origin;
        return new ObjectDesc(id, f, freq, dx, dy, minScale, maxScale, maxRot, minSlope, maxSlope, align, 0, weenie);
    }

    /// <summary>A lookup of scenes written to bytes and read back.</summary>
    public static Func<uint, SceneEntry?> Scenes(params (uint Id, ObjectDesc[] Spots)[] scenes)
    {
        var d = new Dictionary<uint, SceneEntry>();
        foreach ((uint id, ObjectDesc[] spots) in scenes)
        {
            d[id] = SceneEntry.UnPack(RegionSceneBytes.Scene(id, spots));
        }

        return id => d.TryGetValue(id, out SceneEntry? s) ? s : null;
    }

    public static List<ScenePlacement> Generate(LandBlock block, Func<uint, SceneEntry?> scenes, Func<uint, bool>? building = null,
        RegionEntry? region = null)
    {
        var list = new List<ScenePlacement>();
        SceneryGenerator.Generate(block, region ?? Region(), scenes, building, list);
        return list;
    }

    /// <summary>The quarter turn of a vertex applied to a point, written from <c>ObjectDesc::Place</c>'s four branches.</summary>
    public static Vector2 Turn(uint x, uint y, Vector2 p)
    {
        double q = SceneryHash.Unit(x, y, SceneryHash.QuadrantSalt);
        return q < 0.25 ? p : q < 0.5 ? new Vector2(-p.Y, p.X) : q < 0.75 ? new Vector2(-p.X, -p.Y) : new Vector2(p.Y, -p.X);
    }
}
