using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Math;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Tests.Behavior;

/// <summary>Shared builders for sweep scenes: hand-made terrain, a world with the retail sweep, and walkers.</summary>
internal static class SweepScene
{
    /// <summary>Landblock used by most scenes: 0x8080 (x 128, y 128), well inside the world.</summary>
    public const int BlockX = 0x80;

    /// <summary>See <see cref="BlockX"/>.</summary>
    public const int BlockY = 0x80;

    /// <summary>Tick length used by the scenes, seconds (above MinQuantum, below MaxQuantum: one step per tick).</summary>
    public const double Dt = 0.05;

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

    /// <summary>Adds landblock (bx, by) whose vertex (vx, vy) has height index <paramref name="height"/>(vx, vy) and terrain type
    /// <paramref name="type"/>(vx, vy) (0 = grass-like solid; 16..20 water).</summary>
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
    public static uint CellId(int bx, int by, int cx, int cy) => ((uint)bx << 24) | ((uint)by << 16) | (uint)(cx * 8 + cy + 1);

    /// <summary>
    /// A creature with one sphere of radius <paramref name="radius"/> resting on its origin (centre (0, 0, r)), a movement
    /// manager (so that it stays active), step heights, and <paramref name="state"/> (retail's default when null).
    /// It enters the world at <paramref name="p"/> (placement with slide, then a step down onto the ground).
    /// </summary>
    public static PhysicsObj Walker(PhysicsWorld world, in Position p, float radius = 0.5f, float stepUp = 0.6f, float stepDown = 0.6f,
        PhysicsState? state = null, uint id = 1)
    {
        PhysicsObj obj = world.CreateObject(id);
        var parts = new SimplePartArray(1, 0)
        {
            StepUpHeight = stepUp,
            StepDownHeight = stepDown,
        };
        parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, radius), radius) });
        obj.PartArray = parts;
        obj.MovementManager = new BasicMovementManager();
        if (state is not null)
        {
            obj.SetState(state.Value);
        }

        if (!obj.EnterWorld(p))
        {
            throw new InvalidOperationException("The walker could not enter the world.");
        }

        return obj;
    }

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
    public static float Ground(TerrainWorld terrain, in Position p)
    {
        if (!terrain.TryGetTerrainHeight(p, out float z))
        {
            throw new InvalidOperationException("No terrain under the position.");
        }

        return z;
    }
}
