using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class FlatGroundTests
{
    // Flat landblock: every vertex at index 20 of the one-metre table, so the ground is the plane z = 20 (N = (0,0,1),
    // d = -20) in every cell, both triangles.
    private static (TerrainWorld Terrain, PhysicsWorld World) FlatScene(out RetailSweep sweep)
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        return (terrain, SweepScene.Physics(terrain, out sweep));
    }

    [Fact]
    public void EnterWorld_OnFlatGround_StandsOnThePlaneWithContactAndWalkable()
    {
        var (_, world) = FlatScene(out _);
        // Requested at z = 20: the sphere (centre 0.5 above the origin, r = 0.5) touches the plane exactly; the placement's
        // step down of 0.6 m sinks it to 19.4 and validate_walkable lifts it by -(19.9 - 0.5 - 20)/1 = 0.6 again: z = 20.
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4);
        PhysicsObj obj = SweepScene.Walker(world, new Position(cell, new Vector3(100f, 100f, 20f)));

        Assert.Equal(20f, obj.Position.Frame.Origin.Z);
        Assert.Equal(cell, obj.Position.ObjCellId);
        Assert.True((obj.TransientState & TransientState.Contact) != 0);
        Assert.True((obj.TransientState & TransientState.OnWalkable) != 0);
        Assert.Equal(new Vector3(0f, 0f, 1f), obj.ContactPlaneNormal);
        Assert.Equal(-20f, obj.ContactPlaneD);
    }

    [Fact]
    public void EnterWorld_AboveFlatGround_WithinStepDown_LandsOnIt()
    {
        var (_, world) = FlatScene(out _);
        // 0.3 m above the ground: the placement's step down (0.6 m, one attempt since 2r = 1 >= 0.6) finds the plane.
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4);
        PhysicsObj obj = SweepScene.Walker(world, new Position(cell, new Vector3(100f, 100f, 20.3f)));

        Assert.Equal(20f, obj.Position.Frame.Origin.Z, 5);
        Assert.True((obj.TransientState & TransientState.Contact) != 0);
    }

    [Fact]
    public void Walking_InCircles_10000Ticks_KeepsContactAndExactHeight()
    {
        var (_, world) = FlatScene(out _);
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4);
        PhysicsObj obj = SweepScene.Walker(world, new Position(cell, new Vector3(100f, 96f, 20f)));
        // Walk at 3.12 m/s (retail's walk speed) turning at 0.5 rad/s: a circle of radius 3.12 / 0.5 = 6.24 m, so the
        // walker stays inside the landblock. The rotation is about z only, so the root motion never has a z component
        // (M13 = M23 = 0 exactly) and the contact plane (N = +z) leaves the step unchanged: the height must stay exactly 20.
        SweepScene.SetWalk(obj, new Vector3(0f, 3.12f, 0f));
        ((SimplePartArray)obj.PartArray!).SequenceOmega = new Vector3(0f, 0f, 0.5f);
        float minX = float.MaxValue, maxX = float.MinValue;
        SweepScene.Run(world, 10000, _ =>
        {
            Vector3 o = obj.Position.Frame.Origin;
            Assert.Equal(20f, o.Z);
            Assert.True((obj.TransientState & (TransientState.Contact | TransientState.OnWalkable)) == (TransientState.Contact | TransientState.OnWalkable));
            minX = Math.Min(minX, o.X);
            maxX = Math.Max(maxX, o.X);
        });

        // It really walked: the circle's diameter is 2 * 6.24 = 12.48 m (each 0.05 s step is a 0.156 m chord).
        Assert.InRange(maxX - minX, 12.0f, 12.6f);
    }

    [Fact]
    public void Walking_Straight_AcrossCellEdges_ChangesCellIdsAndKeepsHeight()
    {
        var (_, world) = FlatScene(out _);
        uint start = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 0, 4);
        // Facing east (heading 90): local +Y becomes +X. 3 m/s * 0.05 s = 0.15 m per tick; 300 ticks = 45 m: from x = 12
        // (cell column 0) to x = 57 (column 2, since 48 <= 57 < 72).
        PhysicsObj obj = SweepScene.Walker(world, new Position(start, Frame.FromHeading(new Vector3(12f, 108f, 20f), 90f)));
        SweepScene.SetWalk(obj, new Vector3(0f, 3f, 0f));
        SweepScene.Run(world, 300);

        Assert.Equal(57f, obj.Position.Frame.Origin.X, 2);
        Assert.Equal(108f, obj.Position.Frame.Origin.Y, 3);
        Assert.Equal(20f, obj.Position.Frame.Origin.Z);
        Assert.Equal(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 2, 4), obj.Position.ObjCellId);
    }
}
