using System;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;

namespace AcDream.Core.Tests.Support;

/// <summary>
/// A square of flat landblocks (x, y in [<see cref="Lo"/>, <see cref="Hi"/>], ground at <see cref="BspScene.Ground"/>) as
/// retail entries for the landscape: every block has an info entry with one pine (<see cref="WorldSceneEntries.Pine"/>) at
/// block-local (50, 60), so a block at full detail holds exactly one static object.
/// </summary>
internal static class LandscapeEntries
{
    public const int Lo = 0x7A, Hi = 0x86;

    /// <summary>The pine's block-local spot.</summary>
    public static readonly Vector3 PineAt = new(50f, 60f, BspScene.Ground);

    /// <summary>The landblock id of block (x, y).</summary>
    public static uint BlockId(int x, int y) => ((uint)x << 24) | ((uint)y << 16) | 0xFFFFu;

    /// <summary>The outdoor cell of block (x, y) holding block-local (lx, ly).</summary>
    public static uint Cell(int x, int y, float lx, float ly) =>
        ((uint)x << 24) | ((uint)y << 16) | (uint)((int)(lx / 24f) * 8 + (int)(ly / 24f) + 1);

    /// <summary>A position in block (x, y) at block-local (lx, ly) on the ground.</summary>
    public static Position At(int x, int y, float lx, float ly) =>
        new(Cell(x, y, lx, ly), new Frame(new Vector3(lx, ly, BspScene.Ground), Quaternion.Identity));

    /// <summary>The source: every block of the square, its info, and the models.</summary>
    public static DictionarySource Source()
    {
        var s = new DictionarySource();
        var height = new byte[81];
        Array.Fill(height, (byte)BspScene.Ground);
        for (int x = Lo; x <= Hi; x++)
        {
            for (int y = Lo; y <= Hi; y++)
            {
                uint id = BlockId(x, y);
                s.Entries[id] = RetailEntries.LandBlock(id, true, new ushort[81], height);
                uint info = (id & 0xFFFF0000u) | 0xFFFEu;
                s.Entries[info] = RetailEntries.LandBlockInfo(info, 0,
                    [(WorldSceneEntries.Pine, new Frame(PineAt, Quaternion.Identity))], []);
            }
        }

        WorldSceneEntries.AddModels(s);
        return s;
    }

    /// <summary>A world sweeping over world cells, its loader on <paramref name="s"/>, and a landscape of radius
    /// <paramref name="radius"/> over it.</summary>
    public static Landscape Landscape(AcDream.Core.Physics.Data.IRetailDataSource s, out PhysicsWorld world, out WorldCells cells, int radius = 3)
    {
        world = WorldSceneEntries.World(out cells);
        var landscape = new Landscape(new WorldLoader(world, s));
        Xunit.Assert.True(landscape.SetMidRadius(radius));
        return landscape;
    }
}
