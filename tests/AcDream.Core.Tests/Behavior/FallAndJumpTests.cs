using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class FallAndJumpTests
{
    [Fact]
    public void RunningOffALedge_WithoutEdgeSlide_FallsAndLandsWithContactPlane()
    {
        // Plateau at 60 m for vx <= 4 (x <= 96); below it a cliff drops 50 m in one 24 m cell (N.z = 0.43, not walkable);
        // flat ground at 10 m from vx = 5 (x >= 120).
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (vx, _) => vx <= 4 ? 60 : 10);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 3, 4);
        // Default state minus EDGE_SLIDE: a creature that is allowed to walk off edges.
        PhysicsState state = (PhysicsState)PhysicsGlobals.DefaultState & ~PhysicsState.EdgeSlide;
        PhysicsObj obj = SweepScene.Walker(world, new Position(cell, Frame.FromHeading(new Vector3(94f, 108f, 60f), 90f)), state: state);
        SweepScene.SetWalk(obj, new Vector3(0f, 4f, 0f));

        bool fell = false;
        SweepScene.Run(world, 200, _ =>
        {
            if ((obj.TransientState & TransientState.Contact) == 0)
            {
                fell = true;
            }

            // Never below the ground under the origin.
            Assert.True(obj.Position.Frame.Origin.Z >= SweepScene.Ground(terrain, obj.Position) - 0.001f);
        });

        Assert.True(fell);
        // 200 ticks = 10 s: enough to fall 50 m (sqrt(2 * 50 / 9.8) = 3.2 s) and slide to the foot of the cliff. It ends on
        // the flat 10 m ground, standing with a walkable contact plane N = (0, 0, 1), d = -10.
        Vector3 o = obj.Position.Frame.Origin;
        Assert.Equal(10f, o.Z, 3);
        Assert.True(o.X >= 96f);
        Assert.True((obj.TransientState & (TransientState.Contact | TransientState.OnWalkable)) == (TransientState.Contact | TransientState.OnWalkable));
        Assert.Equal(new Vector3(0f, 0f, 1f), obj.ContactPlaneNormal);
        Assert.Equal(-10f, obj.ContactPlaneD);
    }

    [Fact]
    public void RunningToALedge_WithEdgeSlide_StopsAtTheEdge()
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (vx, _) => vx <= 4 ? 60 : 10);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 3, 4);
        PhysicsObj obj = SweepScene.Walker(world, new Position(cell, Frame.FromHeading(new Vector3(94f, 108f, 60f), 90f)));
        SweepScene.SetWalk(obj, new Vector3(0f, 4f, 0f));
        SweepScene.Run(world, 100, _ => Assert.True((obj.TransientState & TransientState.Contact) != 0));

        // The default state has EDGE_SLIDE: every step past the edge (x = 96) fails its step down onto the 0.43 cliff and is
        // cliff-slid back, so the walker never leaves the plateau.
        Assert.Equal(60f, obj.Position.Frame.Origin.Z);
        Assert.InRange(obj.Position.Frame.Origin.X, 95.5f, 96f);
    }

    [Fact]
    public void Jump_OnFlatGround_LandsOnTheHeightItLeft()
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4);
        PhysicsObj obj = SweepScene.Walker(world, new Position(cell, new Vector3(100f, 100f, 20f)));
        float z0 = obj.Position.Frame.Origin.Z;

        // A 5 m/s jump: v·N = 5 > EPSILON, so the next sweep starts without contact (check_contact). The first tick still
        // integrates with the acceleration of a walker in contact (zero: calc_acceleration runs only at the commit), so it
        // rises 5 * 0.05 = 0.25 m at full speed; from then on gravity: 5² / (2 * 9.8000002) = 1.27551 m more.
        // Peak 1.52551 m; sampled every 0.05 s the highest sample is at most 0.5 * 9.8 * 0.025² = 0.0031 m lower.
        obj.SetVelocity(new Vector3(0f, 0f, 5f));
        float peak = z0;
        bool left = false;
        SweepScene.Run(world, 60, _ =>
        {
            peak = Math.Max(peak, obj.Position.Frame.Origin.Z);
            left |= (obj.TransientState & TransientState.Contact) == 0;
            Assert.True(obj.Position.Frame.Origin.Z >= z0 - 0.001f);
        });

        Assert.True(left);
        Assert.InRange(peak - z0, 1.5224f, 1.5256f);
        // Landing: validate_walkable lifts the sphere's low point back onto z = 20 and the bounce (elasticity 0.05) leaves at most
        // 0.05 * 5 = 0.25 m/s, which the small-velocity rule (|v|² - 0.25² < EPSILON) zeroes.
        Assert.Equal(z0, obj.Position.Frame.Origin.Z, 4);
        Assert.True((obj.TransientState & (TransientState.Contact | TransientState.OnWalkable)) == (TransientState.Contact | TransientState.OnWalkable));
        Assert.Equal(Vector3.Zero, obj.Velocity);
    }
}
