using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Determinism;

/// <summary>
/// The cells' obstacle tables against the exact test they stand for. The vector test
/// (<see cref="ObstacleTable.OutOfReach"/>, four entries at a time) gives, lane by lane, the scalar
/// <see cref="ObjectReach.Excludes"/> of the same doubles; and the reach it is given (the exact |scale| · bound rounded up to
/// a float, <see cref="ObstacleSummary.RoundUpReach"/>) never rejects an obstacle that the exact reach keeps.
/// </summary>
[Trait("Category", "Determinism")]
public class ObstacleTableIdentityTests
{
    [Fact]
    public void OutOfReach_IsTheScalarExclusion_LaneByLane()
    {
        var rng = new Random(3810);
        var path = new SpherePath();
        var table = new ObstacleTable(4);
        var s = new ObstacleSummary[4];
        int rejected = 0, kept = 0;
        for (int k = 0; k < 100_000; k++)
        {
            ObjectReach box = Box(rng, path, out Vector3 centre);
            // The cell's landblock offset: none, or a neighbour's (±192 m), as BoxToCellOffset gives.
            Vector3 offset = rng.Next(4) switch
            {
                0 => new Vector3(192f, 0f, 0f),
                1 => new Vector3(0f, -192f, 0f),
                _ => Vector3.Zero,
            };
            for (int lane = 0; lane < 4; lane++)
            {
                float r = rng.Next(12) switch
                {
                    0 => ObstacleSummary.Parented,
                    1 => ObstacleSummary.TestFully,
                    2 => 0f,
                    _ => (float)(rng.NextDouble() * 4.0),
                };
                s[lane] = new ObstacleSummary
                {
                    X = rng.Next(50) == 0 ? -0f : Near(rng, centre.X - offset.X),
                    Y = Near(rng, centre.Y - offset.Y),
                    Z = Near(rng, centre.Z),
                    Reach = r,
                    CellId = 0xA9B40001,
                };
                table.Set(lane, s[lane], 0xA9B4);
            }

            int group = table.NextKept(0, 4, box, offset, out uint keptLanes);
            uint outside = group == 0 ? ~keptLanes & 0xFu : 0xFu;
            for (int lane = 0; lane < 4; lane++)
            {
                bool excluded = box.Excludes((double)offset.X + s[lane].X, (double)offset.Y + s[lane].Y, (double)offset.Z + s[lane].Z,
                    s[lane].Reach);
                Assert.True(((outside >> lane) & 1) == (excluded ? 1u : 0u),
                    $"case {k}, lane {lane}: {s[lane]}, offset {offset}, box x [{box.MinX}, {box.MaxX}] y [{box.MinY}, {box.MaxY}] z [{box.MinZ}, {box.MaxZ}]");
                Assert.True(excluded || s[lane].Reach != ObstacleSummary.Parented, "a parented entry is always rejected");
                Assert.True(!excluded || !float.IsNaN(s[lane].Reach), "a NaN reach is never rejected");
                if (excluded)
                {
                    rejected++;
                }
                else
                {
                    kept++;
                }
            }
        }

        // Both answers must be common (about 80 % and 20 %).
        Assert.True(rejected > 60_000 && kept > 60_000, $"{rejected} rejected, {kept} kept");
    }

    [Fact]
    public void RoundedUpReach_RejectsOnlyWhatTheExactReachRejects()
    {
        var rng = new Random(3811);
        var path = new SpherePath();
        int agree = 0, keptByRounding = 0;
        for (int k = 0; k < 200_000; k++)
        {
            ObjectReach box = Box(rng, path, out Vector3 centre);
            float scale = 0.01f + (float)rng.NextDouble() * 4f, bound = (float)rng.NextDouble() * 3f;
            double exact = Math.Abs((double)scale) * bound;
            float up = ObstacleSummary.RoundUpReach(scale, bound);
            Assert.True(up >= exact && (up == 0f || MathF.BitDecrement(up) < exact), $"case {k}: {scale} × {bound} = {exact:R}, rounded {up:R}");
            // Obstacles on the edge: x a few float steps from where x − m (the margin of the exact reach) meets the box's
            // upper x bound, or within a few centimetres of it.
            float fy = Near(rng, centre.Y), fz = Near(rng, centre.Z);
            double guess = box.MaxX + exact + ObjectReach.Margin;
            double m = exact + ObjectReach.Margin
                + ObjectReach.RelativeMargin * (Math.Abs(guess) + Math.Abs((double)fy) + Math.Abs((double)fz) + exact);
            float fx = (float)(box.MaxX + m);
            if (rng.Next(2) == 0)
            {
                for (int steps = rng.Next(-3, 4); steps != 0; steps -= Math.Sign(steps))
                {
                    fx = steps > 0 ? MathF.BitIncrement(fx) : MathF.BitDecrement(fx);
                }
            }
            else
            {
                fx += (float)((rng.NextDouble() - 0.5) * 0.05);
            }

            bool byUp = box.Excludes(fx, fy, fz, up), byExact = box.Excludes(fx, fy, fz, exact);
            Assert.True(!byUp || byExact, $"case {k}: rejected with the rounded reach {up:R} but not with the exact {exact:R}");
            if (byUp == byExact)
            {
                agree++;
            }
            else
            {
                keptByRounding++;
            }
        }

        // The rounding keeps (for the object's own test) only a sliver of the edge cases, but some: the implication is tested
        // where it can fail.
        Assert.True(agree > 150_000 && keptByRounding > 0, $"{agree} agree, {keptByRounding} kept only by the rounding");
    }

    // A box around one or two check spheres (radius 0.1 to 1.1 m) at a random spot of landblock 0xA9B4.
    private static ObjectReach Box(Random rng, SpherePath path, out Vector3 centre)
    {
        Sphere[] local =
        {
            new(new Vector3(0f, 0f, 0.5f), 0.1f + (float)rng.NextDouble()),
            new(new Vector3(0f, 0f, 1.5f), 0.1f + (float)rng.NextDouble()),
        };
        path.InitSphere(local.AsSpan(0, rng.Next(1, 3)), 1f);
        centre = new Vector3((float)(rng.NextDouble() * 192.0), (float)(rng.NextDouble() * 192.0), (float)(rng.NextDouble() * 100.0));
        path.CheckPos = new Position(0xA9B40001, centre);
        path.CacheGlobalSphere();
        return new ObjectReach(path);
    }

    // A coordinate near c: within 4 m, or 0.5 to 2.5 m to either side (around the margins' edge), or anywhere in 0..192.
    private static float Near(Random rng, float c) => rng.Next(3) switch
    {
        0 => c + (float)(rng.NextDouble() * 8.0 - 4.0),
        1 => c + (rng.Next(2) == 0 ? 1f : -1f) * (0.5f + (float)(rng.NextDouble() * 2.0)),
        _ => (float)(rng.NextDouble() * 192.0),
    };
}
