using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using FsCheck;
using FsCheck.Fluent;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// Property (FsCheck): a human walker (EDGE_SLIDE, two spheres, step-up 0.6 m, step-down 1.5 m) walking at a random angle
/// up a random flight of box steps never ends a tick out of contact and not falling, and never in contact while touching
/// nothing.
/// </summary>
public class StairContactPropertyTests
{
    private readonly record struct Case(int Rise, int Depth, int Heading, int Speed);

    private static readonly Gen<Case> Cases =
        from rise in Gen.Choose(5, 95)          // 0.05 .. 0.95 m per step (the retail reach is 1.5 * 0.6 = 0.9 m)
        from depth in Gen.Choose(4, 20)         // 0.4 .. 2 m treads
        from heading in Gen.Choose(50, 130)     // degrees; 90 walks straight up the flight (east)
        from speed in Gen.Choose(10, 40)        // 1 .. 4 m/s
        select new Case(rise, depth, heading, speed);

    private static Config Cfg => PropertyAssert.Replayable(60, 20261201UL, 0x2545F4914F6CDD1DUL);

    [Fact]
    public void HumanOnRandomStairs_IsNeverOutOfContactWithoutFalling_NorInContactWithNothing()
    {
        // "Falling": z goes down. A falling sphere held by an edge may
        // stay put for up to three ticks: CTransition::validate_transition counts such frames (frames_stationary_fall) and at
        // the third sets a contact plane under the sphere (acclient.c:312193), so the fourth tick is in contact. "On a surface's plane": the feet (origin z) within 2 cm of the ground or of a tread top whose
        // rectangle is within r horizontally of the foot sphere's centre. Retail's step up lifts the sphere onto the tread's
        // plane as soon as the sphere touches the tread's edge (BSPTREE::step_sphere_down moves it along -z onto the plane,
        // acclient.c:361176), so a walker may stand on a tread's plane up to r short of its edge for a few ticks; it may not
        // stand on nothing.
        PropertyAssert.Holds(Cfg, Prop.ForAll(Cases.ToArbitrary(), c =>
        {
            float rise = c.Rise / 100f;
            float depth = c.Depth / 10f;
            var boxes = new (Vector3 Min, Vector3 Max)[5];
            for (int i = 0; i < 5; i++)
            {
                boxes[i] = (new Vector3(i * depth, -3f, 0f), new Vector3((i + 1) * depth, 3f, (i + 1) * rise));
            }

            var origin = new Vector3(105f, 100f, BspScene.Ground);
            WorldCells cells = BspScene.FlatWorld();
            BspScene.AddBoxes(cells, origin, boxes);
            PhysicsWorld world = BspScene.Physics(cells);
            PhysicsObj obj = HumanWalker.Create(world, new Position(BspScene.OutdoorCell(101f, 100f), Frame.FromHeading(new Vector3(101f, 100f, BspScene.Ground), c.Heading)));
            SweepScene.SetWalk(obj, new Vector3(0f, c.Speed / 10f, 0f));
            int hanging = 0;
            bool stationaryFall = false; // the third stationary frame's contact plane (above) is under the sphere, not on a surface
            float lastZ = obj.Position.Frame.Origin.Z;
            for (int tick = 0; tick < 120; tick++)
            {
                world.Tick(world.CurrentTime + SweepScene.Dt);
                Vector3 o = obj.Position.Frame.Origin;
                Vector3 foot = o + new Vector3(0f, 0f, HumanWalker.Radius);
                bool contact = (obj.TransientState & TransientState.Contact) != 0;
                if (contact && !RestsOnAPlane(o, origin, boxes) && !stationaryFall)
                {
                    throw new InvalidOperationException($"{c}: tick {tick}: in contact but on no surface's plane at {o}");
                }

                hanging = !contact && !(o.Z < lastZ - 1e-4f) ? hanging + 1 : 0;
                if (hanging > 3)
                {
                    throw new InvalidOperationException($"{c}: tick {tick}: out of contact and not falling for 4 ticks at {o}");
                }

                lastZ = o.Z;
                stationaryFall = (obj.TransientState & TransientState.StationaryFall) != 0;
            }

            return true;
        }));
    }

    private static bool RestsOnAPlane(Vector3 o, Vector3 origin, (Vector3 Min, Vector3 Max)[] boxes)
    {
        if (MathF.Abs(o.Z - BspScene.Ground) <= 0.02f)
        {
            return true;
        }

        foreach (var (mn, mx) in boxes)
        {
            Vector3 lo = origin + mn, hi = origin + mx;
            float dx = MathF.Max(MathF.Max(lo.X - o.X, 0f), o.X - hi.X);
            float dy = MathF.Max(MathF.Max(lo.Y - o.Y, 0f), o.Y - hi.Y);
            if (MathF.Abs(o.Z - hi.Z) <= 0.02f && dx * dx + dy * dy <= HumanWalker.Radius * HumanWalker.Radius)
            {
                return true;
            }
        }

        return false;
    }
}
