using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

// Issue #33: the human's real step-up reach (docs/bsp-and-indoor.md, "Step-up reach on BSP geometry"). Retail path:
// the grounded hit on the riser asks CTransition::step_up (acclient.c:312793), whose step_down finds the tread only through
// BSPTREE::step_sphere_down (361176) -> find_walkable (363662 / 364310) -> CPolygon::walkable_hits_sphere (360518): the foot
// sphere (radius r - EPSILON = 0.4798, centre 0.48 up) must touch the tread polygon, i.e. its circle at the tread's height
// must reach past the edge: sqrt(0.4798^2 - (rise - 0.48)^2) >= d, d the centre's distance from the riser at the step that
// first touches it. Only then does adjust_sphere_to_plane's 1.5 x step_up_height (0.9 m) apply. A failed step up leaves the
// walker where its last step ended (the slide along the riser's normal, the direction of travel, keeps no motion), so it
// meets the riser at the same d every tick: held for good.
// From x = 100 in 0.05 s ticks: at 2 m/s the riser (x = 105) is first touched from x 104.6 (d 0.4): reach
// 0.48 + sqrt(0.23020804 - 0.16) = 0.7450; at 3.12 m/s (the human's walk) from 104.524 (d 0.476): reach
// 0.48 + sqrt(0.23020804 - 0.226576) = 0.5403, below the 0.6 step-up height itself.
public class StepUpReachTests
{
    private static (PhysicsWorld World, PhysicsObj Walker) Block(float rise, float speed)
    {
        // One block 1 m deep and `rise` high from x = 105, 3 m wide; the human (two spheres r 0.48, step-up 0.6,
        // step-down 1.5) at (100, 100) facing east.
        WorldCells cells = BspScene.FlatWorld();
        BspScene.AddBoxes(cells, new Vector3(105f, 100f, BspScene.Ground),
            new[] { (new Vector3(0f, -1.5f, 0f), new Vector3(1f, 1.5f, rise)) });
        PhysicsWorld world = BspScene.Physics(cells);
        var at = new Position(BspScene.OutdoorCell(100f, 100f), Frame.FromHeading(new Vector3(100f, 100f, BspScene.Ground), 90f));
        PhysicsObj w = HumanWalker.Create(world, at);
        SweepScene.SetWalk(w, new Vector3(0f, speed, 0f));
        return (world, w);
    }

    [Theory]
    [InlineData(2f, 0.74f, true)]
    [InlineData(2f, 0.75f, false)]
    [InlineData(3.12f, 0.53f, true)]
    [InlineData(3.12f, 0.55f, false)]
    public void TheTreadIsReachedOnlyWhenTheFootSpheresCircleReachesItsEdge(float speed, float rise, bool climbs)
    {
        var (world, w) = Block(rise, speed);
        float top = 0f;
        SweepScene.Run(world, 100, _ => top = MathF.Max(top, w.Position.Frame.Origin.Z - BspScene.Ground));
        Vector3 o = w.Position.Frame.Origin;
        if (climbs)
        {
            Assert.Equal(rise, top, 3);                          // stood on the tread
            Assert.True(o.X > 106f, $"stopped at {o}");           // and walked on over it
        }
        else
        {
            Assert.Equal(0f, top);                               // never lifted
            Assert.True(o.X < 105f - 0.48f, $"passed the riser: {o}");
            Assert.True(o.X > 104f, $"did not walk up to the riser: {o}");
        }
    }
}
