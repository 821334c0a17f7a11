using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class BspTransformTests
{
    private const float R = 0.5f;

    [Fact]
    public void RotatedAndScaledBuilding_WallSlideHappensInItsLocalSpace_WithoutPenetrating()
    {
        WorldCells cells = BspScene.FlatWorld();
        // Part-space wall x -5..5, y 0..0.25, z 0..1.5, scale 2 (so 20 m long, 0.5 m thick, 3 m high), turned to heading 30:
        // its long side runs along heading 120 and its near face (part y = 0) faces heading 210.
        var shell = new List<Polygon>();
        var min = new Vector3(-5f, 0f, 0f);
        var max = new Vector3(5f, 0.25f, 1.5f);
        BspScene.AddBox(shell, min, max);
        Frame frame = Frame.FromHeading(new Vector3(100f, 100f, BspScene.Ground), 30f);
        BspScene.AddBuilding(cells, frame, 2f, shell);
        PhysicsWorld world = BspScene.Physics(cells);

        // Start 3 m in front of the face's middle (part (0, -1.5) scaled by 2), walking at heading 100: 20 degrees off the
        // wall's direction (120), towards it. 3 m/s = 0.15 m per tick: 0.15 sin 20 = 0.0513 m per tick towards the wall.
        Vector3 start = frame.LocalToGlobal(new Vector3(0f, -3f, 0f));
        PhysicsObj obj = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(start.X, start.Y), Frame.FromHeading(start, 100f)), R);
        SweepScene.SetWalk(obj, new Vector3(0f, 3f, 0f));

        float minGap = float.MaxValue;
        SweepScene.Run(world, 100, i =>
        {
            // Distance from the centre to the wall, measured in part space and scaled back to metres.
            Vector3 local = frame.GlobalToLocal(BspScene.SphereCenter(obj, R)) / 2f;
            float gap = BspScene.DistanceToBox(local, min, max) * 2f;
            minGap = MathF.Min(minGap, gap);
            Assert.True(gap >= R - 0.002f, $"tick {i}: {gap} m from the wall");
        });

        // It reached the wall (after (3 - 0.5) / 0.0513 = 49 ticks): a slide starts from the last free position, which is
        // within one step's approach (0.0513 m) of touching, and keeps that gap. Then every tick keeps the along-wall
        // part of the step, 0.15 cos 20 = 0.141 m (1 %).
        Assert.True(minGap < R + 0.0513f + 0.002f, $"never reached the wall (closest {minGap})");
        Vector3 before = obj.Position.Frame.Origin;
        SweepScene.Run(world, 1);
        Vector3 d = obj.Position.Frame.Origin - before;
        Vector3 along = frame.LocalToGlobalVec(new Vector3(1f, 0f, 0f));
        float alongStep = d.X * along.X + d.Y * along.Y;
        Assert.InRange(alongStep, 0.141f * 0.99f, 0.141f * 1.01f);
    }
}
