using System;
using System.Collections.Generic;
using System.Linq;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Scenery;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Cost of the procedural scenery (docs/world.md, "Procedural scenery"): unpacking a region (32 terrain types of four slots,
/// three scene types, a calendar, sky and sounds) and a scene of three spots, and generating one landblock's placements —
/// from a built <see cref="LandBlock"/> with a scene lookup (the pure generation), and from the entry and a data source
/// (the landblock built and the scenes unpacked as well). The block is 0xA9B4 with rolling heights, a road along column 4,
/// and every vertex's scene slot from the hash; the scenes hold 1 to 3 spots of various frequencies, displacements, slopes.
/// </summary>
[MemoryDiagnoser]
public class SceneryBenchmarks
{
    private byte[] _region = null!;
    private byte[] _scene = null!;
    private RegionEntry _regionEntry = null!;
    private LandBlock _block = null!;
    private LandBlockEntry _blockEntry = null!;
    private Func<uint, SceneEntry?> _lookup = null!;
    private Source _source = null!;
    private readonly List<ScenePlacement> _placements = new();

    private sealed class Source(Dictionary<uint, byte[]> entries) : IRetailDataSource
    {
        public bool TryGetEntry(uint id, out ReadOnlyMemory<byte> bytes)
        {
            bool ok = entries.TryGetValue(id, out byte[]? b);
            bytes = b;
            return ok;
        }
    }

    private static ObjectDesc Spot(uint id, float freq, float dx, float minScale, float maxScale, float minSlope, uint align = 0)
    {
        Frame f = Frame.Identity;
        f.Origin = new System.Numerics.Vector3(3f, -2f, 0f);
        return new ObjectDesc(id, f, freq, dx, dx, minScale, maxScale, 360f, minSlope, 1f, align, 0, 0);
    }

    /// <summary>Writes the entries and builds the block.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _region = RegionSceneBytes.Region(new RegionDef(
            SceneTypes: [new SceneTypeDef(0, [0x12000001]), new SceneTypeDef(1, [0x12000002, 0x12000003, 0x12000004]), new SceneTypeDef(-1, [0x12000005, 0x12000006])],
            TerrainTypes: Enumerable.Range(0, 32).Select(t => new TerrainTypeDef($"Type{t}", (uint)t, [-1, 0, 1, 2])).ToArray()));
        _regionEntry = RegionEntry.UnPack(_region);
        var scenes = new Dictionary<uint, byte[]>();
        for (uint s = 1; s <= 6; s++)
        {
            ObjectDesc[] spots = Enumerable.Range(0, (int)(s % 3) + 1)
                .Select(k => Spot(0x02000100u + s * 8 + (uint)k, 0.3f + 0.2f * k, 2f + 4f * k, 0.7f, 1.5f, 0.1f * k, (uint)(k & 1)))
                .ToArray();
            scenes[0x12000000u + s] = RegionSceneBytes.Scene(0x12000000u + s, spots);
        }

        _scene = scenes[0x12000002];
        var parsed = scenes.ToDictionary(kv => kv.Key, kv => SceneEntry.UnPack(kv.Value));
        _lookup = id => parsed.TryGetValue(id, out SceneEntry? e) ? e : null;
        _source = new Source(scenes);
        var h = new byte[81];
        var t = new ushort[81];
        for (int i = 0; i < 9; i++)
        {
            for (int j = 0; j < 9; j++)
            {
                h[i * 9 + j] = (byte)(40 + (i * 7 + j * 3) % 11);
                uint slot = SceneryHash.Hash(1352u + (uint)i, 1440u + (uint)j, 0x5107) % 4;
                t[i * 9 + j] = (ushort)((slot << 11) | ((uint)(i + j) % 32 << 2) | (i == 4 ? 1u : 0u));
            }
        }

        _blockEntry = new LandBlockEntry(0xA9B4FFFF, h, t);
        _block = _blockEntry.ToLandBlock(_regionEntry.LandHeightTable);
    }

    /// <summary><c>CRegionDesc::UnPack</c> up to the terrain types.</summary>
    [Benchmark]
    public RegionEntry Region() => RegionEntry.UnPack(_region);

    /// <summary><c>Scene::UnPack</c>: three spots.</summary>
    [Benchmark]
    public SceneEntry Scene() => SceneEntry.UnPack(_scene);

    /// <summary>One landblock's placements from the built block and parsed scenes (the pure generation).</summary>
    [Benchmark]
    public int GenerateBlock()
    {
        _placements.Clear();
        return SceneryGenerator.Generate(_block, _regionEntry, _lookup, null, _placements);
    }

    /// <summary>One landblock's placements from its entry and a data source (block built, scenes unpacked).</summary>
    [Benchmark]
    public int GenerateFromEntry()
    {
        _placements.Clear();
        return SceneryGenerator.Generate(_blockEntry, _regionEntry, _source, null, _placements);
    }
}
