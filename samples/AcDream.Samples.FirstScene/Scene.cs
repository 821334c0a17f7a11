using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.Data;

namespace AcDream.Samples.FirstScene;

/// <summary>
/// The static scene: the 3 × 3 landblocks around Holtburg (0xA8B3-0xAAB5) from the real terrain data when it is found, else
/// synthetic gentle slopes with the same ids, and a small hut (a BSP box) on the centre block 0xA9B4.
/// </summary>
internal static class Scene
{
    /// <summary>The centre landblock, x and y.</summary>
    public const int BlockX = 0xA9;

    /// <summary>The centre landblock, y.</summary>
    public const int BlockY = 0xB4;

    /// <summary>The hut's corners, centre-block-local metres (x, y; its walls run from 3 m under to 3 m over the ground).</summary>
    public static readonly Vector2 HutMin = new(104f, 66f);

    /// <summary>The hut's far corner.</summary>
    public static readonly Vector2 HutMax = new(114f, 72f);

    /// <summary>The outdoor cell id under the centre-block-local point (x, y) (0 &lt;= x, y &lt; 192).</summary>
    public static uint CellAt(float x, float y) => LandDefs.LCoordToGid(BlockX * 8 + (int)(x / 24f), BlockY * 8 + (int)(y / 24f));

    /// <summary>A position on the centre block at (x, y) on the ground, facing <paramref name="heading"/> degrees (clockwise
    /// from north).</summary>
    public static Position OnGround(TerrainWorld terrain, float x, float y, float heading)
    {
        var p = new Position(CellAt(x, y), Frame.FromHeading(new Vector3(x, y, 0f), heading));
        if (!terrain.TryGetTerrainHeight(p, out float z))
        {
            throw new InvalidOperationException($"No terrain under ({x}, {y}).");
        }

        p.Frame.Origin = new Vector3(x, y, z);
        return p;
    }

    /// <summary>The real Holtburg blocks read from <paramref name="dir"/> (the ac-terrain folder).</summary>
    public static TerrainWorld LoadHoltburg(string dir)
    {
        var terrain = new TerrainWorld(TerrainDataFiles.ReadHeightTableCsv(Path.Combine(dir, "land_height_table.csv")));
        foreach (LandBlockEntry d in TerrainDataFiles.ReadLandblockSampleCsv(Path.Combine(dir, "landblock_heights_sample.csv")))
        {
            int bx = (int)(d.Id >> 24), by = (int)((d.Id >> 16) & 0xFF);
            if (Math.Abs(bx - BlockX) <= 1 && Math.Abs(by - BlockY) <= 1)
            {
                terrain.AddLandBlock(d.Id, d.Height, d.Terrain);
            }
        }

        return terrain;
    }

    /// <summary>Synthetic terrain with the same block ids: a height table of 0.5 m per index and a gentle slope rising 0.5 m
    /// per vertex (24 m) to the north-east, continuous across the block edges; terrain type 1 (solid ground) everywhere.</summary>
    public static TerrainWorld Synthetic()
    {
        var table = new float[LandHeightTable.Count];
        for (int i = 0; i < table.Length; i++)
        {
            table[i] = 0.5f * i;
        }

        var terrain = new TerrainWorld(new LandHeightTable(table));
        for (int bx = BlockX - 1; bx <= BlockX + 1; bx++)
        {
            for (int by = BlockY - 1; by <= BlockY + 1; by++)
            {
                var heights = new byte[81];
                var codes = new ushort[81];
                for (int vx = 0; vx < 9; vx++)
                {
                    for (int vy = 0; vy < 9; vy++)
                    {
                        int gx = (bx - BlockX + 1) * 8 + vx, gy = (by - BlockY + 1) * 8 + vy;
                        heights[vx * 9 + vy] = (byte)(40 + gx + gy);
                        codes[vx * 9 + vy] = TerrainTypes.MakeWord(0, 1);
                    }
                }

                terrain.AddLandBlock(LandBlock.MakeId(bx, by), heights, codes);
            }
        }

        return terrain;
    }

    /// <summary>
    /// Builds the hut (a closed box of one-sided quads facing out, compiled to a BSP tree) and attaches it, as a building, to
    /// every land cell its footprint touches: outdoor sweeps test it from there.
    /// </summary>
    public static BuildingObj AddHut(TerrainWorld terrain)
    {
        Vector2 c = (HutMin + HutMax) * 0.5f;
        Position at = OnGround(terrain, c.X, c.Y, 0f);
        float z = at.Frame.Origin.Z;
        var polys = new List<Polygon>();
        AddBox(polys, new Vector3(HutMin.X - c.X, HutMin.Y - c.Y, -3f), new Vector3(HutMax.X - c.X, HutMax.Y - c.Y, 3f));
        BspTree bsp = BspBuilder.Build(polys.ToArray());
        var part = new PhysicsPart(new GfxObjPhysics(bsp), new Position(at.ObjCellId, new Frame(new Vector3(c.X, c.Y, z), Quaternion.Identity)), Vector3.One);
        var hut = new BuildingObj(part, Array.Empty<BldPortal>());
        for (int cx = (int)((HutMin.X - 1f) / 24f); cx <= (int)((HutMax.X + 1f) / 24f); cx++)
        {
            for (int cy = (int)((HutMin.Y - 1f) / 24f); cy <= (int)((HutMax.Y + 1f) / 24f); cy++)
            {
                LandCell cell = terrain.GetLandCell(LandDefs.LCoordToGid(BlockX * 8 + cx, BlockY * 8 + cy))
                    ?? throw new InvalidOperationException("The hut's cells are not loaded.");
                cell.Building = hut;
            }
        }

        return hut;
    }

    /// <summary>Horizontal distance from (x, y) to the hut's footprint (0 inside).</summary>
    public static float DistanceToHut(Vector3 p)
    {
        float dx = MathF.Max(MathF.Max(HutMin.X - p.X, 0f), p.X - HutMax.X);
        float dy = MathF.Max(MathF.Max(HutMin.Y - p.Y, 0f), p.Y - HutMax.Y);
        return MathF.Sqrt(dx * dx + dy * dy);
    }

    // The six faces of the box min..max, each a quad counter-clockwise seen from outside.
    private static void AddBox(List<Polygon> polys, Vector3 min, Vector3 max)
    {
        float x0 = min.X, y0 = min.Y, z0 = min.Z, x1 = max.X, y1 = max.Y, z1 = max.Z;
        Add(polys, new(x1, y0, z0), new(x1, y1, z0), new(x1, y1, z1), new(x1, y0, z1)); // +X
        Add(polys, new(x0, y0, z0), new(x0, y0, z1), new(x0, y1, z1), new(x0, y1, z0)); // -X
        Add(polys, new(x0, y1, z0), new(x0, y1, z1), new(x1, y1, z1), new(x1, y1, z0)); // +Y
        Add(polys, new(x0, y0, z0), new(x1, y0, z0), new(x1, y0, z1), new(x0, y0, z1)); // -Y
        Add(polys, new(x0, y0, z1), new(x1, y0, z1), new(x1, y1, z1), new(x0, y1, z1)); // +Z
        Add(polys, new(x0, y0, z0), new(x0, y1, z0), new(x1, y1, z0), new(x1, y0, z0)); // -Z
    }

    private static void Add(List<Polygon> polys, Vector3 a, Vector3 b, Vector3 c, Vector3 d) =>
        polys.Add(new Polygon((short)polys.Count, new[] { a, b, c, d }, new ushort[] { 0, 1, 2, 3 }));
}
