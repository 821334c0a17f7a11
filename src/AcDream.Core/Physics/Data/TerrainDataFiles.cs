using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Core.Physics.Data;

/// <summary>
/// Readers for the plain-text terrain fixtures: the land height table CSV (<c>index,height_m</c>) and the landblock
/// sample CSV (<c>landblock,vx,vy,ac_index,height_index,height_m,terrain_type,road</c>). Load-time only; they allocate.
/// </summary>
public static class TerrainDataFiles
{
    /// <summary>Reads a land height table CSV: a header line, then 256 lines <c>index,height_m</c> for indices 0..255.</summary>
    /// <exception cref="InvalidDataException">A malformed line, an index outside 0..255, a repeated or missing index.</exception>
    /// <exception cref="ArgumentException">A height outside 0..800 m (see <see cref="LandHeightTable"/>).</exception>
    public static LandHeightTable ReadHeightTableCsv(string path)
    {
        var heights = new float[LandHeightTable.Count];
        var seen = new bool[LandHeightTable.Count];
        int lineNo = 0;
        foreach (string line in File.ReadLines(path))
        {
            lineNo++;
            if (lineNo == 1 || line.Length == 0)
            {
                continue;
            }

            string[] f = line.Split(',');
            if (f.Length != 2
                || !int.TryParse(f[0], NumberStyles.Integer, CultureInfo.InvariantCulture, out int index)
                || !float.TryParse(f[1], NumberStyles.Float, CultureInfo.InvariantCulture, out float h)
                || (uint)index >= LandHeightTable.Count
                || seen[index])
            {
                throw new InvalidDataException($"{path}:{lineNo}: expected a new 'index,height_m' with index 0..255.");
            }

            seen[index] = true;
            heights[index] = h;
        }

        if (Array.IndexOf(seen, false) >= 0)
        {
            throw new InvalidDataException($"{path}: the table does not list all 256 indices.");
        }

        return new LandHeightTable(heights);
    }

    /// <summary>
    /// Reads the landblock sample CSV: 81 rows per landblock, the landblock written <c>0xXXYY</c>, the terrain word made
    /// from <c>terrain_type</c> and <c>road</c> (scene bits 0). Landblocks are returned in first-appearance order.
    /// </summary>
    /// <exception cref="InvalidDataException">A malformed row, <c>ac_index != vx * 9 + vy</c>, or a landblock without
    /// exactly its 81 vertices.</exception>
    public static IReadOnlyList<LandBlockEntry> ReadLandblockSampleCsv(string path)
    {
        var order = new List<uint>();
        var heights = new Dictionary<uint, byte[]>();
        var terrains = new Dictionary<uint, ushort[]>();
        var counts = new Dictionary<uint, int>();
        int lineNo = 0;
        foreach (string line in File.ReadLines(path))
        {
            lineNo++;
            if (lineNo == 1 || line.Length == 0)
            {
                continue;
            }

            string[] f = line.Split(',');
            if (f.Length != 8
                || !f[0].StartsWith("0x", StringComparison.OrdinalIgnoreCase)
                || !uint.TryParse(f[0].AsSpan(2), NumberStyles.HexNumber, CultureInfo.InvariantCulture, out uint lb)
                || lb > 0xFFFF
                || !int.TryParse(f[1], NumberStyles.Integer, CultureInfo.InvariantCulture, out int vx)
                || !int.TryParse(f[2], NumberStyles.Integer, CultureInfo.InvariantCulture, out int vy)
                || !int.TryParse(f[3], NumberStyles.Integer, CultureInfo.InvariantCulture, out int acIndex)
                || !byte.TryParse(f[4], NumberStyles.Integer, CultureInfo.InvariantCulture, out byte heightIndex)
                || !int.TryParse(f[6], NumberStyles.Integer, CultureInfo.InvariantCulture, out int type)
                || !int.TryParse(f[7], NumberStyles.Integer, CultureInfo.InvariantCulture, out int road)
                || (uint)vx > 8 || (uint)vy > 8 || acIndex != vx * 9 + vy
                || (uint)type > 31 || (uint)road > 3)
            {
                throw new InvalidDataException($"{path}:{lineNo}: malformed landblock sample row.");
            }

            uint id = (lb << 16) | 0xFFFFu;
            if (!heights.TryGetValue(id, out byte[]? h))
            {
                h = new byte[LandBlock.VertexCount];
                heights[id] = h;
                terrains[id] = new ushort[LandBlock.VertexCount];
                counts[id] = 0;
                order.Add(id);
            }

            h[acIndex] = heightIndex;
            terrains[id][acIndex] = TerrainTypes.MakeWord(road, type);
            counts[id]++;
        }

        var result = new List<LandBlockEntry>(order.Count);
        foreach (uint id in order)
        {
            if (counts[id] != LandBlock.VertexCount)
            {
                throw new InvalidDataException($"{path}: landblock 0x{id:X8} has {counts[id]} rows, not {LandBlock.VertexCount}.");
            }

            result.Add(new LandBlockEntry(id, heights[id], terrains[id]));
        }

        return result;
    }
}
