using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Math;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>Terrain builders for the report's sweep scenes: hand-made landblocks with a one-metre height table, and the real
/// Holtburg 3 × 3 landblocks from the fixtures.</summary>
internal static class TerrainKit
{
    /// <summary>Landblock of the hand-made scenes (x 128, y 128).</summary>
    public const int Block = 0x80;

    /// <summary>A terrain world whose height index i is i metres.</summary>
    public static TerrainWorld Metres()
    {
        var h = new float[LandHeightTable.Count];
        for (int i = 0; i < h.Length; i++)
        {
            h[i] = i;
        }

        return new TerrainWorld(new LandHeightTable(h));
    }

    /// <summary>Adds the hand-made block 0x8080 whose vertex (vx, vy) has height index <paramref name="height"/>(vx, vy).</summary>
    public static void AddBlock(TerrainWorld world, Func<int, int, int> height)
    {
        var heights = new byte[81];
        var terrain = new ushort[81];
        for (int vx = 0; vx < 9; vx++)
        {
            for (int vy = 0; vy < 9; vy++)
            {
                heights[vx * 9 + vy] = checked((byte)height(vx, vy));
                terrain[vx * 9 + vy] = TerrainTypes.MakeWord(0, 1);
            }
        }

        world.AddLandBlock(LandBlock.MakeId(Block, Block), heights, terrain);
    }

    /// <summary>Outdoor cell id of cell (cx, cy) of the hand-made block.</summary>
    public static uint CellId(int cx, int cy) => ((uint)Block << 24) | ((uint)Block << 16) | (uint)(cx * 8 + cy + 1);

    /// <summary>The real Holtburg landblocks 0xA8B3-0xAAB5 read from <paramref name="dir"/> (parsed once; build worlds with
    /// <see cref="HoltburgWorld"/>).</summary>
    public static (LandHeightTable Table, List<LandBlockData> Blocks) ReadHoltburg(string dir)
    {
        var blocks = new List<LandBlockData>();
        foreach (LandBlockData d in TerrainDataFiles.ReadLandblockSampleCsv(Path.Combine(dir, "landblock_heights_sample.csv")))
        {
            if (d.BlockId >> 24 is >= 0xA8 and <= 0xAA && ((d.BlockId >> 16) & 0xFF) is >= 0xB3 and <= 0xB5)
            {
                blocks.Add(d);
            }
        }

        return (TerrainDataFiles.ReadHeightTableCsv(Path.Combine(dir, "land_height_table.csv")), blocks);
    }

    /// <summary>
    /// A fresh terrain world of the Holtburg blocks. Each scene run needs its own: land cells hold the shadows of the objects
    /// in them, so a terrain world shared by two physics worlds would let one world's objects collide with the other's.
    /// </summary>
    public static TerrainWorld HoltburgWorld((LandHeightTable Table, List<LandBlockData> Blocks) data)
    {
        var world = new TerrainWorld(data.Table);
        foreach (LandBlockData d in data.Blocks)
        {
            world.AddLandBlock(d.BlockId, d.Height, d.Terrain);
        }

        return world;
    }

    /// <summary>A physics world with <paramref name="profile"/> sweeping through <paramref name="terrain"/>.</summary>
    public static PhysicsWorld World(TerrainWorld terrain, PhysicsProfile profile) =>
        new(0.0, profile) { Sweep = new RetailSweep(terrain) };

    /// <summary>A creature: one sphere (0.5 m by default) resting on its origin, step heights 0.6 m, a movement manager (stays active),
    /// <paramref name="state"/> (retail's default when null), placed at <paramref name="p"/>.</summary>
    public static PhysicsObj Walker(PhysicsWorld world, in Position p, uint id, PhysicsState? state = null, float radius = 0.5f)
    {
        PhysicsObj obj = world.CreateObject(id);
        var parts = new SimplePartArray(1, 0) { StepUpHeight = 0.6f, StepDownHeight = 0.6f, Radius = radius, Height = 1.8f };
        parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, radius), radius) });
        obj.PartArray = parts;
        obj.MovementManager = new BasicMovementManager();
        if (state is not null)
        {
            obj.SetState(state.Value);
        }

        if (!obj.EnterWorld(p))
        {
            throw new InvalidOperationException("walker could not enter the world");
        }

        return obj;
    }

    /// <summary>Sets a walker's root-motion velocity (local axes, +Y forward) and turn rate (rad/s about +Z).</summary>
    public static void Walk(PhysicsObj obj, Vector3 local, float omegaZ = 0f)
    {
        var parts = (SimplePartArray)obj.PartArray!;
        parts.SequenceVelocity = local;
        parts.SequenceOmega = new Vector3(0f, 0f, omegaZ);
    }

    /// <summary>Terrain height under <paramref name="p"/>, or NaN.</summary>
    public static float Ground(TerrainWorld terrain, in Position p) => terrain.TryGetTerrainHeight(p, out float z) ? z : float.NaN;
}
