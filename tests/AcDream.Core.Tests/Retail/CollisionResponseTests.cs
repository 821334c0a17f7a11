using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class CollisionResponseTests
{
    private sealed class NoCells : ICellSource
    {
        public ObjCell? GetVisible(uint cellId) => null;
    }

    private sealed class Recorder : ICollisionListener
    {
        public int Count;
        public EnvCollisionProfile Last;

        public void OnEnvironmentCollision(PhysicsObj obj, in EnvCollisionProfile profile)
        {
            Count++;
            Last = profile;
        }
    }

    private static (RetailSweep Sweep, PhysicsObj Obj) Scene()
    {
        var world = new PhysicsWorld(0.0);
        var sweep = new RetailSweep(new NoCells());
        world.Sweep = sweep;
        return (sweep, world.CreateObject(1));
    }

    [Fact]
    public void HandleAllCollisions_Landing_BouncesByElasticity()
    {
        var (sweep, obj) = Scene();
        obj.SetVelocity(new Vector3(0f, 0f, -5f));
        var ci = new CollisionInfo();
        ci.SetCollisionNormal(new Vector3(0f, 0f, 1f));
        // v·n = -5 < 0: v += -(v·n)(1 + 0.05) n = (0, 0, -5 + 5.25) = (0, 0, 0.25).
        obj.HandleAllCollisions(sweep, ci, false, false);
        Assert.Equal(0.25f, obj.Velocity.Z, 6);
    }

    [Fact]
    public void HandleAllCollisions_Inelastic_Stops()
    {
        var (sweep, obj) = Scene();
        obj.SetState(obj.State | PhysicsState.Inelastic);
        obj.SetVelocity(new Vector3(3f, 0f, -5f));
        var ci = new CollisionInfo();
        ci.SetCollisionNormal(new Vector3(0f, 0f, 1f));
        obj.HandleAllCollisions(sweep, ci, false, false);
        Assert.Equal(Vector3.Zero, obj.Velocity);
    }

    [Theory]
    // frames_stationary_fall: 0 clears the three bits, 1 sets STATIONARY_FALL, 2 STATIONARY_STOP (and stops the object),
    // 3 stops it and clears the bits (retail jumps straight to the clear, acclient.c:321807).
    [InlineData(0, TransientState.None, false)]
    [InlineData(1, TransientState.StationaryFall, false)]
    [InlineData(2, TransientState.StationaryStop, true)]
    [InlineData(3, TransientState.None, true)]
    public void HandleAllCollisions_StationaryFrames_SetTheStationaryBits(int frames, TransientState expected, bool stopped)
    {
        var (sweep, obj) = Scene();
        obj.SetVelocity(new Vector3(1f, 0f, 0f));
        var ci = new CollisionInfo { FramesStationaryFall = frames };
        obj.HandleAllCollisions(sweep, ci, false, false);
        const TransientState bits = TransientState.StationaryFall | TransientState.StationaryStop | TransientState.StationaryStuck;
        Assert.Equal(expected, obj.TransientState & bits);
        Assert.Equal(stopped ? Vector3.Zero : new Vector3(1f, 0f, 0f), obj.Velocity);
    }

    [Fact]
    public void ValidateTransition_ThreeBlockedFrames_StandTheFallerOnAMadeUpPlane()
    {
        var (sweep, obj) = Scene();
        Assert.True((obj.State & PhysicsState.Gravity) != 0);
        Transition t = sweep.Pool.Make()!;
        t.InitObject(obj, ObjectInfoState.None);
        t.InitSphere(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) }, 1f);
        var p = new Position(0x80800001, new Vector3(10f, 10f, 30f));
        t.InitPath(null, p, p);
        t.SpherePath.SetCheckPos(p, null);
        // Each blocked step (no progress): 0 -> 1 -> 2 -> 3; on the third the contact plane N = (0,0,1),
        // d = r - ((c.y + c.x) * 0 + c.z) = 0.5 - 30.5 = -30 is made up under the sphere, and (not in contact) the
        // collision normal and the environment collision are recorded.
        Assert.Equal(TransitionState.Ok, t.ValidateTransition(TransitionState.Collided));
        Assert.Equal(1, t.CollisionInfo.FramesStationaryFall);
        t.ValidateTransition(TransitionState.Collided);
        Assert.Equal(2, t.CollisionInfo.FramesStationaryFall);
        Assert.False(t.CollisionInfo.ContactPlaneValid);
        t.ValidateTransition(TransitionState.Collided);
        Assert.Equal(3, t.CollisionInfo.FramesStationaryFall);
        Assert.True(t.CollisionInfo.ContactPlaneValid);
        Assert.Equal(new CollisionPlane(new Vector3(0f, 0f, 1f), -30f), t.CollisionInfo.ContactPlane);
        Assert.True(t.CollisionInfo.CollidedWithEnvironment);
        Assert.True((t.ObjectInfo.State & ObjectInfoState.OnWalkable) != 0);
    }

    [Fact]
    public void ValidateTransition_ProgressResetsTheStationaryCounter()
    {
        var (sweep, obj) = Scene();
        Transition t = sweep.Pool.Make()!;
        t.InitObject(obj, ObjectInfoState.None);
        t.InitSphere(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) }, 1f);
        var p = new Position(0x80800001, new Vector3(10f, 10f, 30f));
        t.InitPath(null, p, p);
        t.SpherePath.SetCheckPos(p, null);
        t.ValidateTransition(TransitionState.Collided);
        Assert.Equal(1, t.CollisionInfo.FramesStationaryFall);
        // An OK step that moved (check differs from curr): redo -> 0.
        t.SpherePath.AddOffsetToCheckPos(new Vector3(0f, 0f, -0.1f));
        t.ValidateTransition(TransitionState.Ok);
        Assert.Equal(0, t.CollisionInfo.FramesStationaryFall);
        Assert.Equal(29.9f, t.SpherePath.CurrPos.Frame.Origin.Z, 5);
    }

    [Fact]
    public void JumpLanding_ReportsEachLandingOnce()
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out RetailSweep sweep);
        var recorder = new Recorder();
        sweep.CollisionListener = recorder;
        PhysicsObj obj = SweepScene.Walker(world, new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4), new Vector3(100f, 100f, 20f)));
        int placed = recorder.Count;
        // Jump and land: a landing sweep (not in contact) records an environment collision; REPORT_COLLISIONS is in the
        // default state, so the listener hears it, with the downward velocity and "not in contact before". The jump peaks
        // 1.5255 m up (FallAndJumpTests), so it lands at sqrt(2 * 9.8 * 1.5255) = 5.47 m/s; the bounce, 0.05 * 5.47 =
        // 0.273 m/s, is above the 0.25 m/s stop, so it hops 0.273² / 19.6 = 3.8 mm and lands again, slower; its
        // bounce is stopped: two landings, two reports (the hop in between ends the environment collision).
        obj.SetVelocity(new Vector3(0f, 0f, 5f));
        SweepScene.Run(world, 60);
        Assert.Equal(placed + 2, recorder.Count);
        Assert.False(recorder.Last.MeInContact);
        Assert.True(recorder.Last.Velocity.Z < 0f);
        // Standing still afterwards, the tick never sweeps (the new position equals the old), so nothing ends the
        // environment collision: it stays open until a sweep without one.
        Assert.True(obj.CollidingWithEnvironment);
    }
}
