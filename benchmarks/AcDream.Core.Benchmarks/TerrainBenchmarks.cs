using System;
using System.IO;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using BenchmarkDotNet.Attributes;
using AcDream.Core.Physics.Data;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Cost of the terrain queries the sweep and clients call: height under a position, find_terrain_poly, water depth and
/// the cell list of a two-sphere body. Scene: the Holtburg 3 × 3 landblocks (0xA8B3-0xAAB5) from the real fixtures when
/// ACDREAM_TERRAIN_DIR is set, otherwise a synthetic 3 × 3 of the same ids with random heights. Each benchmark runs
/// 1,000 queries over 1,000 precomputed random points; the mean is per query.
/// </summary>
[MemoryDiagnoser]
public class TerrainBenchmarks
{
    private const int Ops = 1000;
    private TerrainWorld _world = null!;
    private readonly Position[] _positions = new Position[Ops];
    private readonly double[] _gx = new double[Ops];
    private readonly double[] _gy = new double[Ops];
    private readonly LandCell[] _cells = new LandCell[Ops];
    private readonly Vector3[] _local = new Vector3[Ops];
    private readonly Vector3[] _centers = new Vector3[2];
    private readonly float[] _radii = [0.48f, 0.48f];
    private readonly uint[] _ids = new uint[32];

    /// <summary>Loads or synthesises the scene and the query points.</summary>
    [GlobalSetup]
    public void Setup()
    {
        string? dir = Environment.GetEnvironmentVariable("ACDREAM_TERRAIN_DIR");
        var rnd = new Random(42);
        if (!string.IsNullOrEmpty(dir))
        {
            _world = new TerrainWorld(TerrainDataFiles.ReadHeightTableCsv(Path.Combine(dir, "land_height_table.csv")));
            foreach (LandBlockEntry d in TerrainDataFiles.ReadLandblockSampleCsv(Path.Combine(dir, "landblock_heights_sample.csv")))
            {
                if (d.Id >> 24 is >= 0xA8 and <= 0xAA && ((d.Id >> 16) & 0xFF) is >= 0xB3 and <= 0xB5)
                {
                    _world.AddLandBlock(d.Id, d.Height, d.Terrain);
                }
            }
        }
        else
        {
            var table = new float[256];
            for (int i = 0; i < 256; i++)
            {
                table[i] = i < 201 ? 2f * i : 400f + (i - 200);
            }

            _world = new TerrainWorld(new LandHeightTable(table));
            var h = new byte[81];
            var t = new ushort[81];
            for (int bx = 0xA8; bx <= 0xAA; bx++)
            {
                for (int by = 0xB3; by <= 0xB5; by++)
                {
                    rnd.NextBytes(h);
                    _world.AddLandBlock(LandBlock.MakeId(bx, by), h, t);
                }
            }
        }

        double x0 = 0xA8 * 192.0, y0 = 0xB3 * 192.0;
        for (int i = 0; i < Ops; i++)
        {
            _gx[i] = x0 + rnd.NextDouble() * 576.0;
            _gy[i] = y0 + rnd.NextDouble() * 576.0;
            int bx = (int)(_gx[i] / 192.0), by = (int)(_gy[i] / 192.0);
            var local = new Vector3((float)(_gx[i] - bx * 192.0), (float)(_gy[i] - by * 192.0), 0f);
            var p = new Position(LandDefs.LCoordToGid(bx * 8, by * 8), local);
            p.AdjustToOutside();
            _positions[i] = p;
            _cells[i] = _world.GetLandCell(p.ObjCellId)!;
            _local[i] = p.Frame.Origin;
        }
    }

    /// <summary>Height under a position: adjust_to_outside, get_landcell, find_terrain_poly, Plane::set_height.</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public float HeightAtPosition()
    {
        float sum = 0f;
        for (int i = 0; i < Ops; i++)
        {
            _world.TryGetTerrainHeight(_positions[i], out float z);
            sum += z;
        }

        return sum;
    }

    /// <summary>Height at global coordinates (metres from the world's south-west corner).</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public float HeightAtGlobal()
    {
        float sum = 0f;
        for (int i = 0; i < Ops; i++)
        {
            _world.TryGetTerrainHeight(_gx[i], _gy[i], out float z);
            sum += z;
        }

        return sum;
    }

    /// <summary>CLandCell::find_terrain_poly on a known cell (two point_in_poly2D at most).</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public int FindTerrainPoly()
    {
        int found = 0;
        for (int i = 0; i < Ops; i++)
        {
            if (_cells[i].FindTerrainPoly(_local[i], out Polygon? p))
            {
                found += p.PolyId;
            }
        }

        return found;
    }

    /// <summary>Water depth under a position (cell lookup, triangle, depth rule).</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public float WaterDepth()
    {
        float sum = 0f;
        for (int i = 0; i < Ops; i++)
        {
            _world.TryGetWaterDepth(_positions[i], out float d);
            sum += d;
        }

        return sum;
    }

    /// <summary>find_cell_list for a two-sphere body (human-sized: r = 0.48, centres 0.48 and 1.35 m up).</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public int FindCellList()
    {
        int total = 0;
        for (int i = 0; i < Ops; i++)
        {
            Vector3 o = _local[i];
            _centers[0] = new Vector3(o.X, o.Y, o.Z + 0.48f);
            _centers[1] = new Vector3(o.X, o.Y, o.Z + 1.35f);
            total += _world.FindCellList(_positions[i], _centers, _radii, _ids, out _);
        }

        return total;
    }
}
