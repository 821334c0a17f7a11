using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// Where a walking human stops at a wall (what <c>docs/getting-started.md</c> describes for the sample's hut): not at
/// contact, but where its last collision-free step ended. A step that would take the feet sphere into the wall slides along
/// it from where the previous step ended, so the sphere's centre stays between its radius and its radius plus one step's
/// approach from the wall, and keeps that distance while it slides.
/// </summary>
public sealed class WallStopDistanceTests(ITestOutputHelper output)
{
    private const float WallY = 110f;

    [Theory]
    [InlineData(3.12f, 25.5f, 60)]   // the sample: walk NNE into the hut's south wall, 60 fps (a step every 1/30 s)
    [InlineData(3.12f, 25.5f, 15)]   // the same walk at 15 fps: a step every 1/15 s
    [InlineData(6.02f, 25.5f, 30)]   // running (4 m/s x the sample's run rate 1.505)
    [InlineData(6.02f, 0f, 15)]      // running head-on at 15 fps: stops, no slide
    public void AHuman_StopsWithinOneStepOfTheWall_AndKeepsThatDistanceWhileSliding(float speed, float heading, int fps)
    {
        // A wall 80 m long, its south face at y = 110 (normal -y); the human from (100, 105) walks towards it.
        WorldCells cells = BspScene.FlatWorld();
        BspScene.AddBoxes(cells, new Vector3(100f, WallY, BspScene.Ground), (new Vector3(-40f, 0f, 0f), new Vector3(40f, 0.5f, 3f)));
        PhysicsWorld world = BspScene.Physics(cells);
        PhysicsObj human = HumanWalker.Create(world, new Position(BspScene.OutdoorCell(100f, 105f),
            Frame.FromHeading(new Vector3(100f, 105f, BspScene.Ground), heading)));
        ((SimplePartArray)human.PartArray!).SequenceVelocity = new Vector3(0f, speed, 0f);
        float radius = HumanWalker.Radius;

        // A step lasts at least 1/30 s (the world gate) and less than 1/30 s + one frame (a frame that ends a hair short of
        // the gate waits for the next one): its approach to the wall is at most speed x cos(heading) x (1/30 + 1/fps).
        float approachBound = (float)(speed * Math.Cos(heading * Math.PI / 180.0) * (1.0 / 30.0 + 1.0 / fps));
        double now = 0;
        float closest = float.MaxValue, lastDistance = WallY - human.Position.Frame.Origin.Y, spread = 0f, largestApproach = 0f;
        int frames = 4 * fps;   // 4 s: the wall is reached after about 1.6 s at the slowest approach
        for (int f = 1; f <= frames; f++)
        {
            world.Tick(now += 1.0 / fps);
            float d = WallY - human.Position.Frame.Origin.Y;
            largestApproach = MathF.Max(largestApproach, lastDistance - d);
            closest = MathF.Min(closest, d);
            if (f > frames / 2)
            {
                spread = MathF.Max(spread, MathF.Abs(d - lastDistance));
            }

            lastDistance = d;
        }

        output.WriteLine($"{speed} m/s, heading {heading}, {fps} fps: stopped {lastDistance:F4} m from the wall (radius {radius}, "
            + $"largest step approach {largestApproach:F4}, bound {approachBound:F4})");
        Assert.True(closest >= radius - 0.001f, $"the feet sphere entered the wall: {closest}");
        Assert.True(largestApproach <= approachBound + 0.0001f, $"a step approached the wall by {largestApproach} m");
        Assert.InRange(lastDistance, radius - 0.001f, radius + largestApproach);
        Assert.True(spread < 0.001f, $"the distance changed by {spread} m while sliding");
        if (heading != 0f)
        {
            Assert.True(human.Position.Frame.Origin.X > 105f, "it slid along the wall");
        }
    }
}
