using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Determinism;

/// <summary>
/// Each exact shortcut of the sweep against the retail computation it replaces, over many random inputs, bit for bit:
/// the direct outdoor cells of spheres inside one landblock's cells (<see cref="CellList.TryInteriorCells"/>) against
/// <see cref="LandCell.AddAllOutsideCells"/>, and the check spheres taken from the current centres
/// (<see cref="SpherePath.CacheGlobalSphereFromCurrCenter"/>) against <see cref="SpherePath.CacheGlobalSphere()"/>.
/// The whole sweep with and without them is compared by <see cref="ReferencePathsEquivalenceTests"/>.
/// </summary>
[Trait("Category", "Determinism")]
public class SweepShortcutIdentityTests
{
    [Fact]
    public void InteriorCells_MatchTheGeneralOutdoorCellSearch()
    {
        var rng = new Random(424242);
        uint[] blocks = { 0xA9B40000, 0x00000000, 0x00FF0000, 0xFF000000, 0xFEFE0000, 0x40400000 };
        Span<Sphere> spheres = stackalloc Sphere[2];
        Span<Vector3> centers = stackalloc Vector3[2];
        Span<float> radii = stackalloc float[2];
        Span<uint> ids = stackalloc uint[LandCell.MaxCellsPerSphere * 2];
        int shortcut = 0, general = 0;
        for (int k = 0; k < 400_000; k++)
        {
            uint cellLow = rng.Next(10) == 0 ? (uint)rng.Next(0, 0x120) : (uint)rng.Next(1, 65);
            uint cellId = blocks[rng.Next(blocks.Length)] | cellLow;
            int n = rng.Next(1, 3);
            for (int i = 0; i < n; i++)
            {
                float r = rng.Next(6) switch
                {
                    0 => 0f,
                    1 => 12f + (float)rng.NextDouble() * 2f,
                    _ => (float)rng.NextDouble() * 2f,
                };
                centers[i] = new Vector3(Coordinate(rng, r), Coordinate(rng, r), (float)(rng.NextDouble() * 100.0));
                radii[i] = r;
                spheres[i] = new Sphere(centers[i], r);
            }

            var p = new Position(cellId, new Vector3(centers[0].X, centers[0].Y, 0f));
            if (!CellList.TryInteriorCells(cellId, spheres[..n], out uint id0, out uint id1))
            {
                general++;
                continue;
            }

            shortcut++;
            int count = LandCell.AddAllOutsideCells(p, centers[..n], radii[..n], ids, 0);
            int expected = id1 == 0 ? 1 : 2;
            Assert.True(count == expected && ids[0] == id0 && (id1 == 0 || ids[1] == id1),
                $"case {k}: cell {cellId:X8}, spheres {spheres[0]} {(n > 1 ? spheres[1].ToString() : "")}: shortcut {id0:X8} {id1:X8}, general {count} cells {ids[0]:X8} {(count > 1 ? ids[1] : 0):X8}");
        }

        // Both paths must be exercised often: at least 50,000 cases each (about 18 % take the shortcut).
        Assert.True(shortcut > 50_000 && general > 50_000, $"{shortcut} shortcut, {general} general");
    }

    [Fact]
    public void CheckSpheresFromCurrentCentres_MatchTheFullRecompute()
    {
        var rng = new Random(777);
        var path = new SpherePath();
        Span<Sphere> local = stackalloc Sphere[2];
        for (int k = 0; k < 200_000; k++)
        {
            int n = rng.Next(1, 3);
            for (int i = 0; i < n; i++)
            {
                // Centres on the z axis (walkers), and off it; some exact zeros of either sign.
                float cx = rng.Next(3) == 0 ? Small(rng) : 0f, cy = rng.Next(3) == 0 ? Small(rng) : (rng.Next(2) == 0 ? 0f : -0f);
                float r = (float)rng.NextDouble() + 0.1f;
                local[i] = new Sphere(new Vector3(cx, cy, rng.Next(4) == 0 ? -0f : r + i), r);
            }

            path.InitSphere(local[..n], rng.Next(4) == 0 ? 1.3f : 1f);
            Quaternion q = rng.Next(3) switch
            {
                0 => Quaternion.CreateFromAxisAngle(Vector3.UnitZ, (float)(rng.NextDouble() * 7.0)),
                1 => Quaternion.Normalize(new Quaternion(Small(rng), Small(rng), Small(rng), 1f)),
                _ => Quaternion.Identity,
            };
            var origin = new Vector3(Small(rng) * 100f, Small(rng) * 100f, rng.Next(5) == 0 ? 0f : Small(rng) * 50f);
            var pos = new Position(0xA9B40001, new Frame(origin, q));
            path.InitPath(null, true, pos, pos);
            path.CheckPos = path.CurrPos;
            path.CacheGlobalSphereFromCurrCenter(path.CheckPos.Frame);
            Sphere s0 = path.GlobalSphere[0], s1 = path.GlobalSphere[1];
            Vector3 low = path.GlobalLowPoint;
            path.CacheGlobalSphere();
            Assert.True(Same(s0, path.GlobalSphere[0]) && (n < 2 || Same(s1, path.GlobalSphere[1])) && Same(low, path.GlobalLowPoint),
                $"case {k}: frame {pos.Frame}, spheres {local[0]} {(n > 1 ? local[1].ToString() : "")}");
        }
    }

