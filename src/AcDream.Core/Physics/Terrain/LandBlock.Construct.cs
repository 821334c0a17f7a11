using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Terrain;

// Building the terrain: vertices, the split rule, triangles, cells and water.
public sealed partial class LandBlock
{
    // Retail's split multipliers (acclient.c:354000), applied in wrapping 32-bit integer arithmetic.
    private const int SplitMulXY = 214614067;     // 0x0CCAC033
    private const int SplitAddY = 1813693831;     // 0x6C1AC587
    private const int SplitMulX = 1109124029;     // 0x421BE3BD
    private const int SplitAdd = 1369149221;      // 0x519B8F25

    /// <summary>
    /// 2^-32, the scale that maps the split rule's unsigned 32-bit value into [0, 1). The decompilation prints it as
    /// <c>2.3283064e-10</c>, the shortest decimal of float 0x2F800000 = 2^-32.
    /// </summary>
    internal const double SplitScale = 1.0 / 4294967296.0;

    /// <summary>
    /// The raw value of retail's split rule for the cell at global cell coordinates (<paramref name="globalCellX"/>,
    /// <paramref name="globalCellY"/>):
    /// <c>gy * (214614067 * gx + 1813693831) - 1109124029 * gx - 1369149221</c> in wrapping 32-bit arithmetic.
    /// </summary>
    public static uint SplitValue(int globalCellX, int globalCellY) =>
        unchecked((uint)(globalCellY * (SplitMulXY * globalCellX + SplitAddY) - SplitMulX * globalCellX - SplitAdd));

    /// <summary>
    /// Retail's pseudo-random triangle split: true when the cell at global cell coordinates
    /// (<paramref name="globalCellX"/>, <paramref name="globalCellY"/>) (landblock column * 8 + cell column, likewise for
    /// rows) is cut from its south-west to its north-east corner, false when it is cut from south-east to north-west.
    /// </summary>
    /// <remarks>
    /// Retail tests <c>(double)(uint)v * 2^-32 &gt;= 0.5</c>, i.e. the top bit of <see cref="SplitValue"/>. Had the
    /// scale been the shortened decimal or the x87 run at 24-bit precision, the threshold would move by at most ~64; no
    /// cell of the 2040 × 2040 world has a value within 440 of 2^31, so every reading gives the same world (pinned by a
    /// test over all cells).
    /// </remarks>
    // retail: CLandBlockStruct::ConstructPolygons (acclient.c:354000), the SWtoNEcut test
    public static bool IsSWtoNECut(int globalCellX, int globalCellY) =>
        (double)SplitValue(globalCellX, globalCellY) * SplitScale >= 0.5;

    // retail: CLandBlockStruct::ConstructVertices (acclient.c:354620)
    private void ConstructVertices()
    {
        // poly_size = (24 * 8) / side_polygon_count = 24 (flt_844C88, acclient.c:787077).
        float polySize = (float)(LandDefs.BlockLength / (double)SidePolygonCount);
        for (int ix = 0; ix < SideVertexCount; ix++)
        {
            for (int iy = 0; iy < SideVertexCount; iy++)
            {
                int i = ix * SideVertexCount + iy;
                _vertices[i] = new Vector3(
                    (float)(ix * (double)polySize),
                    (float)(iy * (double)polySize),
                    HeightTable[_height[i]]);
            }
        }
    }

