using System;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// A client callback that throws propagates out of <see cref="PhysicsWorld.Tick"/> (documented). Afterwards the world ticks
/// on: no "inside a tick" refusal, the transition pool and the fade-hook pool are full again, the throwing one-shot anim hook
/// is gone, and every object is visited and moves at the next ticks. Covered: the environment collision listener, the player
/// listener, the step observer and an anim hook, with both visiting modes.
/// </summary>
public class ThrowingCallbackLeavesWorldTickableTests
{
    public enum Callback
    {
        CollisionListener,
        PlayerListener,
        StepObserver,
        AnimHook,
    }

    private sealed class ClientBug : Exception
    {
    }

    private sealed class Thrower : IStepObserver, ICollisionListener, IPlayerPhysicsListener
    {
        public Callback Kind { get; set; }

        public bool Armed { get; set; }

        public int[] Steps { get; } = new int[8];

        public void OnStep(PhysicsObj obj, float quantum, double physicsTime)
        {
            Steps[obj.Id]++;
            Fire(Callback.StepObserver, obj.Id == 2);
        }

        public void OnEnvironmentCollision(PhysicsObj obj, in EnvCollisionProfile profile) => Fire(Callback.CollisionListener, true);

        public void PlayerPhysicsUpdated(PhysicsObj player) => Fire(Callback.PlayerListener, true);

        public void Fire(Callback kind, bool here)
        {
            if (Armed && Kind == kind && here)
            {
                Armed = false;
                throw new ClientBug();
            }
        }
    }

    private sealed class ThrowingAnimHook(Thrower t) : IAnimHook
    {
        public int Runs { get; private set; }

        public void Execute(PhysicsObj obj)
        {
            Runs++;
            t.Fire(Callback.AnimHook, true);
        }
    }

    [Theory]
    [InlineData(Callback.CollisionListener, false)]
    [InlineData(Callback.CollisionListener, true)]
    [InlineData(Callback.PlayerListener, false)]
    [InlineData(Callback.PlayerListener, true)]
    [InlineData(Callback.StepObserver, false)]
    [InlineData(Callback.StepObserver, true)]
    [InlineData(Callback.AnimHook, false)]
    [InlineData(Callback.AnimHook, true)]
    public void AfterAThrowingCallback_TheWorldTicksOn_PoolsFull_EveryObjectMoves(Callback kind, bool visitEveryObject)
    {
        var terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20); // flat, z = 20
        var world = new PhysicsWorld(0.0) { VisitEveryObject = visitEveryObject };
        var sweep = new RetailSweep(terrain);
        world.Sweep = sweep;
        int hooks = world.FreeHookCount;
        var thrower = new Thrower { Kind = kind };
        world.StepObserver = thrower;
        world.PlayerListener = thrower;
        sweep.CollisionListener = thrower;
        // 1: the player, walking north; 2: a walker north too, fading its translucency (a pooled hook in flight);
        // 3: a faller 2 m up (beyond its 0.6 m step down), whose landing reports an environment collision.
        PhysicsObj player = ObjectScene.Creature(world, 1, ObjectScene.At(60f, 60f));
        PhysicsObj walker = ObjectScene.Creature(world, 2, ObjectScene.At(90f, 60f));
        PhysicsObj faller = ObjectScene.Creature(world, 3, ObjectScene.At(120f, 60f, ObjectScene.GroundZ + 2f));
        world.Player = player;
        SweepScene.SetWalk(player, new Vector3(0f, 2f, 0f));
        SweepScene.SetWalk(walker, new Vector3(0f, 2f, 0f));
        walker.SetTranslucency(0.5f, 0.4);
        Assert.Equal(hooks - 1, world.FreeHookCount);
        var hook = new ThrowingAnimHook(thrower);
        if (kind == Callback.AnimHook)
        {
            walker.AddAnimHook(hook);
        }

        thrower.Armed = true;
        bool thrown = false;
        for (int i = 0; i < 40 && !thrown; i++)
        {
            try
            {
                world.Tick(world.CurrentTime + SweepScene.Dt);
            }
            catch (ClientBug)
            {
                thrown = true;
            }
        }

        Assert.True(thrown);
        Assert.Equal(0, sweep.Pool.Level);
        Assert.Equal(0, world.StepScratchDepth);

        // The next ticks run: no "inside a tick" refusal; every object is stepped, the walkers move on.
        float playerY = player.Position.Frame.Origin.Y;
        float walkerY = walker.Position.Frame.Origin.Y;
        Array.Clear(thrower.Steps);
        SweepScene.Run(world, 20);
        Assert.True(thrower.Steps[1] >= 20 && thrower.Steps[2] >= 20, $"steps {thrower.Steps[1]}, {thrower.Steps[2]}");
        Assert.True(player.Position.Frame.Origin.Y > playerY + 1.5f);
        Assert.True(walker.Position.Frame.Origin.Y > walkerY + 1.5f);
        Assert.Equal(ObjectScene.GroundZ, faller.Position.Frame.Origin.Z, 3);
        // The fade ended and its hook went back: the pool is full. The one-shot anim hook ran once and is gone.
        Assert.Equal(0.5f, walker.Translucency);
        Assert.Equal(hooks, world.FreeHookCount);
        Assert.Equal(0, walker.PendingAnimHookCount);
        Assert.Equal(kind == Callback.AnimHook ? 1 : 0, hook.Runs);
        Assert.Equal(0, sweep.Pool.Level);
        Assert.Equal(0, world.StepScratchDepth);
    }
}
