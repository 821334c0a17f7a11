using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

// Issue #25 item 2, the wall stop gap: a walker heading straight into a wall stops where its last collision-free step
// ended, and the gap is never closed. Retail path (head-on, on the ground): BSPTREE::find_collisions (acclient.c:361295)
// sees the sphere hit the face and asks BSPTREE::step_sphere_up (361071); the step up fails (the wall is higher than the
// reach), so SPHEREPATH::step_up_slide (313455) slides with CSphere::slide_sphere (358898): the movement projected onto
// the face's direction (normal x contact plane normal) is shorter than sqrt(0.0002) head-on, so it returns COLLIDED (2)
// without moving the sphere. CTransition::transitional_insert (312833) returns that, and validate_transition (312193)
// puts the check position back to curr_pos, the end of the last step that collided with nothing (312222); the remaining
// steps of find_transitional_position (313170) collide the same way. Nothing moves the sphere up to the face: the gap is
// the distance at the end of the last free step, in [r, r + one step), where a step is the tick's movement cut by
// calc_num_steps (311763) into ceil(d / r) equal parts, and a tick is at least MinQuantum (CPhysics::UseTime, 311334).
public class WallStopGapTests
{
    private const float R = 0.48f;     // the human's feet sphere
    private const float Face = 60f;    // the wall's south face, y = 60

    // A closed box building (one-sided quads via BspBuilder, a PhysicsPart in a BuildingObj on the land cells it covers),
    // x 90..110, y 60..64, 3 m high; a one-sphere walker (r 0.48, centre 0.48 up) at (100, 48) heading north.
    private static (PhysicsWorld World, PhysicsObj Walker) Scene(float speed)
    {
        WorldCells cells = BspScene.FlatWorld();
        BspScene.AddBoxes(cells, new Vector3(100f, Face, BspScene.Ground), (new Vector3(-10f, 0f, 0f), new Vector3(10f, 4f, 3f)));
        PhysicsWorld world = BspScene.Physics(cells);
        var at = new Position(BspScene.OutdoorCell(100f, 48f), Frame.FromHeading(new Vector3(100f, 48f, BspScene.Ground), 0f));
        PhysicsObj w = SweepScene.Walker(world, at, R);
        SweepScene.SetWalk(w, new Vector3(0f, speed, 0f));
        return (world, w);
    }

    [Theory]
    // 0.05 s ticks, each one step d = 0.05 v (one step while d <= r). The walker at gap g = 12 - k d after k ticks moves
    // while the next step ends at least r from the face (12 - (k + 1) d >= 0.48) and stops for good at the first k that fails:
    // walk 3.12: d 0.156, k 73 -> 12 - 11.388 = 0.612; run 4.00: d 0.2, k 57 -> 0.6; run 9.5: d 0.475, k 24 -> 0.6.
    // Run 11.33: d 0.5665 > r, so each tick is 2 steps of 0.28325: k 20 -> 0.67, and the next tick's first step would end
    // at 0.38675 < r: 0.67.
    [InlineData(3.12f, 0.612f)]
    [InlineData(4.00f, 0.600f)]
    [InlineData(9.50f, 0.600f)]
    [InlineData(11.33f, 0.670f)]
    public void HeadOnIntoAWall_StopsAtTheEndOfTheLastFreeStep_AndNeverClosesTheGap(float speed, float gap)
    {
        var (world, w) = Scene(speed);
        SweepScene.Run(world, 150);   // at 3.12 m/s the wall is reached after 74 ticks
        float stopped = Face - w.Position.Frame.Origin.Y;
        Assert.Equal(gap, stopped, 3);
        // Pressing on for two more seconds changes nothing.
        SweepScene.Run(world, 40, _ => Assert.Equal(stopped, Face - w.Position.Frame.Origin.Y));
        Assert.Equal(BspScene.Ground, w.Position.Frame.Origin.Z);
    }

    [Fact]
    public void TheGap_AtAnyFrameRateAndSpeed_IsAtLeastTheRadius_AndLessThanRadiusPlusOneStep()
    {
        // The table (30, 60, 144 fps; walk 3.12, runs 4.00 to 11.33): the gap depends on where the steps fall, but
        // it is always >= r (1 mm float tolerance) and < r + the step length of the largest tick the walker took, and it
        // stays. (At 60 and 144 fps a tick below MinQuantum moves nothing, so the steps are 2 or 3 and 5 frames long.)
        foreach (int fps in new[] { 30, 60, 144 })
        {
            foreach (float speed in new[] { 3.12f, 4f, 6.02f, 7.67f, 9.5f, 11.33f })
            {
                var (world, w) = Scene(speed);
                float maxTick = 0f;
                double t = 0.0;
                for (int i = 0; i < fps * 6; i++)
                {
                    float before = w.Position.Frame.Origin.Y;
                    t += 1.0 / fps;
                    world.Tick(t);
                    maxTick = MathF.Max(maxTick, w.Position.Frame.Origin.Y - before);
                }

                float g = Face - w.Position.Frame.Origin.Y;
                float step = maxTick / MathF.Ceiling(maxTick / R);
                Assert.True(g >= R - 0.001f && g < R + step + 0.0001f, $"{fps} fps, {speed} m/s: gap {g}, step {step}");
                for (int i = 0; i < fps; i++)
                {
                    t += 1.0 / fps;
                    world.Tick(t);
                }

                Assert.Equal(g, Face - w.Position.Frame.Origin.Y);
            }
        }
    }
}
