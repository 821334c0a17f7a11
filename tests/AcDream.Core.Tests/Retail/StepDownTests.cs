using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class StepDownTests
{
    // Flat ground at 20 m; a one-sphere object (r = 0.5, step heights 0.6) whose check position floats 0.3 m above it,
    // as after a step off a small ledge.
    private static Transition Floating(ObjectInfoState state)
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out RetailSweep sweep);
        PhysicsObj obj = world.CreateObject(1);
        obj.PartArray = new SimplePartArray(1, 0) { StepUpHeight = 0.6f, StepDownHeight = 0.6f };
        Transition t = sweep.Pool.Make()!;
        t.InitObject(obj, state);
        t.InitSphere(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) }, 1f);
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4);
        var p = new Position(cell, new Vector3(100f, 100f, 20.3f));
        t.InitPath(terrain.GetLandCell(cell), p, p);
        t.SpherePath.SetCheckPos(p, terrain.GetLandCell(cell));
        return t;
    }

    [Fact]
    public void Walking_StepsDownByStepDownHeight_OntoGround0Point3Below()
    {
        // ON_WALKABLE: step_down_height 0.6 (2r = 1 >= 0.6: one attempt). The sphere sinks 0.3 into the ground and
        // validate_walkable lifts it back: walk_interp = (1 - (-1 / 0.6) * -0.3) = 0.5, accepted. It lands on z = 20.
        Transition t = Floating(ObjectInfoState.Contact | ObjectInfoState.OnWalkable);
        Assert.Equal(TransitionState.Ok, t.TransitionalInsert(3));
        Assert.True(t.CollisionInfo.ContactPlaneValid);
        Assert.Equal(20f, t.SpherePath.CheckPos.Frame.Origin.Z, 4);
    }

    [Fact]
    public void NotWalking_StepsDownOnly0Point04_AndLeavesTheGround()
    {
        // In contact but not on walkable ground: the step down is 0.04 m (landing allowance 0.0871557); the ground 0.3 m
        // below is out of reach, and without ON_WALKABLE the edge slide lets it go: OK, no contact, still at 20.3.
        Transition t = Floating(ObjectInfoState.Contact);
        Assert.Equal(TransitionState.Ok, t.TransitionalInsert(3));
        Assert.False(t.CollisionInfo.ContactPlaneValid);
        Assert.Equal(20.3f, t.SpherePath.CheckPos.Frame.Origin.Z);
    }

    [Fact]
    public void NotInContact_DoesNotStepDown()
    {
        // Without CONTACT (falling) there is no step down at all.
        Transition t = Floating(ObjectInfoState.None);
        Assert.Equal(TransitionState.Ok, t.TransitionalInsert(3));
        Assert.False(t.CollisionInfo.ContactPlaneValid);
        Assert.Equal(20.3f, t.SpherePath.CheckPos.Frame.Origin.Z);
    }
}
