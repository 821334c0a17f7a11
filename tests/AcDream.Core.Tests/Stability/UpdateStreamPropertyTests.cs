using System;
using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Tests.Replay.Harness;
using AcDream.Core.Tests.Support;
using FsCheck;
using FsCheck.Fluent;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// Property-based (FsCheck) invariants over random streams of server reports and frames for a remote creature: the
/// interpolation queue never holds more than 20 nodes, no frame moves the creature faster than the interpolation speed cap
/// unless it was placed (a blip or a snap), and nothing becomes NaN.
/// </summary>
public class UpdateStreamPropertyTests
{
    private enum Kind
    {
        Near,        // a report within 6 m of the last one, next timestamp
        Duplicate,   // the last report again, same timestamp
        Stale,       // a report with an older timestamp
        Far,         // a report 150 m from the last one, next timestamp
        Direct,      // InterpolateTo without the network path
        Frame,       // the client clock advances and the world ticks
    }

    private readonly record struct Event(Kind Kind, int A, int B, int Dt);

    private static readonly Gen<Event> Events =
        from kind in Gen.Frequency(
            (5, Gen.Constant(Kind.Near)), (1, Gen.Constant(Kind.Duplicate)), (1, Gen.Constant(Kind.Stale)),
            (1, Gen.Constant(Kind.Far)), (2, Gen.Constant(Kind.Direct)), (8, Gen.Constant(Kind.Frame)))
        from a in Gen.Choose(-6000, 6000)
        from b in Gen.Choose(-6000, 6000)
        from dt in Gen.Frequency((8, Gen.Choose(34, 120)), (1, Gen.Choose(121, 500)), (1, Gen.Choose(1, 33)))
        select new Event(kind, a, b, dt);

    private static Config Cfg => PropertyAssert.Replayable(150, 20261122UL, 0x2545F4914F6CDD1DUL);

    [Fact]
    public void QueueNeverExceedsTwenty_AndNoFrameMovesFasterThanTheCapExceptAPlacement()
    {
        // The cap: the interpolation step is at most speed * quantum, speed = 2 x the adjusted max speed of the default
        // interpreter (get_minterp: 4 m/s) = 8 m/s (acclient.c:389237); the creature has no root motion and rests on the ground
        // (zero velocity, no gravity), the constraint only shrinks offsets. So a frame that did not place the creature moves it
        // at most 8 m/s * (the simulated time: update_time after - before). Float rounding of the origin (below 256 m: 1.5e-5
        // m per operation, a few operations per step, at most 10 steps per frame): allow 1e-3 m.
        PropertyAssert.Holds(Cfg, Prop.ForAll(Gen.ArrayOf(Events, 120).ToArbitrary(), events =>
        {
            var s = new ManagerScene(new Vector3(96f, 80f, 0f));
            s.World.Tick(0.05);
            PhysicsObj c = s.Creature;
            ushort stamp = 1;
            Position last = c.Position;
            double now = s.World.CurrentTime;
            foreach (Event e in events)
            {
                switch (e.Kind)
                {
                    case Kind.Near:
                    case Kind.Far:
                        Vector3 o = ManagerScene.GlobalOf(last);
                        Vector3 step = e.Kind == Kind.Near ? new Vector3(e.A / 1000f, e.B / 1000f, 0f) : new Vector3(e.A >= 0 ? 150f : -150f, 0f, 0f);
                        last = ManagerScene.At(Wrap(o + step), e.B * 0.03f);
                        c.HandleReceivedPosition(last, ++stamp, 0, true);
                        break;
                    case Kind.Duplicate:
                        c.HandleReceivedPosition(last, stamp, 0, true);
                        break;
                    case Kind.Stale:
                        c.HandleReceivedPosition(ManagerScene.At(Wrap(ManagerScene.GlobalOf(last) + new Vector3(3f, 0f, 0f))), (ushort)(stamp - 1 - (e.A & 7)), 0, true);
                        break;
                    case Kind.Direct:
                        c.InterpolateTo(ManagerScene.At(Wrap(ManagerScene.GlobalOf(c.Position) + new Vector3(e.A / 500f, e.B / 500f, 0f))), (e.A & 1) == 0);
                        break;
                    case Kind.Frame:
                        Position before = c.Position;
                        double u0 = c.UpdateTime;
                        int placements = s.Ground.PlacementCount;
                        now += e.Dt / 1000.0;
                        s.World.Tick(now);
                        double simulated = c.UpdateTime - u0;
                        bool placed = s.Ground.PlacementCount != placements;
                        float moved = Vector3.Distance(ManagerScene.GlobalOf(before), ManagerScene.GlobalOf(c.Position));
                        if (!placed && moved > 8.0 * Math.Max(simulated, 0.0) + 1e-3)
                        {
                            throw new InvalidOperationException(FormattableString.Invariant($"moved {moved} m in {simulated} s without a placement"));
                        }

                        break;
                }

                int count = c.PositionManager?.InterpolationManager?.Count ?? 0;
                if (count > InterpolationManager.MaxQueueLength || !VectorMath.IsFinite(c.Position.Frame.Origin) || !c.Position.Frame.IsValid())
                {
                    return false;
                }
            }

            return true;
        }));
    }

    // Keeps reports inside landblock 0x7F7F's neighbourhood (global offsets -150..340 m from its corner), well inside the world.
    private static Vector3 Wrap(Vector3 g) => new(Math.Clamp(g.X, -150f, 340f), Math.Clamp(g.Y, -150f, 340f), 0f);
}
