using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using FsCheck;
using FsCheck.Fluent;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// Property-based (FsCheck) invariant of the retail sweep against BSP geometry: a walker among random boxes (walls, pillars,
/// low blocks it may climb) never ends a tick with its sphere inside a box, never NaN, never lost.
/// </summary>
public class BspSweepPropertyTests
{
    private readonly record struct Case(int Seed, int Speed, int Turn, int Heading, int Dt);

    private static readonly Gen<Case> Cases =
        from seed in Gen.Choose(0, int.MaxValue - 1)
        from speed in Gen.Choose(5, 120)               // 0.5 .. 12 m/s of root motion
        from turn in Gen.Choose(-150, 150)             // -1.5 .. 1.5 rad/s
        from heading in Gen.Choose(0, 359)
        from dt in Gen.Elements(34, 50, 100, 200)      // ms per tick
        select new Case(seed, speed, turn, heading, dt);

    private static Config Cfg => PropertyAssert.Replayable(40, 20261122UL, 0x14057B7EF767814FUL);

    [Fact]
    public void RandomWalkers_AmongRandomBoxes_NeverEndInsideOne()
    {
        // "Inside": the distance from the sphere's centre to a box below r - 1 mm (the margin of the BSP behaviour tests: the
        // sphere-polygon tests work to EPSILON = 0.2 mm, positions near 100 m round by 7.6e-6 m). Boxes taller than the
        // walker's step-up reach (0.6 m) can only be touched; lower ones may be climbed onto, where the sphere rests on the
        // top (distance exactly r).
        PropertyAssert.Holds(Cfg, Prop.ForAll(Cases.ToArbitrary(), c =>
        {
            const float r = 0.5f;
            var rng = new Random(c.Seed);
            var boxes = new List<(Vector3 Min, Vector3 Max)>();
            for (int i = 0; i < 12; i++)
            {
                // Centres in a 30 m square around (100, 100), kept 3 m clear of the start point (100, 100).
                Vector3 centre;
                do
                {
                    centre = new Vector3(85f + (float)rng.NextDouble() * 30f, 85f + (float)rng.NextDouble() * 30f, 0f);
                }
                while (Math.Abs(centre.X - 100f) < 3f + 2f && Math.Abs(centre.Y - 100f) < 3f + 2f);

                var half = new Vector3(0.1f + (float)rng.NextDouble() * 2f, 0.1f + (float)rng.NextDouble() * 2f, 0f);
                float height = rng.Next(3) == 0 ? 0.2f + (float)rng.NextDouble() * 0.3f : 3f;
                boxes.Add((centre - half - new Vector3(100f, 100f, 0f), centre + half - new Vector3(100f, 100f, 0f) + new Vector3(0f, 0f, height)));
            }

            WorldCells cells = BspScene.FlatWorld();
            BspScene.AddBoxes(cells, new Vector3(100f, 100f, BspScene.Ground), boxes.ToArray());
            PhysicsWorld world = BspScene.Physics(cells);
            PhysicsObj w = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(100f, 100f), Frame.FromHeading(new Vector3(100f, 100f, BspScene.Ground), c.Heading)), r);
            SweepScene.SetWalk(w, new Vector3(0f, c.Speed / 10f, 0f));
            ((SimplePartArray)w.PartArray!).SequenceOmega = new Vector3(0f, 0f, c.Turn / 100f);
            double t = 0.0;
            for (int tick = 1; tick <= 150; tick++)
            {
                t += c.Dt / 1000.0;
                world.Tick(t);
                Vector3 o = w.Position.Frame.Origin;
                if (w.CellId == 0 || !VectorMath.IsFinite(o))
                {
                    throw new InvalidOperationException($"tick {tick}: lost or non-finite: {w.Position}");
                }

                if (w.Position.ObjCellId >> 16 == ((uint)SweepScene.BlockX << 8 | SweepScene.BlockY)
                    && Vector2.Distance(new Vector2(o.X, o.Y), new Vector2(100f, 100f)) > 40f)
                {
                    break; // it has left the box field; the loaded landblock ends 92 m further
                }

                Vector3 centre = o + new Vector3(0f, 0f, r);
                foreach ((Vector3 mn, Vector3 mx) in boxes)
                {
                    Vector3 gMin = mn + new Vector3(100f, 100f, BspScene.Ground), gMax = mx + new Vector3(100f, 100f, BspScene.Ground);
                    float d = BspScene.DistanceToBox(centre, gMin, gMax);
                    if (d < r - 0.001f)
                    {
                        throw new InvalidOperationException($"tick {tick}: centre {centre} is {d} m from box {gMin}..{gMax}");
                    }
                }
            }

            return true;
        }));
    }
}
