using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Determinism;

/// <summary>
/// The port's exact shortcuts of the sweep (obstacles out of reach skipped, the cell array kept when it cannot change)
/// against the plain retail paths (<c>RetailSweep.ReferencePaths</c>): two worlds built from one seed, one of each, tick
/// side by side and every object must have the same bits after every tick (cell, origin, rotation, velocity, transient
/// state). The scene is a crowd on a 2 × 2 landblock corner of random hilly terrain with cliffs, so walkers meet, slide
/// along each other, step up and down, climb slopes, fall, jump and cross landblock and cell edges: random radii, one or two
/// spheres, scales, creatures, ethereal walkers, walkers with cylinder spheres, and standing obstacles.
/// </summary>
[Trait("Category", "Determinism")]
public class ReferencePathsEquivalenceTests
{
    private const int WalkerCount = 260;
    private const int Ticks = 420;
    private const double Dt = 0.05;

    [Fact]
    public void CrowdOnHills_ShortcutsAndReferencePaths_GiveTheSameBitsEveryTick()
    {
        Scene fast = Build(seed: 20261201, reference: false);
        Scene slow = Build(seed: 20261201, reference: true);
        Assert.Equal(fast.Objects.Length, slow.Objects.Length);
        var rngFast = new Random(99);
        var rngSlow = new Random(99);
        long walkerTicks = 0;
        long moved = 0;
        int contacts = 0;
        for (int t = 0; t < Ticks; t++)
        {
            Steer(fast, rngFast, t);
            Steer(slow, rngSlow, t);
            Position[] before = Positions(fast);
            fast.World.Tick(fast.World.CurrentTime + Dt);
            slow.World.Tick(slow.World.CurrentTime + Dt);
            for (int i = 0; i < fast.Objects.Length; i++)
            {
                PhysicsObj a = fast.Objects[i], b = slow.Objects[i];
                AssertSame(a, b, t, i);
                if (a.Position.ObjCellId != before[i].ObjCellId || a.Position.Frame.Origin != before[i].Frame.Origin)
                {
                    moved++;
                }

                if ((a.TransientState & TransientState.Contact) != 0)
                {
                    contacts++;
                }
            }

            walkerTicks += fast.Objects.Length;
        }

        // At least 100,000 object ticks compared, most of them moving (a scene that froze would prove nothing).
        Assert.True(walkerTicks >= 100_000, $"{walkerTicks} object ticks");
        Assert.True(moved > walkerTicks / 2, $"{moved} of {walkerTicks} object ticks moved");
        Assert.True(contacts > walkerTicks / 2, $"{contacts} of {walkerTicks} object ticks in contact");
    }

    private sealed record Scene(PhysicsWorld World, PhysicsObj[] Objects);

