using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Scene;

/// <summary>The world tick (CPhysics::UseTime, acclient.c:311334): outer gate, clock handling, isolation, allocation.</summary>
public class WorldTickTests
{
    [Fact]
    public void WorldTicks_OnlyOnceAThirtiethOfASecondHasPassed()
    {
        var world = new PhysicsWorld(10.0);
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 100f));
        var steps = new StepRecorder();
        world.StepObserver = steps;

        Assert.False(world.Tick(10.0 + 1.0 / 60.0)); // 0.0167 < 1/30: the objects are not updated
        Assert.Equal(0, steps.Count);
        Assert.Equal(10.0, world.LastUpdate);

        Assert.True(world.Tick(10.04)); // 0.04 >= 1/30
        Assert.Equal(1, steps.Count);
        Assert.Equal((float)(10.04 - 10.0), steps.Quantum(0));
        Assert.Equal(10.04, world.LastUpdate);
        Assert.Equal(10.04, obj.UpdateTime);
    }

    [Fact]
    public void ClockGoingBackwards_Resyncs_WithoutUpdating()
    {
        var world = new PhysicsWorld(10.0);
        Assert.False(world.Tick(5.0));
        Assert.Equal(5.0, world.LastUpdate);
        Assert.True(world.Tick(5.05));
    }

    [Fact]
    public void BadTimes_AreRejected_StateUnchanged()
    {
        var world = new PhysicsWorld(1.0);
        Assert.Throws<ArgumentException>(() => world.Tick(double.NaN));
        Assert.Throws<ArgumentException>(() => world.SetCurrentTime(double.PositiveInfinity));
        Assert.Throws<ArgumentException>(() => new PhysicsWorld(double.NaN));
        Assert.Equal(1.0, world.CurrentTime);
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(1f, 1f, 1f));
        Assert.Throws<ArgumentException>(() => obj.SetVelocity(new Vector3(float.NaN, 0f, 0f)));
        Assert.Equal(Vector3.Zero, obj.Velocity);
        Assert.Throws<ArgumentOutOfRangeException>(() => obj.Friction = 1.5f);
        Assert.Throws<ArgumentException>(() => obj.SetTranslucency(float.NaN, 1.0));
        var other = new PhysicsWorld();
        Assert.Throws<ArgumentException>(() => other.Player = obj);
    }

    [Fact]
    public void TwoWorlds_TickSideBySide_WithoutTouchingEachOther()
    {
        var a = new PhysicsWorld(0.0);
        var b = new PhysicsWorld(0.0, PhysicsProfile.AceCompatible);
        PhysicsObj oa = TickTestContext.CreateObject(a, new Vector3(10f, 10f, 100f));
        PhysicsObj ob = TickTestContext.CreateObject(b, new Vector3(10f, 10f, 100f));
        a.Player = oa;
        for (int n = 1; n <= 10; n++)
        {
            Assert.True(a.Tick(n * 0.0625));
        }

        Assert.Equal(0.625, a.CurrentTime);
        Assert.Equal(0.0, b.CurrentTime);
        Assert.Equal(0.0, b.PhysicsTime);
        Assert.Null(b.Player);
        Assert.Equal(100f, ob.Position.Frame.Origin.Z);
        Assert.True(oa.Position.Frame.Origin.Z < 99f);
    }

    [Fact]
    public void SetFrameInternal_NaNQuaternionWithFiniteOrigin_BecomesZeroQuaternion()
    {
        var world = new PhysicsWorld();
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(1f, 2f, 3f));
        Frame bad = Frame.Identity;
        bad.Origin = new Vector3(4f, 5f, 6f);
        bad.SetQuaternionRaw(float.NaN, 0f, 0f, 0f);
        obj.SetFrameInternal(bad);
        // IsValid fails and IsValidExceptForHeading holds: retail zeroes the quaternion (acclient.c:321327). The engine's own
        // steps keep that repair.
        Assert.Equal(new Vector3(4f, 5f, 6f), obj.Position.Frame.Origin);
        Assert.Equal(0f, obj.Position.Frame.Qw);
        Assert.Equal(0f, obj.Position.Frame.Qz);
    }

    [Fact]
    public void SetFrame_NaNQuaternionWithFiniteOrigin_IsRefused_StateUnchanged()
    {
        // non-retail (docs/divergences.md, "Value domains"): the public SetFrame refuses the NaN quaternion instead of storing
        // the retail repair's all-zero rotation.
        var world = new PhysicsWorld();
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(1f, 2f, 3f));
        Position before = obj.Position;
        Frame bad = Frame.Identity;
        bad.Origin = new Vector3(4f, 5f, 6f);
        bad.SetQuaternionRaw(float.NaN, 0f, 0f, 0f);
        Assert.Throws<ArgumentException>(() => obj.SetFrame(bad));
        Assert.Equal(before, obj.Position);
        Assert.Equal(1f, obj.Position.Frame.Qw);
    }

    [Fact]
    public void RemovedObject_IsNoLongerTicked_AndItsHooksReturnToThePool()
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 100f), id: 42);
        int free = world.FreeHookCount;
        obj.SetTranslucency2(0f, 1f, 10.0);
        Assert.Same(obj, world.GetObjectById(42));
        world.RemoveObject(obj);
        Assert.Equal(0, world.ObjectCount);
        Assert.Null(world.GetObjectById(42));
        Assert.Equal(free, world.FreeHookCount);
        Assert.True(world.Tick(0.0625));
        Assert.Equal(100f, obj.Position.Frame.Origin.Z);
    }

    [Fact]
    public void SteadyStateTick_AllocatesNothing()
    {
        var world = new PhysicsWorld(0.0);
        for (int i = 0; i < 50; i++)
        {
            PhysicsObj o = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 1000f));
            o.SetOmega(new Vector3(0f, 0f, 1f));
            o.SetVelocity(new Vector3(1f, 0f, 0f));
            o.MakePositionManager();
        }

        world.Player = world.GetObject(0);
        world.StepObserver = new StepRecorder();
        double t = 0;
        for (int i = 0; i < 10; i++)
        {
            world.Tick(t += 0.0625); // warm-up (JIT)
        }

        ((StepRecorder)world.StepObserver).Clear();
        world.GetObject(1).SetTranslucency2(0f, 1f, 0.5); // pooled hook: no allocation either
        AllocationProbe.AssertSteadyStateAllocatesNothing(() =>
        {
            for (int i = 0; i < 30; i++)
            {
                world.Tick(t += (i % 3 == 0) ? 0.45 : 0.0625); // includes three-step stalls
            }
        });
    }
}
