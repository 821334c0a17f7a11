using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Scene;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Scene;

/// <summary>
/// The gate queue never misses a crossing: against a brute-force double-precision measurement of every queued object, over
/// random walks that wander, stand still, stride along and teleport across landblocks, with objects added and forgotten all the
/// while. And its SIMD band scan flags what double precision flags.
/// </summary>
public class GateQueueTests
{
    private const double Gate = 96.0;

    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    [InlineData(3)]
    [InlineData(4)]
    [InlineData(5)]
    public void EveryCrossing_IsAmongTheHits_OverRandomWalksAndChurn(int seed)
    {
        var rng = new Random(seed);
        var world = new PhysicsWorld(0.0);
        var queue = new GateQueue();
        var objects = new List<PhysicsObj>();
        // 1,500 objects over about 500 m square (parts of up to 9 landblocks), most 0-5 m up, one in five up to 150 m (so that
        // height alone can put an object beyond 96 m: the grid's cells are skipped by their 3D extent).
        for (int k = 0; k < 1500; k++)
        {
            Position p = SceneTestContext.At(-150f + (float)rng.NextDouble() * 500f, -150f + (float)rng.NextDouble() * 500f,
                (float)rng.NextDouble() * (k % 5 == 0 ? 150f : 5f));
            objects.Add(SceneTestContext.Add(world, 10u + (uint)k, p));
        }

        Position player = SceneTestContext.At(100f, 100f, 1f);
        var queued = new HashSet<PhysicsObj>();
        var hits = new GateHit[4];
        long hitCount = 0, steps = 0;
        for (int step = 0; step < 4000; step++)
        {
            // Move: mostly a step of up to 1.2 m (a fast runner's tick or more), sometimes none, now and then a jump of tens to hundreds
            // of metres.
            int kind = rng.Next(100);
            float reach = kind < 10 ? 0f : kind < 97 ? (float)rng.NextDouble() * 1.2f : 10f + (float)rng.NextDouble() * 300f;
            float angle = (float)(rng.NextDouble() * 2.0 * Math.PI);
            var next = new Position(player.ObjCellId,
                player.Frame.Origin + new Vector3(reach * MathF.Sin(angle), reach * MathF.Cos(angle), 0f));
            if (next.TryAdjustToOutside())
            {
                player = next;
            }

            int n = queue.Advance(player, ref hits, out _);
            hitCount += n;
            steps++;
            for (int i = 0; i < n; i++)
            {
                GateHit h = hits[i];
                if (!queue.IsLive(h))
                {
                    continue;
                }

                PhysicsObj hit = queue.Object(h.Slot);
                bool far = IsFar(hit, player);
                if (far != queue.IsFar(h.Slot))
                {
                    if (rng.Next(8) == 0)
                    {
                        // A crossing that wakes its object (a mover): it leaves the queue in the middle of the resolution.
                        GateQueue.Forget(hit);
                        queued.Remove(hit);
                        continue;
                    }

                    queue.RecordFlip(h.Slot, step, far);
                }

                if (rng.Next(50) == 0 && queued.Count > 0)
                {
                    // Something else wakes meanwhile (a listener kicks an object), wherever it is.
                    PhysicsObj other = objects[rng.Next(objects.Count)];
                    if (queued.Remove(other))
                    {
                        GateQueue.Forget(other);
                    }
                }
            }

            queue.Finish(hits, n);

            // Churn: forget a few queued objects and queue a few others, measured where the player now is.
            for (int c = rng.Next(0, 8); c > 0; c--)
            {
                PhysicsObj o = objects[rng.Next(objects.Count)];
                if (queued.Remove(o))
                {
                    GateQueue.Forget(o);
                }
                else
                {
                    queue.Add(o, IsFar(o, player), idle: true, onWalkable: true);
                    queued.Add(o);
                }
            }

            foreach (PhysicsObj o in queued)
            {
                Assert.True(queue.IsFar(o._scene.GateSlot) == IsFar(o, player),
                    $"seed {seed} step {step}: object {o.Id} at {Distance(o, player):F6} m recorded on the wrong side");
            }
        }

        // The hits are the crossings and a few near the boundary, not the queue.
        Assert.True(hitCount < steps * 10, $"{hitCount} hits in {steps} steps");
        Assert.True(queue.EntryCount < 3 * objects.Count, $"entries {queue.EntryCount}");
    }

