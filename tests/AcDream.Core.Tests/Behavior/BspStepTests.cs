using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Math;
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
        // Facing east (heading 90) at 2 m/s: 0.1 m per tick. Default state minus EDGE_SLIDE (see docs/bsp-and-indoor.md,
        // "Step up and EDGE_SLIDE": a walker lifted onto a tread while its centre is still short of the tread's edge by more
        // than r/2 is held there by the edge slide).
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

    [Fact(Skip = "Open question (docs/bsp-and-indoor.md, 'Step up and EDGE_SLIDE'): with EDGE_SLIDE a walker lifted onto the "
        + "first tread while its centre is 0.4 m short of the tread's edge is held there, because check_walkable needs the "
        + "centre within r/2 of the edge. Kept as a repro until retail's lost compares are settled.")]
    public void Repro_Staircase_WithEdgeSlide_IsClimbedAtWalkingSpeed()
    {
        WorldCells cells = BspScene.FlatWorld();
        var boxes = new (Vector3, Vector3)[5];
        for (int i = 0; i < 5; i++)
        {
            boxes[i] = (new Vector3(i, -1.5f, 0f), new Vector3(i + 1, 1.5f, (i + 1) * 0.55f));
        }

        BspScene.AddBoxes(cells, new Vector3(105f, 100f, BspScene.Ground), boxes);
        PhysicsWorld world = BspScene.Physics(cells);
        PhysicsObj obj = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(100f, 100f), Frame.FromHeading(new Vector3(100f, 100f, BspScene.Ground), 90f)),
            R, stepUp: StepUp, stepDown: StepUp);
        SweepScene.SetWalk(obj, new Vector3(0f, 2f, 0f));
        SweepScene.Run(world, 95);
        Assert.Equal(BspScene.Ground + 5 * 0.55f, obj.Position.Frame.Origin.Z, 3);
    }
}
