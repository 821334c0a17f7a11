using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class BspFallAndMissileTests
{
    private const float R = 0.5f;

    // A 4 x 4 x 1 m box on the ground, x 100..104, y 98..102, top at z = 21.
    private static readonly Vector3 BoxMin = new(100f, 98f, BspScene.Ground);
    private static readonly Vector3 BoxMax = new(104f, 102f, BspScene.Ground + 1f);

    [Theory]
    // Centre x relative to the box's west edge (x = 100): well on it, just on it, on the edge, just off, off by most of r.
    [InlineData(0.6f)]
    [InlineData(0.1f)]
    [InlineData(0f)]
    [InlineData(-0.1f)]
    [InlineData(-0.4f)]
    public void FallingOntoTheEdgeOfABox_EndsOnItOrOnTheGround_NeverInside(float offset)
    {
        WorldCells cells = BspScene.FlatWorld();
        BspScene.AddBoxes(cells, Vector3.Zero, (BoxMin, BoxMax));
        PhysicsWorld world = BspScene.Physics(cells);
        // Dropped from 3 m above the box top (origin z = 24): placement in free air, then gravity.
        var start = new Vector3(100f + offset, 100f, BspScene.Ground + 4f);
        PhysicsObj obj = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(start.X, start.Y), start), R);

        SweepScene.Run(world, 100, i =>
        {
            float d = BspScene.DistanceToBox(BspScene.SphereCenter(obj, R), BoxMin, BoxMax);
            Assert.True(d >= R - 0.002f, $"offset {offset}, tick {i}: centre {BspScene.SphereCenter(obj, R)} is {d} from the box");
        });

        // After 5 s it rests (contact) either on the top (origin z = 21) or on the ground beside the box (z = 20).
        Vector3 o = obj.Position.Frame.Origin;
        Assert.True((obj.TransientState & TransientState.Contact) != 0, $"offset {offset}: no contact at {o}");
        bool onTop = MathF.Abs(o.Z - (BspScene.Ground + 1f)) < 0.002f;
        bool onGround = MathF.Abs(o.Z - BspScene.Ground) < 0.002f;
        Assert.True(onTop || onGround, $"offset {offset}: resting at {o}");
        if (offset >= 0.1f)
        {
            // The centre is over the top: it must land on it.
            Assert.True(onTop, $"offset {offset}: expected on top, at {o}");
        }
    }

    [Fact]
    public void Missile_At50MetresPerSecond_NeverPassesThroughA10CentimetreWall()
    {
        WorldCells cells = BspScene.FlatWorld();
        // Wall x 110..110.1 (0.1 m thick), y 90..110, z 20..25.
        BspScene.AddBoxes(cells, new Vector3(110f, 100f, BspScene.Ground), (new Vector3(0f, -10f, 0f), new Vector3(0.1f, 10f, 5f)));
        PhysicsWorld world = BspScene.Physics(cells);
        PhysicsState missile = (PhysicsState)PhysicsGlobals.DefaultState | PhysicsState.Missile;
        missile &= ~PhysicsState.Gravity;
        const float r = 0.1f;
        PhysicsObj obj = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(100f, 100f), new Vector3(100f, 100f, BspScene.Ground + 2f)), r, state: missile);
        // 50 m/s = 2.5 m per 0.05 s tick, 25 sweep steps of 0.1 m (the radius) per tick.
        obj.SetVelocity(new Vector3(50f, 0f, 0f));

        float maxX = float.MinValue;
        SweepScene.Run(world, 20, i =>
        {
            float cx = BspScene.SphereCenter(obj, r).X;
            maxX = MathF.Max(maxX, cx);
            Assert.True(cx <= 110f - r + 0.002f, $"tick {i}: missile centre x {cx} passed the wall face");
        });

        // It reached the wall (within one 0.1 m sweep step of touching it, x >= 110 - 0.1 - 0.1) and bounced:
        // v' = v - (1 + elasticity) (v.n) n with elasticity 0.05 and n = -x: 50 - 1.05 * 50 = -2.5 m/s.
        Assert.True(maxX >= 110f - r - 0.1f - 0.002f, $"reached only {maxX}");
        Assert.Equal(-2.5f, obj.Velocity.X, 3);
    }
}
