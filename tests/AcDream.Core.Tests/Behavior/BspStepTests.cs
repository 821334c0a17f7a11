using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class BspStepTests
{
    private const float R = 0.5f;
    // Retail's reach on BSP steps: step_up runs step_down(step_up_height) WITHOUT lowering the sphere first, and
    // CPolygon::adjust_sphere_to_plane accepts a lift of t * h as long as walk_interp = 1 - t stays >= -0.5, i.e. a rise of up
    // to 1.5 * h (provided the sphere reaches the tread). With h = 0.4 the limit is 0.6 m.
    private const float StepUp = 0.4f;

    // Five steps, each 1 m deep and `rise` high, climbing east from x = 105 (the first riser) to x = 110, 3 m wide.
    private static PhysicsObj StairScene(float rise, out PhysicsWorld world)
    {
        WorldCells cells = BspScene.FlatWorld();
        var boxes = new (Vector3, Vector3)[5];
        for (int i = 0; i < 5; i++)
        {
            boxes[i] = (new Vector3(i, -1.5f, 0f), new Vector3(i + 1, 1.5f, (i + 1) * rise));
        }

        BspScene.AddBoxes(cells, new Vector3(105f, 100f, BspScene.Ground), boxes);
        world = BspScene.Physics(cells);
        // Facing east (heading 90) at 2 m/s: 0.1 m per tick. Default state minus EDGE_SLIDE: these tests pin the step-up
        // reach alone (with EDGE_SLIDE the precipice probe decides too, see the tests below and docs/bsp-and-indoor.md).
        PhysicsObj obj = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(100f, 100f), Frame.FromHeading(new Vector3(100f, 100f, BspScene.Ground), 90f)),
            R, stepUp: StepUp, stepDown: StepUp, state: (PhysicsState)PhysicsGlobals.DefaultState & ~PhysicsState.EdgeSlide);
        SweepScene.SetWalk(obj, new Vector3(0f, 2f, 0f));
        return obj;
    }

    [Fact]
    public void Staircase_RiseJustUnderTheRetailStepReach_IsClimbed()
    {
        // rise 0.55 < 1.5 * 0.4 = 0.6. The riser is hit with the centre 0.1 m into it (x = 104.6, 0.1 m per tick); the
        // tread (z 0.55) is 0.05 above the centre, and its edge is 0.4 m away horizontally: within the contact radius
        // sqrt((0.5 - 0.0002)^2 - 0.05^2) = 0.497, so find_walkable meets it; t = (0.05 + 0.5) / 0.4 = 1.375, walk_interp
        // 1 - 1.375 = -0.375 >= -0.5: accepted, the sphere rises 0.55.
        PhysicsObj obj = StairScene(0.55f, out PhysicsWorld world);
        SweepScene.Run(world, 95);

        // 95 ticks * 0.1 m = 9.5 m of walking: from x = 100 to 109.5 when nothing holds it back, i.e. on the top tread
        // (x 109..110). It stands on it: z = 20 + 5 * 0.55 = 22.75.
        Vector3 o = obj.Position.Frame.Origin;
        Assert.True(o.X > 109f && o.X < 110f, $"stopped at {o}");
        Assert.Equal(BspScene.Ground + 5 * 0.55f, o.Z, 3);
        Assert.True((obj.TransientState & TransientState.OnWalkable) != 0);
    }

    [Fact]
    public void Staircase_RiseJustOverTheRetailStepReach_Blocks()
    {
        // rise 0.65 > 0.6: the tread is reached (contact radius sqrt(0.4998^2 - 0.15^2) = 0.477 >= 0.4) but
        // t = (0.15 + 0.5) / 0.4 = 1.625 gives walk_interp -0.625 < -0.5: rejected. The step up fails and the walker slides
        // against the riser (normal -x): it stays on the ground, in front of the first riser (centre x <= 105 - r).
        PhysicsObj obj = StairScene(0.65f, out PhysicsWorld world);
        SweepScene.Run(world, 150, _ =>
        {
            Assert.True(obj.Position.Frame.Origin.X <= 105f - R + 0.001f, $"passed the riser: {obj.Position.Frame.Origin}");
            Assert.Equal(BspScene.Ground, obj.Position.Frame.Origin.Z, 3);
        });

        Assert.True(obj.Position.Frame.Origin.X > 104f, "it did walk up to the riser");
    }

    // Five treads 1 m deep and `rise` high from x = 105, for a walker with EDGE_SLIDE (retail's default state).
    private static PhysicsWorld Flight(float rise)
    {
        WorldCells cells = BspScene.FlatWorld();
        var boxes = new (Vector3, Vector3)[5];
        for (int i = 0; i < 5; i++)
        {
            boxes[i] = (new Vector3(i, -1.5f, 0f), new Vector3(i + 1, 1.5f, (i + 1) * rise));
        }

        BspScene.AddBoxes(cells, new Vector3(105f, 100f, BspScene.Ground), boxes);
        return BspScene.Physics(cells);
    }

    private static Position StartFacingEast() =>
        new(BspScene.OutdoorCell(100f, 100f), Frame.FromHeading(new Vector3(100f, 100f, BspScene.Ground), 90f));

    [Fact]
    public void Repro_Staircase_WithEdgeSlide_IsClimbedAtWalkingSpeed()
    {
        // The human walker (two spheres r 0.48, step-up 0.6, step-down 1.5, EDGE_SLIDE) at 2 m/s (0.1 m per tick), rise 0.55.
        // The riser (x = 105) is hit with the foot sphere's centre at x = 104.6: the tread (z 0.55) is 0.07 above the centre,
        // contact radius sqrt((0.48 - 0.0002)^2 - 0.07^2) = 0.474 >= 0.4 to the edge, t = (0.07 + 0.48) / 0.6 = 0.917,
        // walk_interp 0.083 >= -0.5: lifted onto the tread's plane 0.4 m short of its edge. Next step (0.3 m short):
        // check_walkables' half sphere (r/2 = 0.24) is off the tread, so CTransition::check_walkable probes down: with two
        // spheres the 1.5 m step-down is only halved (1.5 > 2r → 0.75, acclient.c:312474), the probe's feet reach
        // 0.55 - 0.75 < 0 below the lower floor, ground is found and the step stands. 95 ticks walk 9.5 m: on the top tread
        // (x 109..110) at z = 20 + 5 * 0.55 = 22.75.
        PhysicsWorld world = Flight(0.55f);
        PhysicsObj obj = HumanWalker.Create(world, StartFacingEast());
        SweepScene.SetWalk(obj, new Vector3(0f, 2f, 0f));
        SweepScene.Run(world, 95);
        Vector3 o = obj.Position.Frame.Origin;
        Assert.True(o.X > 109f && o.X < 110f, $"stopped at {o}");
        Assert.Equal(BspScene.Ground + 5 * 0.55f, o.Z, 3);
        Assert.True((obj.TransientState & TransientState.OnWalkable) != 0);
    }

    [Theory]
    [InlineData(0.29f, true)]
    [InlineData(0.31f, false)]
    public void OneSphereWithEdgeSlide_ClimbsOnlyWhenThePrecipiceProbeReachesTheLowerFloor(float rise, bool climbs)
    {
        // Retail's precipice rule, not a port defect: one sphere r 0.5, step-up = step-down = 0.3, EDGE_SLIDE. The step up
        // lifts the sphere onto the first tread's plane 0.4 m short of its edge (riser hit at x = 104.6; the tread is reached
        // within the contact radius, reach 1.5 * 0.3 = 0.45 >= rise). On the next step (0.3 m short) check_walkables' half
        // sphere (0.25) is off the tread, and CTransition::check_walkable probes 0.3 m down (0.3 <= 2r, not shortened,
        // acclient.c:312474): the probe's feet go to rise - 0.3 above the floor. rise 0.29 → -0.01: the ground is touched,
        // the step stands and the walker climbs (the flight top at 5 * 0.29 = 1.45). rise 0.31 → +0.01: nothing below,
        // step_down fails, edge_slide finds the tread as the walkable and precipice_slide takes the movement off along its
        // edge's normal (-x): the walker stays at x = 104.6 on the tread's plane. It keeps Contact: validate_transition
        // (acclient.c:312193) restores the last known contact plane (the tread's) while the centre is within r + EPSILON of
        // it, which it is (exactly r above it).
        PhysicsWorld world = Flight(rise);
        PhysicsObj obj = SweepScene.Walker(world, StartFacingEast(), R, stepUp: 0.3f, stepDown: 0.3f);
        SweepScene.SetWalk(obj, new Vector3(0f, 2f, 0f));
        SweepScene.Run(world, 95);
        Vector3 o = obj.Position.Frame.Origin;
        if (climbs)
        {
            Assert.True(o.X > 109f && o.X < 110f, $"stopped at {o}");
            Assert.Equal(BspScene.Ground + 5 * rise, o.Z, 3);
        }
        else
        {
            Assert.Equal(104.6f, o.X, 3);
            Assert.Equal(BspScene.Ground + rise, o.Z, 3);
            Assert.True((obj.TransientState & TransientState.Contact) != 0);
        }
    }

    [Fact]
    public void OneSphereWithEdgeSlide_ALargeStepDownIsCutToHalfTheRadius_AndHoldsAtTheTreadEdge()
    {
        // One sphere r 0.5, step-up 0.4, step-down 1.5, EDGE_SLIDE, rise 0.31: CTransition::check_walkable cuts a step-down
        // above 2r (1.5 > 1) to r/2 = 0.25 for a single sphere (acclient.c:312474), so the probe's feet reach
        // 0.31 - 0.25 = 0.06 above the floor: nothing; the walker is held at x = 104.6 as above although its step-down is 1.5.
        PhysicsWorld world = Flight(0.31f);
        PhysicsObj obj = SweepScene.Walker(world, StartFacingEast(), R, stepUp: StepUp, stepDown: 1.5f);
        SweepScene.SetWalk(obj, new Vector3(0f, 2f, 0f));
        SweepScene.Run(world, 95);
        Assert.Equal(104.6f, obj.Position.Frame.Origin.X, 3);
        Assert.Equal(BspScene.Ground + 0.31f, obj.Position.Frame.Origin.Z, 3);
    }
}
