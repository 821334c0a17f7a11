using System;
using System.Collections.Generic;
using System.IO;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Tests.Support.Shared;
using Xunit;
using AcDream.Core.Physics.Data;

namespace AcDream.Core.Tests.Support;

/// <summary>
/// A fact that needs the real Dereth terrain fixtures (heightfield and land height table). They are not in the repository:
/// the folder is found as the report finds it (<see cref="TerrainDataDir"/>: <c>ACDREAM_TERRAIN_DIR</c>, a relative value
/// resolved against the repository root, else ../shared/data/ac-terrain beside the repository); when it is not found the test
/// is skipped with the reason, and <c>TerrainDataReportTests</c> prints the same reason in every run.
/// </summary>
public sealed class TerrainDataFactAttribute : FactAttribute
{
    /// <summary>Skips the test when the fixtures are not found.</summary>
    public TerrainDataFactAttribute()
    {
        if (TerrainTestData.FindDir(out string reason) is null)
        {
            Skip = "Real terrain data not found: " + reason + ".";
        }
    }
}

/// <summary>Shared terrain scene builders: the real fixtures (loaded once) and small synthetic landblocks.</summary>
internal static class TerrainTestData
{
    public const string Variable = TerrainDataDir.Variable;

    private static readonly Lazy<(string? Dir, string Reason)> Found = new(() => (TerrainDataDir.Find(out string reason), reason));

    private static readonly Lazy<LandHeightTable> RealTableLazy = new(() =>
        TerrainDataFiles.ReadHeightTableCsv(Path.Combine(Dir, "land_height_table.csv")));

    private static readonly Lazy<IReadOnlyList<LandBlockEntry>> SampleLazy = new(() =>
        TerrainDataFiles.ReadLandblockSampleCsv(Path.Combine(Dir, "landblock_heights_sample.csv")));

    private static readonly Lazy<TerrainImage> ImageLazy = new(() => TerrainImage.Load(Path.Combine(Dir, "terrain.png")));

    /// <summary>The fixtures folder (see <see cref="TerrainDataDir"/>); throws when it is not found.</summary>
    public static string Dir => Found.Value.Dir ?? throw new InvalidOperationException("Real terrain data not found: " + Found.Value.Reason);

    /// <summary>The fixtures folder, or null with the reason.</summary>
    public static string? FindDir(out string reason)
    {
        reason = Found.Value.Reason;
        return Found.Value.Dir;
    }

    /// <summary>The real land height table.</summary>
    public static LandHeightTable RealTable => RealTableLazy.Value;

    /// <summary>The 12 sample landblocks of landblock_heights_sample.csv.</summary>
    public static IReadOnlyList<LandBlockEntry> Sample => SampleLazy.Value;

    /// <summary>The whole heightfield (terrain.png).</summary>
    public static TerrainImage Image => ImageLazy.Value;

    /// <summary>The sample landblock with id 0xXXYYFFFF.</summary>
    public static LandBlockEntry SampleBlock(uint blockId)
    {
        foreach (LandBlockEntry d in Sample)
        {
            if (d.Id == blockId)
            {
                return d;
            }
        }

        throw new InvalidOperationException($"Landblock 0x{blockId:X8} is not in the sample.");
    }

    /// <summary>A world holding the given sample landblocks.</summary>
    public static TerrainWorld SampleWorld(params uint[] blockIds)
    {
        var world = new TerrainWorld(RealTable);
        foreach (uint id in blockIds)
        {
            LandBlockEntry d = SampleBlock(id);
            world.AddLandBlock(d.Id, d.Height, d.Terrain);
        }

        return world;
    }

    /// <summary>A synthetic table: index i maps to i metres (test-only; the real table is data).</summary>
    public static LandHeightTable IdentityTable() => SyntheticTerrain.MetreTable();

    /// <summary>81 height indices from a function of the vertex (vx, vy).</summary>
    public static byte[] Heights(Func<int, int, int> f)
    {
        var h = new byte[81];
        for (int vx = 0; vx < 9; vx++)
        {
            for (int vy = 0; vy < 9; vy++)
            {
                h[vx * 9 + vy] = (byte)f(vx, vy);
            }
        }

        return h;
    }

    /// <summary>81 terrain words, all of terrain type <paramref name="type"/>.</summary>
    public static ushort[] Terrain(int type)
    {
        var t = new ushort[81];
        Array.Fill(t, TerrainTypes.MakeWord(0, type));
        return t;
    }

    /// <summary>Sets vertex (vx, vy) of a terrain array to <paramref name="type"/>.</summary>
    public static void SetType(ushort[] terrain, int vx, int vy, int type) => terrain[vx * 9 + vy] = TerrainTypes.MakeWord(0, type);
}
