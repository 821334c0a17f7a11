using System.Collections.Generic;
using System.IO;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.Data;

namespace AcDream.Core.Tests.Support.Shared;

/// <summary>The real Holtburg 3 × 3 landblocks 0xA8B3-0xAAB5 from the terrain fixtures (compiled into the tests and the
/// benchmarks; no xunit here).</summary>
internal static class Holtburg
{
    /// <summary>The Holtburg landblocks read from <paramref name="dir"/> (parsed once; build worlds with <see cref="World"/>).</summary>
    public static (LandHeightTable Table, List<LandBlockEntry> Blocks) Read(string dir)
    {
        var blocks = new List<LandBlockEntry>();
        foreach (LandBlockEntry d in TerrainDataFiles.ReadLandblockSampleCsv(Path.Combine(dir, "landblock_heights_sample.csv")))
        {
            if (d.Id >> 24 is >= 0xA8 and <= 0xAA && ((d.Id >> 16) & 0xFF) is >= 0xB3 and <= 0xB5)
            {
                blocks.Add(d);
            }
        }

        return (TerrainDataFiles.ReadHeightTableCsv(Path.Combine(dir, "land_height_table.csv")), blocks);
    }

    /// <summary>
    /// A fresh terrain world of the Holtburg blocks, in file order. Each scene run needs its own: land cells hold the shadows of
    /// the objects in them, so a terrain world shared by two physics worlds would let one world's objects collide with the other's.
    /// </summary>
    public static TerrainWorld World((LandHeightTable Table, List<LandBlockEntry> Blocks) data)
    {
        var world = new TerrainWorld(data.Table);
        foreach (LandBlockEntry d in data.Blocks)
        {
            world.AddLandBlock(d.Id, d.Height, d.Terrain);
        }

        return world;
    }

    /// <summary>The outdoor cell under the point (x, y) of the centre block 0xA9B4 (block-local metres).</summary>
    public static uint CentreCell(float x, float y) => LandDefs.LCoordToGid(0xA9 * 8 + (int)(x / 24f), 0xB4 * 8 + (int)(y / 24f));
}
