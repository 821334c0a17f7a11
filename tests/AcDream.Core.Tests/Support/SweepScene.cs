using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;

namespace AcDream.Core.Tests.Support;

/// <summary>Shared builders for sweep scenes: hand-made terrain, a world with the retail sweep, and walkers.</summary>
internal static class SweepScene
{
    /// <summary>Landblock used by most scenes: 0x8080 (x 128, y 128), well inside the world.</summary>
    public const int BlockX = 0x80;

    /// <summary>See <see cref="BlockX"/>.</summary>
    public const int BlockY = 0x80;

    /// <summary>Tick length used by the scenes, seconds (above MinQuantum, below MaxQuantum: one step per tick).</summary>
    public const double Dt = 0.05;

    /// <summary>A height table with exactly one metre per index (see <see cref="SyntheticTerrain.MetreTable"/>).</summary>
    public static LandHeightTable MetreTable() => SyntheticTerrain.MetreTable();

    /// <summary>Adds landblock (bx, by) from a height function and a terrain-type function (see <see cref="SyntheticTerrain.AddBlock"/>).</summary>
    public static LandBlock AddBlock(TerrainWorld world, int bx, int by, Func<int, int, int> height, Func<int, int, int>? type = null) =>
        SyntheticTerrain.AddBlock(world, bx, by, height, type);

    /// <summary>A terrain world with the one-metre table.</summary>
    public static TerrainWorld Terrain() => new(MetreTable());

    /// <summary>A physics world sweeping through <paramref name="terrain"/> with the retail sweep.</summary>
    public static PhysicsWorld Physics(TerrainWorld terrain, out RetailSweep sweep)
    {
        var world = new PhysicsWorld(0.0);
        sweep = new RetailSweep(terrain);
        world.Sweep = sweep;
        return world;
    }

    /// <summary>Outdoor cell id of cell (cx, cy) of landblock (bx, by).</summary>
    public static uint CellId(int bx, int by, int cx, int cy) => SyntheticTerrain.CellId(bx, by, cx, cy);

    /// <summary>
    /// A creature with one sphere of radius <paramref name="radius"/> resting on its origin (centre (0, 0, r)), a movement
    /// manager (so that it stays active), step heights, and <paramref name="state"/> (retail's default when null).
    /// It enters the world at <paramref name="p"/> (placement with slide, then a step down onto the ground).
    /// </summary>
    public static PhysicsObj Walker(PhysicsWorld world, in Position p, float radius = 0.5f, float stepUp = 0.6f, float stepDown = 0.6f,
        PhysicsState? state = null, uint id = 1) =>
        Walkers.Create(world, id, p, Walkers.OneSphere(radius, stepUp, stepDown), state);

    /// <summary>Sets the walker's animation (root motion) velocity, m/s in its local axes (+Y forward).</summary>
    public static void SetWalk(PhysicsObj obj, Vector3 localVelocity) => ((SimplePartArray)obj.PartArray!).SequenceVelocity = localVelocity;

    /// <summary>Ticks <paramref name="world"/> <paramref name="n"/> times by <see cref="Dt"/>, calling <paramref name="each"/> after every tick.</summary>
    public static void Run(PhysicsWorld world, int n, Action<int>? each = null)
    {
        for (int i = 0; i < n; i++)
        {
            world.Tick(world.CurrentTime + Dt);
            each?.Invoke(i);
        }
    }

    /// <summary>The terrain height under an outdoor position, metres.</summary>
    public static float Ground(TerrainWorld terrain, in Position p) => SyntheticTerrain.Ground(terrain, p);
}
