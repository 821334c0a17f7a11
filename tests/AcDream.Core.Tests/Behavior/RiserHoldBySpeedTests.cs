using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

// Issue #25 item 9: the one-sphere EDGE_SLIDE riser hold is retail, and at walking speed only. Retail path: the step up
// (CTransition::step_up, acclient.c:312793) lifts the sphere onto the tread's plane as soon as it touches the riser, with
// the centre still over the lower floor; step_down skips the walkable probe while step_up is set (312664-312668). On the
// next step, transitional_insert's step down (312833; a single sphere's step-down above 2r is cut to r/2 there, 312974)
// and CTransition::check_walkable (312474: first SPHEREPATH::check_walkables, i.e. half the sphere, r/2, on the tread;
// else a probe down by the step-down height, cut to r/2 for a single sphere when it exceeds 2r, 312506) must find
// walkable ground. With r 0.5 and step-down 1.5 the probe is 0.25 m: on a 0.31 m riser it ends 0.06 m above the floor and
// finds nothing, so edge_slide -> SPHEREPATH::precipice_slide (acclient.c:314002-314032) removes the movement across the
// tread's edge: the walker is held on the tread's plane. It is released as soon as one step puts the centre within r/2 of
// the tread (check_walkables then succeeds without a probe): x >= 105 - 0.25 = 104.75 for the riser at x = 105.
// Walking, 0.1 m steps: the riser is touched at x 104.6 (r - 0.1 inside), the next step ends at 104.7 < 104.75: held for
// good. Running, 0.3 m steps from x 100: 104.5 (touching at exactly r, no hit), then 104.8: touched and lifted at 104.8 >=
// 104.75, on the tread's half-sphere test at once: every riser climbed the same way.
public class RiserHoldBySpeedTests
{
    private const float R = 0.5f;
    private const float Rise = 0.31f;

    private static (PhysicsWorld World, PhysicsObj Walker) Flight(float speed)
    {
        // Five treads 1 m deep and 0.31 m high from x = 105, 3 m wide; the walker (one sphere r 0.5, step-up 0.4,
        // step-down 1.5, retail's default state with EDGE_SLIDE) at (100, 100) facing east.
        WorldCells cells = BspScene.FlatWorld();
        var boxes = new (Vector3, Vector3)[5];
        for (int i = 0; i < 5; i++)
        {
            boxes[i] = (new Vector3(i, -1.5f, 0f), new Vector3(i + 1, 1.5f, (i + 1) * Rise));
        }

        BspScene.AddBoxes(cells, new Vector3(105f, 100f, BspScene.Ground), boxes);
        PhysicsWorld world = BspScene.Physics(cells);
        var at = new Position(BspScene.OutdoorCell(100f, 100f), Frame.FromHeading(new Vector3(100f, 100f, BspScene.Ground), 90f));
        PhysicsObj w = SweepScene.Walker(world, at, R, stepUp: 0.4f, stepDown: 1.5f);
        Assert.True((w.State & PhysicsState.EdgeSlide) != 0);
        SweepScene.SetWalk(w, new Vector3(0f, speed, 0f));
        return (world, w);
    }

    [Fact]
    public void Walking_0_1MetreSteps_IsHeldAtTheRiser_OnTheTreadsPlane()
    {
        var (world, w) = Flight(2f);   // 2 m/s x 0.05 s = 0.1 m per tick
        SweepScene.Run(world, 95);
        Assert.Equal(104.6f, w.Position.Frame.Origin.X, 3);
        Assert.Equal(BspScene.Ground + Rise, w.Position.Frame.Origin.Z, 3);
        Assert.True((w.TransientState & TransientState.Contact) != 0);
    }

    [Fact]
    public void Running_0_3MetreSteps_ClimbsTheFlight()
    {
        var (world, w) = Flight(6f);   // 6 m/s x 0.05 s = 0.3 m per tick
        float topZ = BspScene.Ground + 5 * Rise;   // 21.55
        bool onTop = false;
        // The top tread (x 109..110) is under the centre after (109.3 - 100) / 0.3 = 31 ticks; stop before the far end.
        for (int i = 0; i < 32; i++)
        {
            SweepScene.Run(world, 1);
            Vector3 o = w.Position.Frame.Origin;
            onTop |= o.X > 109f && o.X < 110f && System.Math.Abs(o.Z - topZ) < 0.001f;
        }

        Assert.True(onTop, $"did not reach the top tread: {w.Position.Frame.Origin}");
    }
}