    // retail: CLandBlockStruct::ConstructPolygons (acclient.c:354000) with AddPolygon (acclient.c:353295)
    private void ConstructPolygons()
    {
        int blockX = BlockX * SideCellCount;
        int blockY = BlockY * SideCellCount;
        Span<Vector3> tri = stackalloc Vector3[3];
        Span<ushort> ids = stackalloc ushort[3];
        for (int i = 0; i < SideCellCount; i++)
        {
            for (int j = 0; j < SideCellCount; j++)
            {
                int gx = i + blockX;
                int gy = j + blockY;
                int k = j + i * SideCellCount;
                int sw = i * SideVertexCount + j;
                int se = (i + 1) * SideVertexCount + j;
                int ne = se + 1;
                int nw = sw + 1;
                bool cut = IsSWtoNECut(gx, gy);
                _swToNeCut[k] = cut;
                Polygon p0, p1;
                if (cut)
                {
                    p0 = MakeTriangle(2 * k, sw, se, ne, tri, ids);
                    p1 = MakeTriangle(2 * k + 1, sw, ne, nw, tri, ids);
                }
                else
                {
                    p0 = MakeTriangle(2 * k, sw, se, nw, tri, ids);
                    p1 = MakeTriangle(2 * k + 1, ne, nw, se, tri, ids);
                }

                _polygons[2 * k] = p0;
                _polygons[2 * k + 1] = p1;
                uint cellId = LandDefs.LCoordToGid(gx, gy);

                // The cell's frame origin is its centre: ((2i + 1) * 12, (2j + 1) * 12, 0) (flt_844C8C = 24 * 0.5).
                var origin = new Vector3(
                    (float)((2 * i + 1) * (double)LandDefs.HalfCellLength),
                    (float)((2 * j + 1) * (double)LandDefs.HalfCellLength),
                    0f);
                _cells[k] = new LandCell(this, i, j, cellId, p0, p1, origin);
            }
        }
    }

    private Polygon MakeTriangle(int polyIndex, int v0, int v1, int v2, Span<Vector3> tri, Span<ushort> ids)
    {
        tri[0] = _vertices[v0];
        tri[1] = _vertices[v1];
        tri[2] = _vertices[v2];
        ids[0] = (ushort)v0;
        ids[1] = (ushort)v1;
        ids[2] = (ushort)v2;
        return new Polygon((short)polyIndex, tri, ids);
    }

    // retail: CLandBlockStruct::CalcWater (acclient.c:354565)
    private void CalcWater()
    {
        bool blockHasWater = false;
        bool blockAllWater = true;
        for (int x = 0; x < SideCellCount; x++)
        {
            for (int y = 0; y < SideCellCount; y++)
            {
                CalcCellWater(x, y, out bool hasWater, out bool allWater);
                WaterType w;
                if (hasWater)
                {
                    blockHasWater = true;
                    if (allWater)
                    {
                        w = WaterType.EntirelyWater;
                    }
                    else
                    {
                        blockAllWater = false;
                        w = WaterType.PartiallyWater;
                    }
                }
                else
                {
                    blockAllWater = false;
                    w = WaterType.NotWater;
                }

                _cells[x * SideCellCount + y].WaterType = w;
            }
        }

        WaterType = !blockHasWater ? WaterType.NotWater
            : blockAllWater ? WaterType.EntirelyWater
            : WaterType.PartiallyWater;
    }

    // retail: CLandBlockStruct::CalcCellWater (acclient.c:353607)
    private void CalcCellWater(int cellX, int cellY, out bool hasWater, out bool allWater)
    {
        hasWater = false;
        allWater = true;
        for (int vx = cellX; vx <= cellX + 1; vx++)
        {
            for (int vy = cellY; vy <= cellY + 1; vy++)
            {
                if (TerrainTypes.IsWater(_terrain[vx * SideVertexCount + vy]))
                {
                    hasWater = true;
                }
                else
                {
                    allWater = false;
                }
            }
        }
    }

    // retail: CLandBlock::get_land_limits (acclient.c:351418)
    private void GetLandLimits()
    {
        byte hi = _height[0];
        byte lo = _height[0];
        for (int i = 1; i < VertexCount; i++)
        {
            hi = Math.Max(hi, _height[i]);
            lo = Math.Min(lo, _height[i]);
        }

        MaxZval = (float)(HeightTable[hi] + 200.0);
        MinZval = (float)(HeightTable[lo] - 1.0);
    }
}