    private static Scene Build(int seed, bool reference)
    {
        var rng = new Random(seed);
        TerrainWorld terrain = SyntheticTerrain.Metres();
        for (int bx = 0x40; bx <= 0x41; bx++)
        {
            for (int by = 0x40; by <= 0x41; by++)
            {
                var h = new int[81];
                for (int k = 0; k < 81; k++)
                {
                    // Hills of up to 12 m per 24 m cell, and now and then a 30 m cliff (too steep to walk).
                    h[k] = 20 + rng.Next(13) + (rng.Next(12) == 0 ? 30 : 0);
                }

                SyntheticTerrain.AddBlock(terrain, bx, by, (vx, vy) => h[vx * 9 + vy]);
            }
        }

        var world = new PhysicsWorld(0.0);
        var sweep = new RetailSweep(terrain) { ReferencePaths = reference };
        world.Sweep = sweep;
        var objects = new System.Collections.Generic.List<PhysicsObj>();
        uint id = 1;
        for (int n = 0; objects.Count < WalkerCount && n < WalkerCount * 4; n++)
        {
            // A crowd of about 9 objects per cell around the corner of the four landblocks (global x, y = 192 m).
            float gx = 150f + (float)rng.NextDouble() * 84f, gy = 150f + (float)rng.NextDouble() * 84f;
            int bx = gx < 192f ? 0x40 : 0x41, by = gy < 192f ? 0x40 : 0x41;
            float x = gx - (bx - 0x40) * 192f, y = gy - (by - 0x40) * 192f;
            uint cell = LandDefs.LCoordToGid(bx * 8 + (int)(x / 24f), by * 8 + (int)(y / 24f));
            int kind = rng.Next(10);
            float r = 0.3f + (float)rng.NextDouble() * 0.6f;
            SimplePartArray parts = Walkers.OneSphere(r, 0.3f + (float)rng.NextDouble() * 0.5f, 0.3f + (float)rng.NextDouble() * 0.5f);
            if (kind <= 2)
            {
                // A human-like pair: a second sphere above the first.
                parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, r), r), new Sphere(new Vector3(0f, 0f, r + 1f), r) });
            }
            else if (kind == 3)
            {
                parts.SetCylSpheres(new[] { new CylSphere(Vector3.Zero, r, 1.6f) });
            }

            PhysicsState? state = kind == 4 ? PhysicsState.Ethereal | PhysicsState.Gravity | PhysicsState.ReportCollisions : null;
            IWeenieObject? weenie = kind is 5 or 6 ? WeenieTraits.Creature : null;
            Position p = SyntheticTerrain.OnGround(terrain, cell, x, y, (float)(rng.NextDouble() * 360.0), 0.05f);
            PhysicsObj obj;
            try
            {
                obj = Walkers.Create(world, id, p, parts, state, weenie);
            }
            catch (InvalidOperationException)
            {
                continue;
            }

            id++;
            if (rng.Next(4) == 0)
            {
                obj.SetScaleStatic(0.7f + (float)rng.NextDouble() * 0.7f);
            }

            // One object in ten stands still (an obstacle); the others walk 0.5 to 6 m/s.
            float speed = kind == 9 ? 0f : 0.5f + (float)rng.NextDouble() * 5.5f;
            parts.SequenceVelocity = new Vector3(0f, speed, 0f);
            objects.Add(obj);
        }

        world.ObjectMaintenanceActive = false;
        return new Scene(world, objects.ToArray());
    }

    private static void Steer(Scene s, Random rng, int tick)
    {
        if (tick % 10 != 0)
        {
            return;
        }

        foreach (PhysicsObj o in s.Objects)
        {
            var parts = (SimplePartArray)o.PartArray!;
            parts.SequenceOmega = new Vector3(0f, 0f, (float)(rng.NextDouble() * 2.0 - 1.0));
            if (rng.Next(20) == 0 && (o.TransientState & TransientState.Contact) != 0)
            {
                o.SetVelocity(new Vector3(0f, 0f, 3f + (float)rng.NextDouble() * 3f));
            }
        }
    }

    private static Position[] Positions(Scene s)
    {
        var p = new Position[s.Objects.Length];
        for (int i = 0; i < p.Length; i++)
        {
            p[i] = s.Objects[i].Position;
        }

        return p;
    }

    private static void AssertSame(PhysicsObj a, PhysicsObj b, int tick, int index)
    {
        Position pa = a.Position, pb = b.Position;
        Frame fa = pa.Frame, fb = pb.Frame;
        bool same = pa.ObjCellId == pb.ObjCellId
                    && Bits(fa.Origin) == Bits(fb.Origin)
                    && BitConverter.SingleToInt32Bits(fa.Qw) == BitConverter.SingleToInt32Bits(fb.Qw)
                    && BitConverter.SingleToInt32Bits(fa.Qx) == BitConverter.SingleToInt32Bits(fb.Qx)
                    && BitConverter.SingleToInt32Bits(fa.Qy) == BitConverter.SingleToInt32Bits(fb.Qy)
                    && BitConverter.SingleToInt32Bits(fa.Qz) == BitConverter.SingleToInt32Bits(fb.Qz)
                    && Bits(a.Velocity) == Bits(b.Velocity)
                    && a.TransientState == b.TransientState
                    && a.CellId == b.CellId;
        Assert.True(same, $"tick {tick}, object {index} (id {a.Id}): {pa} / {a.Velocity} / {a.TransientState} vs {pb} / {b.Velocity} / {b.TransientState}");
    }

    private static (int, int, int) Bits(Vector3 v) =>
        (BitConverter.SingleToInt32Bits(v.X), BitConverter.SingleToInt32Bits(v.Y), BitConverter.SingleToInt32Bits(v.Z));
}
