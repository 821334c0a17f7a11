using System;
using System.IO;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.Data;
using AcDream.Core.Fixtures.Data;

namespace AcDream.Samples.FirstScene;

/// <summary>
/// The static scene as a client's data files would hand it over (<see cref="SampleData"/>): the 3 × 3 landblocks around
/// Holtburg (0xA8B3-0xAAB5) from the real terrain data when it is found, else synthetic gentle slopes with the same ids, and
/// on the centre block 0xA9B4 a small hut (a building whose model is a GfxObj box), two trees and a rock.
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

    /// <summary>The hut's model (a GfxObj box), a tree's Setup and its drawn part, and a rock (a low GfxObj box).</summary>
    public const uint HutModel = 0x01000100, TreeSetup = 0x02000200, TreePart = 0x01000201, Rock = 0x01000202;

    /// <summary>The real Holtburg blocks read from <paramref name="dir"/> (the ac-terrain folder), as a client's data files
    /// would hand them over.</summary>
    public static SampleData LoadHoltburg(string dir)
    {
        var data = new SampleData(TerrainDataFiles.ReadHeightTableCsv(Path.Combine(dir, "land_height_table.csv")));
        foreach (LandBlockEntry d in TerrainDataFiles.ReadLandblockSampleCsv(Path.Combine(dir, "landblock_heights_sample.csv")))
        {
            int bx = (int)(d.Id >> 24), by = (int)((d.Id >> 16) & 0xFF);
            if (Math.Abs(bx - BlockX) <= 1 && Math.Abs(by - BlockY) <= 1)
            {
                data.AddBlock(d.Id, d.Height, d.Terrain);
            }
        }

        return data;
    }

    /// <summary>Synthetic terrain with the same block ids: a height table of 0.5 m per index and a gentle slope rising 0.5 m
    /// per vertex (24 m) to the north-east, continuous across the block edges; terrain type 1 (solid ground) everywhere.</summary>
    public static SampleData Synthetic()
    {
        var table = new float[LandHeightTable.Count];
        for (int i = 0; i < table.Length; i++)
        {
            table[i] = 0.5f * i;
        }

        var data = new SampleData(new LandHeightTable(table));
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

                data.AddBlock(LandBlock.MakeId(bx, by) | 0xFFFFu, heights, codes);
            }
        }

        return data;
    }

    /// <summary>
    /// The centre block's contents, as its landblock info (0xXXYYFFFE) lists them: the hut (a building whose model is a
    /// GfxObj box, 10 × 6 m, walls from 3 m under to 3 m over the ground at its centre), two trees (a Setup with one
    /// cylinder, r 1.5 m) and a rock (a GfxObj box 1.6 m wide, 0.4 m high) away from the player's path.
    /// </summary>
    public static void AddContents(SampleData data)
    {
        // The ground under each object, from the terrain the client's files describe.
        var probe = new TerrainWorld(data.HeightTable);
        LandBlockEntry centre = LandBlockEntry.UnPack(data.Entries[CentreBlock]);
        probe.AddLandBlock(centre.ToLandBlock(data.HeightTable));
        Vector2 c = (HutMin + HutMax) * 0.5f;
        Frame At(float x, float y) => new(OnGround(probe, x, y, 0f).Frame.Origin, Quaternion.Identity);

        data.Entries[HutModel] = WorldDataBytes.BoxGfxObj(HutModel,
            new Vector3(HutMin.X - c.X, HutMin.Y - c.Y, -3f), new Vector3(HutMax.X - c.X, HutMax.Y - c.Y, 3f));
        data.Entries[TreePart] = WorldDataBytes.DrawingGfxObj(TreePart, new Vector3(-2f, -2f, 0f), new Vector3(2f, 2f, 12f));
        data.Entries[TreeSetup] = WorldDataBytes.CylinderSetup(TreeSetup, TreePart, 1.5f, 12f, -1f);
        data.Entries[Rock] = WorldDataBytes.BoxGfxObj(Rock, new Vector3(-0.8f, -0.8f, -0.2f), new Vector3(0.8f, 0.8f, 0.4f));
        data.Entries[(CentreBlock & 0xFFFF0000u) | 0xFFFEu] = WorldDataBytes.LandBlockInfo((CentreBlock & 0xFFFF0000u) | 0xFFFEu,
            [(TreeSetup, At(30f, 170f)), (TreeSetup, At(170f, 170f)), (Rock, At(20f, 20f))],
            [(HutModel, At(c.X, c.Y))]);
        data.Entries[CentreBlock] = WorldDataBytes.LandBlock(CentreBlock, true, centre.Terrain, centre.Height);
    }

    /// <summary>The centre landblock's id.</summary>
    public const uint CentreBlock = ((uint)BlockX << 24) | ((uint)BlockY << 16) | 0xFFFFu;

    /// <summary>Horizontal distance from (x, y) to the hut's footprint (0 inside).</summary>
    public static float DistanceToHut(Vector3 p)
    {
        float dx = MathF.Max(MathF.Max(HutMin.X - p.X, 0f), p.X - HutMax.X);
        float dy = MathF.Max(MathF.Max(HutMin.Y - p.Y, 0f), p.Y - HutMax.Y);
        return MathF.Sqrt(dx * dx + dy * dy);
    }
}