    [Fact]
    public void BandScan_FlagsWhatDoublePrecisionFlags()
    {
        // Entries within 6 m of the 96 m circle about a centre in another landblock's frame (large global coordinates), the
        // player up to 5 m from the centre: every entry double precision puts below the tolerance (less a hair for float
        // rounding) is flagged, none above it (plus the hair) is; membership likewise.
        var rng = new Random(11);
        const double cx = 33_000.25, cy = 41_000.75, cz = 40.0;
        var band = new GateBand(6.0);
        band.Reset(cx, cy, cz);
        const int count = 4000;
        var pos = new (double X, double Y, double Z, bool Far)[count];
        for (int i = 0; i < count; i++)
        {
            double a = rng.NextDouble() * 2.0 * Math.PI, r = Gate + (rng.NextDouble() * 2.0 - 1.0) * 6.0;
            pos[i] = (cx + r * Math.Sin(a), cy + r * Math.Cos(a), cz + rng.NextDouble() * 3.0, rng.Next(2) == 0);
            band.Append(i, 0, 0, pos[i].X, pos[i].Y, pos[i].Z, pos[i].Far);
        }

        var hits = new GateHit[4];
        const float tolerance = GateQueue.ScanTolerance;
        const double hair = 0.01; // m² of d²: far more than float rounding of offsets under 110 m (a few 1e-3)
        for (int t = 0; t < 50; t++)
        {
            double px = cx + (rng.NextDouble() * 2.0 - 1.0) * 3.5, py = cy + (rng.NextDouble() * 2.0 - 1.0) * 3.5;
            double pz = cz + rng.NextDouble();
            double lo = 94.0, hi = 98.0;
            int n = band.Scan(px, py, pz, (float)(Gate * Gate), tolerance, 0, ref hits, 0, true, (float)(lo * lo), (float)(hi * hi));
            var flagged = new HashSet<int>();
            for (int i = 0; i < n; i++)
            {
                flagged.Add(hits[i].Slot);
            }

            var ring = new GateBand(2.0);
            ring.Reset(px, py, pz);
            band.CopyMembersTo(ring);
            for (int i = 0; i < count; i++)
            {
                double dx = pos[i].X - px, dy = pos[i].Y - py, dz = pos[i].Z - pz;
                double d2 = dx * dx + dy * dy + dz * dz;
                double test = (pos[i].Far ? 1.0 : -1.0) * (d2 - Gate * Gate);
                if (test < tolerance - hair)
                {
                    Assert.Contains(i, flagged);
                }
                else if (test > tolerance + hair)
                {
                    Assert.DoesNotContain(i, flagged);
                }
            }

            // The copied members are the entries strictly inside (94 m, 98 m), give or take the hair.
            int inside = 0, maybe = 0;
            for (int i = 0; i < count; i++)
            {
                double dx = pos[i].X - px, dy = pos[i].Y - py, dz = pos[i].Z - pz;
                double d2 = dx * dx + dy * dy + dz * dz;
                if (d2 > lo * lo + hair && d2 < hi * hi - hair)
                {
                    inside++;
                }
                else if (d2 > lo * lo - hair && d2 < hi * hi + hair)
                {
                    maybe++;
                }
            }

            Assert.InRange(ring.Count, inside, inside + maybe);
        }
    }

    [Theory]
    [InlineData(21)]
    [InlineData(22)]
    public void GridSelection_HoldsEveryEntryNearEitherCircle(int seed)
    {
        // 4,000 entries over 600 m square and 0-160 m up (height alone can carry one across 96 m), a player and a former ring
        // centre up to 40 m apart: the band selection is exactly the entries within the band width of 96 m about the player,
        // and every entry within the crossing width about the former centre that the side test flags is among the hits.
        var rng = new Random(seed);
        var grid = new GateGrid();
        const int count = 4000;
        var place = new (int Cell, int Index)[count];
        for (int i = 0; i < count; i++)
        {
            double x = 20_000.0 + rng.NextDouble() * 600.0, y = 30_000.0 + rng.NextDouble() * 600.0;
            grid.Add(i, 0, 0, x, y, (float)(rng.NextDouble() * 160.0), rng.Next(2) == 0, out int c, out int k);
            place[i] = (c, k);
        }

        var hits = new long[4];
        var band = new long[4];
        var ring = new long[4];
        for (int t = 0; t < 40; t++)
        {
            double px = 20_150.0 + rng.NextDouble() * 300.0, py = 30_150.0 + rng.NextDouble() * 300.0, pz = rng.NextDouble() * 20.0;
            double qx = px + (rng.NextDouble() * 2.0 - 1.0) * 28.0, qy = py + (rng.NextDouble() * 2.0 - 1.0) * 28.0;
            const double crossWidth = 9.0, bandWidth = 12.05, ringWidth = 2.05, tolerance = 0.25;
            int n = grid.Select(px, py, pz, qx, qy, pz, crossWidth, bandWidth, ringWidth, tolerance, ref hits, ref band,
                out int b, ref ring, out int r, out long tested);
            var hitSet = new HashSet<long>(hits[..n]);
            var bandSet = new HashSet<long>(band[..b]);
            Assert.True(tested < count, $"tested {tested} of {count}: the selection should skip cells");
            for (int i = 0; i < count; i++)
            {
                grid.Global(place[i].Cell, place[i].Index, out double x, out double y, out double z);
                double dp = Math.Sqrt((x - px) * (x - px) + (y - py) * (y - py) + (z - pz) * (z - pz));
                double dq = Math.Sqrt((x - qx) * (x - qx) + (y - qy) * (y - qy) + (z - pz) * (z - pz));
                long key = GateGrid.Pack(place[i].Cell, place[i].Index);
                if (Math.Abs(Math.Abs(dp - Gate) - bandWidth) > 1e-6)
                {
                    Assert.Equal(Math.Abs(dp - Gate) < bandWidth, bandSet.Contains(key));
                }

                double side = grid.At(place[i].Cell, place[i].Index).Side;
                if (Math.Abs(dq - Gate) < crossWidth - 1e-6 && side * (dp * dp - Gate * Gate) < tolerance - 1e-6)
                {
                    Assert.Contains(key, hitSet);
                }
            }
        }
    }

    private static bool IsFar(PhysicsObj o, in Position player) => Distance(o, player) > Gate;

    private static double Distance(PhysicsObj o, in Position player)
    {
        GateQueue.Global(o.Position, out double ox, out double oy, out double oz);
        GateQueue.Global(player, out double px, out double py, out double pz);
        double dx = ox - px, dy = oy - py, dz = oz - pz;
        return Math.Sqrt(dx * dx + dy * dy + dz * dz);
    }
}
