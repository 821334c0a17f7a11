using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class BspWallTests
{
    private const float R = 0.5f;

    [Fact]
    public void WalkingIntoAWall_AtAShallowAngle_SlidesAlongItAtFullParallelSpeed_WithoutPenetrating()
    {
        WorldCells cells = BspScene.FlatWorld();
        // A wall 80 m long, 0.5 m thick, 3 m high, its south face at y = 110 (normal -y).
        BspScene.AddBoxes(cells, new Vector3(100f, 110f, BspScene.Ground), (new Vector3(-40f, 0f, 0f), new Vector3(40f, 0.5f, 3f)));
        PhysicsWorld world = BspScene.Physics(cells);
        // Heading 80 degrees: 10 degrees north of east. Forward speed 3 m/s = 0.15 m per 0.05 s tick:
        // along the wall (x) 0.15 * sin 80 = 0.14772 m, into it (y) 0.15 * cos 80 = 0.02605 m per tick.
        PhysicsObj obj = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(70f, 105f), Frame.FromHeading(new Vector3(70f, 105f, BspScene.Ground), 80f)), R);
        SweepScene.SetWalk(obj, new Vector3(0f, 3f, 0f));

        // The walker reaches the wall after (110 - 0.5 - 105) / 0.02605 = 173 ticks; then it must slide.
        float xAt200 = 0f;
        SweepScene.Run(world, 300, i =>
        {
            Vector3 c = BspScene.SphereCenter(obj, R);
            // Never closer to the wall plane than the radius (1 mm tolerance for float rounding).
            Assert.True(c.Y <= 110f - R + 0.001f, $"tick {i}: centre {c} penetrates the wall");
            Assert.Equal(BspScene.Ground, obj.Position.Frame.Origin.Z, 3);
            if (i == 199)
            {
                xAt200 = obj.Position.Frame.Origin.X;
            }
        });

        // Sliding keeps the whole parallel component: 100 ticks * 0.14772 = 14.772 m (1 % tolerance).
        float progress = obj.Position.Frame.Origin.X - xAt200;
        Assert.InRange(progress, 14.772f * 0.99f, 14.772f * 1.01f);
        // And it is against the wall: centre y = 110 - r = 109.5 (within 2 cm).
        Assert.InRange(BspScene.SphereCenter(obj, R).Y, 109.48f, 109.5f + 0.001f);
    }

    [Fact]
    public void WalkingIntoA90DegreeCorner_StopsWithoutJitter_AndNeverPenetrates()
    {
        WorldCells cells = BspScene.FlatWorld();
        // Walls meeting at (110, 110): one along x (south face y = 110), one along y (west face x = 110).
        BspScene.AddBoxes(cells, new Vector3(100f, 100f, BspScene.Ground),
            (new Vector3(-10f, 10f, 0f), new Vector3(10.5f, 10.5f, 3f)),
            (new Vector3(10f, -10f, 0f), new Vector3(10.5f, 10.5f, 3f)));
        PhysicsWorld world = BspScene.Physics(cells);
        // Heading 45 (north-east) at 3 m/s from (100, 100): reaches the corner after about 9.5 * sqrt 2 / 0.15 = 90 ticks.
        PhysicsObj obj = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(100f, 100f), Frame.FromHeading(new Vector3(100f, 100f, BspScene.Ground), 45f)), R);
        SweepScene.SetWalk(obj, new Vector3(0f, 3f, 0f));

        Vector3 min = new(float.MaxValue), max = new(float.MinValue);
        SweepScene.Run(world, 200, i =>
        {
            Vector3 c = BspScene.SphereCenter(obj, R);
            Assert.True(c.X <= 110f - R + 0.001f && c.Y <= 110f - R + 0.001f, $"tick {i}: centre {c} penetrates a wall");
            if (i >= 160)
            {
                min = Vector3.Min(min, obj.Position.Frame.Origin);
                max = Vector3.Max(max, obj.Position.Frame.Origin);
            }
        });

        // The last 40 ticks: still (no movement above 1 mm on any axis), in the corner. A step that can slide along
        // neither wall is refused whole (validate_transition returns to the current position), so the walker stops within
        // one step (0.15 m) of touching both walls: centre x, y in [109.5 - 0.15, 109.5].
        Vector3 spread = max - min;
        Assert.True(spread.X < 0.001f && spread.Y < 0.001f && spread.Z < 0.001f, $"jitter {spread}");
        Vector3 end = obj.Position.Frame.Origin;
        Assert.InRange(end.X, 109.35f, 109.5f + 0.001f);
        Assert.InRange(end.Y, 109.35f, 109.5f + 0.001f);
    }
}
