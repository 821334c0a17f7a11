using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Core.Tests.Support.Shared;

/// <summary>Hand-made terrain for the tests and the benchmarks (compiled into both; no xunit here): a height table of one
/// metre per index, landblocks from a height function, outdoor cell ids, and positions standing on the ground.</summary>
internal static class SyntheticTerrain
{
    /// <summary>A height table with exactly one metre per index (index i -> i m; all within retail's 0..800 rule).</summary>
    public static LandHeightTable MetreTable()
    {
        var h = new float[LandHeightTable.Count];
        for (int i = 0; i < h.Length; i++)
        {
            h[i] = i;
        }

        return new LandHeightTable(h);
    }

    /// <summary>A terrain world with the one-metre table.</summary>
    public static TerrainWorld Metres() => new(MetreTable());

    /// <summary>A terrain world with the one-metre table and one flat landblock (bx, by) at height index
    /// <paramref name="heightIndex"/> (with the one-metre table, the ground is the plane z = heightIndex).</summary>
    public static TerrainWorld FlatBlock(int bx, int by, int heightIndex)
    {
        TerrainWorld terrain = Metres();
        AddBlock(terrain, bx, by, (_, _) => heightIndex);
        return terrain;
    }

    /// <summary>Adds landblock (bx, by) whose vertex (vx, vy) has height index <paramref name="height"/>(vx, vy) and terrain type
    /// <paramref name="type"/>(vx, vy) (1 when null: grass-like solid; 16..20 water).</summary>
    public static LandBlock AddBlock(TerrainWorld world, int bx, int by, Func<int, int, int> height, Func<int, int, int>? type = null)
    {
        var heights = new byte[81];
        var terrain = new ushort[81];
        for (int vx = 0; vx < 9; vx++)
        {
            for (int vy = 0; vy < 9; vy++)
            {
                heights[vx * 9 + vy] = checked((byte)height(vx, vy));
                terrain[vx * 9 + vy] = TerrainTypes.MakeWord(0, type?.Invoke(vx, vy) ?? 1);
            }
        }

        return world.AddLandBlock(LandBlock.MakeId(bx, by), heights, terrain);
    }

    /// <summary>Outdoor cell id of cell (cx, cy) (each 0..7) of landblock (bx, by).</summary>
    public static uint CellId(int bx, int by, int cx, int cy) => ((uint)bx << 24) | ((uint)by << 16) | (uint)(cx * 8 + cy + 1);

    /// <summary>The terrain height under an outdoor position, metres; throws when there is no terrain under it.</summary>
    public static float Ground(TerrainWorld terrain, in Position p)
    {
        if (!terrain.TryGetTerrainHeight(p, out float z))
        {
            throw new InvalidOperationException("No terrain under the position.");
        }

        return z;
    }

    /// <summary>The position (x, y) of outdoor cell <paramref name="cellId"/> facing <paramref name="heading"/> degrees, standing
    /// <paramref name="lift"/> metres above the terrain under it.</summary>
    public static Position OnGround(TerrainWorld terrain, uint cellId, float x, float y, float heading = 0f, float lift = 0f)
    {
        var p = new Position(cellId, Frame.FromHeading(new Vector3(x, y, 0f), heading));
        p.Frame.Origin = new Vector3(x, y, Ground(terrain, p) + lift);
        return p;
    }
}
