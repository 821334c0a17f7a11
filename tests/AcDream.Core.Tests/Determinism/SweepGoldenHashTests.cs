using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Determinism;

/// <summary>
/// Golden hash of a seeded sweep scene: eight walkers on a landblock with a walkable slope, a cliff and a pond, turning at
/// random and jumping now and then, for 2,000 ticks. A determinism pin like <see cref="FrameGoldenHashTests"/>: recorded once,
/// it must not change under another JIT mode or run; its physical correctness is covered by the Retail and Behavior tests.
/// </summary>
[Trait("Category", "Determinism")]
public class SweepGoldenHashTests
{
    /// <summary>Recorded pin for <see cref="RunSweepScene"/>(2000). Re-recorded on branch objcoll: the walkers meet (first
    /// at tick 119) and, with object collisions, no longer pass through each other (was 1550880469434589296).</summary>
    private const ulong SweepScene2000 = 467847325377838751UL;

    internal static ulong RunSweepScene(int ticks, bool descendingCreation = false)
    {
        var rng = new Random(20261122);
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY,
            (vx, vy) => vx <= 3 ? 20 + vy : vx <= 5 ? 60 : 60 - 27 * (vx - 5) + 90,
            (vx, vy) => vx == 1 && vy >= 6 ? 17 : 1);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        var walkers = new PhysicsObj[8];
        for (int k = 0; k < walkers.Length; k++)
        {
            // Walkers are created in index order or in reverse; the script below addresses them by index (= id - 1).
            int i = descendingCreation ? walkers.Length - 1 - k : k;
            float x = 30f + 18f * i, y = 40f + 10f * i;
            uint cell = LandDefs.LCoordToGid(SweepScene.BlockX * 8 + (int)(x / 24f), SweepScene.BlockY * 8 + (int)(y / 24f));
            Position p = SyntheticTerrain.OnGround(terrain, cell, x, y, 40f * i);
            walkers[i] = SweepScene.Walker(world, p, id: (uint)(i + 1));
            SweepScene.SetWalk(walkers[i], new Vector3(0f, 2f + 0.3f * i, 0f));
        }

        var h = new StateHasher();
        for (int t = 0; t < ticks; t++)
        {
            if ((t & 15) == 0)
            {
                foreach (PhysicsObj w in walkers)
                {
                    ((SimplePartArray)w.PartArray!).SequenceOmega = new Vector3(0f, 0f, (float)(rng.NextDouble() - 0.5));
                    if (rng.Next(8) == 0 && (w.TransientState & TransientState.Contact) != 0)
                    {
                        w.SetVelocity(new Vector3(0f, 0f, 4f));
                    }
                }
            }

            world.Tick(world.CurrentTime + SweepScene.Dt);
            foreach (PhysicsObj w in walkers)
            {
                h.Add(w.Position);
                h.Add((uint)w.TransientState);
                h.Add(w.Velocity);
            }
        }

        return h.Value;
    }

    [Fact]
    public void SweepScene_SameInputs_SameHashEveryRun()
    {
        Assert.Equal(RunSweepScene(2000), RunSweepScene(2000));
    }

    [Fact]
    public void SweepScene_WalkersCreatedInReverseOrder_SameHash()
    {
        Assert.Equal(RunSweepScene(2000), RunSweepScene(2000, descendingCreation: true));
    }

    [Fact]
    public void SweepScene_MatchesGoldenHash()
    {
        Assert.Equal(SweepScene2000, RunSweepScene(2000));
    }
}
