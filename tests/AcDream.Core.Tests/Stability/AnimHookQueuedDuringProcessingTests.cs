using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// An animation hook queued while <c>process_hooks</c> runs the anim hooks waits for the next step. Retail re-reads the
/// growing count (acclient.c:318640), so a hook that re-queues itself ("run again next frame") never let the step return;
/// the port runs the hooks queued before the pass and keeps the others (docs/divergences.md, "Anim hooks queued during the
/// pass").
/// </summary>
public class AnimHookQueuedDuringProcessingTests
{
    private sealed class RequeueingHook : IAnimHook
    {
        public int Runs { get; private set; }

        public void Execute(PhysicsObj obj)
        {
            Runs++;
            obj.AddAnimHook(this);
        }
    }

    private sealed class QueueOtherHook : IAnimHook
    {
        private readonly IAnimHook _other;

        public QueueOtherHook(IAnimHook other) => _other = other;

        public void Execute(PhysicsObj obj) => obj.AddAnimHook(_other);
    }

    private sealed class CountingHook : IAnimHook
    {
        public int Runs { get; private set; }

        public void Execute(PhysicsObj obj) => Runs++;
    }

    private sealed class StepCounter : IStepObserver
    {
        public int Steps { get; private set; }

        public void OnStep(PhysicsObj obj, float quantum, double physicsTime) => Steps++;
    }

    [Fact]
    public void SelfRequeueingHook_RunsExactlyOncePerStep()
    {
        var world = new PhysicsWorld(0.0);
        var steps = new StepCounter();
        world.StepObserver = steps;
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f), spheres: 0);
        var hook = new RequeueingHook();
        obj.AddAnimHook(hook);

        // Ten ticks of 0.05 s: one step each (0.05 s is below MaxQuantum, above MinQuantum).
        for (int k = 1; k <= 10; k++)
        {
            world.Tick(k * 0.05);
            Assert.Equal(k, steps.Steps);
            Assert.Equal(k, hook.Runs);
            Assert.Equal(1, obj.PendingAnimHookCount);
        }

        // A 0.5 s tick is cut into 0.2 + 0.2 + 0.1 s: three steps, three runs.
        world.Tick(1.0);
        Assert.Equal(13, steps.Steps);
        Assert.Equal(13, hook.Runs);
    }

    [Fact]
    public void HookQueuedByAnotherHook_RunsAtTheNextStep_InQueueOrder()
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f), spheres: 0);
        var later = new CountingHook();
        var before = new CountingHook();
        obj.AddAnimHook(new QueueOtherHook(later));
        obj.AddAnimHook(before);

        world.Tick(0.05);
        Assert.Equal(1, before.Runs);
        Assert.Equal(0, later.Runs);
        Assert.Equal(1, obj.PendingAnimHookCount);

        world.Tick(0.10);
        Assert.Equal(1, before.Runs);
        Assert.Equal(1, later.Runs);
        Assert.Equal(0, obj.PendingAnimHookCount);
    }
}