    [Fact]
    public void ObjectReach_MarginsAndBox_AsDocumented()
    {
        Assert.Equal(0.05, ObjectReach.Margin);
        Assert.Equal(1e-4, ObjectReach.RelativeMargin);

        // One check sphere at (10, 10, 10), r = 0.5: the box is [9.5, 10.5] on each axis.
        var path = new SpherePath();
        path.InitSphere(new[] { new Sphere(Vector3.Zero, 0.5f) }, 1f);
        path.CheckPos = new Position(0xA9B40001, new Vector3(10f, 10f, 10f));
        path.CacheGlobalSphere();
        var reach = new ObjectReach(path);
        Assert.Equal(9.5, reach.MinX);
        Assert.Equal(10.5, reach.MaxZ);

        // An obstacle reaching 0.3 m from (11.9, 10, 10): m = 0.3 + 0.05 + 1e-4 * (11.9 + 10 + 10 + 0.3) = 0.35322, and
        // 11.9 - 0.35322 = 11.54678 > 10.5: out of reach. From (10.85, 10, 10): m = 0.353115, 10.85 - m = 10.496885 < 10.5.
        Assert.True(reach.Excludes(11.9, 10.0, 10.0, 0.3));
        Assert.False(reach.Excludes(10.85, 10.0, 10.0, 0.3));
        Assert.False(reach.Excludes(double.NaN, 10.0, 10.0, 0.3));
        Assert.False(reach.Excludes(100.0, 10.0, 10.0, double.NaN));
    }

    [Fact]
    public void ObstacleReach_BoundsEverySphere_AndIsOffWithCylinders()
    {
        // Created with one dummy sphere: centre (0, 0, 0.1), r = 0.1 (PhysicsGlobals.DummySphereRadius): 0.2.
        var parts = new AcDream.Core.Physics.Objects.Parts.SimplePartArray(1, 1);
        Assert.Equal((float)((double)PhysicsGlobals.DummySphereRadius + PhysicsGlobals.DummySphereRadius), parts.ObstacleReach);

        // (0, 0, 0.5) r 0.5 reaches 1; (0.3, -0.4, 1.5) r 0.5 reaches 0.3 + 0.4 + 1.5 + 0.5 = 2.7 (in double from the floats
        // 2.70000001192..., stored as the float 2.7f = 2.70000004768..., which is not below it).
        parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f), new Sphere(new Vector3(0.3f, -0.4f, 1.5f), 0.5f) });
        Assert.Equal(2.7f, parts.ObstacleReach);
        Assert.True(parts.ObstacleReach >= (double)0.3f + 0.4f + 1.5f + 0.5f);

        parts.SetCylSpheres(new[] { new CylSphere(Vector3.Zero, 0.5f, 1.8f) });
        Assert.Equal(-1f, parts.ObstacleReach);
    }

    // A coordinate for a sphere of radius r: anywhere in and around the landblock, or within a few ulps of a cell edge or of
    // the radius from one (where the edge tests turn), or of 0, EPSILON and 192.
    private static float Coordinate(Random rng, float r)
    {
        float edge = 24f * rng.Next(0, 9);
        float baseValue = rng.Next(16) switch
        {
            0 => edge + r,
            1 => edge - r,
            2 => edge,
            3 => PhysicsGlobals.Epsilon,
            4 => -PhysicsGlobals.Epsilon,
            _ => (float)(rng.NextDouble() * 200.0 - 4.0),
        };
        for (int ulps = rng.Next(-3, 4); ulps != 0; ulps -= Math.Sign(ulps))
        {
            baseValue = ulps > 0 ? MathF.BitIncrement(baseValue) : MathF.BitDecrement(baseValue);
        }

        return baseValue;
    }

    private static float Small(Random rng) => (float)(rng.NextDouble() * 2.0 - 1.0);

    private static bool Same(in Sphere a, in Sphere b) => Same(a.Center, b.Center) && Bits(a.Radius) == Bits(b.Radius);

    private static bool Same(Vector3 a, Vector3 b) => Bits(a.X) == Bits(b.X) && Bits(a.Y) == Bits(b.Y) && Bits(a.Z) == Bits(b.Z);

    private static int Bits(float f) => BitConverter.SingleToInt32Bits(f);
}
