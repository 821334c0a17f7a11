using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using AcDream.Core.Physics.Data;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>Terrain builders for the report's sweep scenes: hand-made landblocks with a one-metre height table, and the real
/// Holtburg 3 × 3 landblocks from the fixtures.</summary>
internal static class TerrainKit
{
    /// <summary>Landblock of the hand-made scenes (x 128, y 128).</summary>
    public const int Block = 0x80;

    /// <summary>A terrain world whose height index i is i metres.</summary>
    public static TerrainWorld Metres() => SyntheticTerrain.Metres();

    /// <summary>Adds the hand-made block 0x8080 whose vertex (vx, vy) has height index <paramref name="height"/>(vx, vy).</summary>
    public static void AddBlock(TerrainWorld world, Func<int, int, int> height) => SyntheticTerrain.AddBlock(world, Block, Block, height);

    /// <summary>Outdoor cell id of cell (cx, cy) of the hand-made block.</summary>
    public static uint CellId(int cx, int cy) => SyntheticTerrain.CellId(Block, Block, cx, cy);

    /// <summary>The real Holtburg landblocks 0xA8B3-0xAAB5 read from <paramref name="dir"/> (parsed once; build worlds with
    /// <see cref="HoltburgWorld"/>).</summary>
    public static (LandHeightTable Table, List<LandBlockEntry> Blocks) ReadHoltburg(string dir) => Holtburg.Read(dir);

    /// <summary>A fresh terrain world of the Holtburg blocks (see <see cref="Holtburg.World"/>).</summary>
    public static TerrainWorld HoltburgWorld((LandHeightTable Table, List<LandBlockEntry> Blocks) data) => Holtburg.World(data);

    /// <summary>A physics world with <paramref name="profile"/> sweeping through <paramref name="terrain"/>.</summary>
    public static PhysicsWorld World(TerrainWorld terrain, PhysicsProfile profile) =>
        new(0.0, profile) { Sweep = new RetailSweep(terrain) };

    /// <summary>A creature: one sphere (0.5 m by default) resting on its origin, step heights 0.6 m, a movement manager (stays active),
    /// <paramref name="state"/> (retail's default when null), placed at <paramref name="p"/>.</summary>
    public static PhysicsObj Walker(PhysicsWorld world, in Position p, uint id, PhysicsState? state = null, float radius = 0.5f)
    {
        SimplePartArray parts = Walkers.OneSphere(radius);
        parts.Radius = radius;
        parts.Height = 1.8f;
        return Walkers.Create(world, id, p, parts, state);
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
