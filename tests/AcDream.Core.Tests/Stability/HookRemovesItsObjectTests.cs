using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// A hook whose Execute removes its own object from the world (a client despawning a creature from its fade-out hook).
/// <c>RemoveObject</c> returns the object's pooled fades to the world's pool while <c>process_hooks</c> is still walking the
/// list; the walk must stop there, and the pool must never hold a hook twice (a free list pointing at itself would hand the same
/// <see cref="FPHook"/> to every later fade and cross-link the hook lists of different objects).
/// </summary>
public class HookRemovesItsObjectTests
{
    private const int Capacity = 64;

    private sealed class RemoveOwnerHook : PhysicsObjHook
    {
        private readonly bool _reportDone;

        public RemoveOwnerHook(bool reportDone) => _reportDone = reportDone;

        public int Runs { get; private set; }

        public override bool Execute(PhysicsObj obj)
        {
            Runs++;
            obj.World.RemoveObject(obj);
            return _reportDone;
        }
    }

    private sealed class RemoveOwnerAnimHook : IAnimHook
    {
        public void Execute(PhysicsObj obj) => obj.World.RemoveObject(obj);
    }

    private sealed class CountingAnimHook : IAnimHook
    {
        public int Runs { get; private set; }

        public void Execute(PhysicsObj obj) => Runs++;
    }

    private sealed class StepCounter : IStepObserver
    {
        public readonly int[] Steps = new int[8];

        public void OnStep(PhysicsObj obj, float quantum, double physicsTime) => Steps[obj.Id]++;
    }

    private static PhysicsObj Create(PhysicsWorld world, uint id) =>
        TickTestContext.CreateObject(world, new Vector3(2f + id, 10f, 0f), spheres: 0, id: id);

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void CompletingFade_ThenSelfRemovingHook_PoolHoldsEachHookOnce(bool hookReportsDone)
    {
        var world = new PhysicsWorld(0.0, hookPoolCapacity: Capacity);
        PhysicsObj obj = Create(world, 1);
        obj.SetTranslucency(0.5f, 0.01); // completes at the first step (0.05 s > 0.01 s): frac = 1
        var remover = new RemoveOwnerHook(hookReportsDone);
        obj.AddHook(remover);            // newest: runs first, then the fade would be next in the walk
        Assert.Equal(Capacity - 1, world.FreeHookCount);

        world.Tick(0.05);

        Assert.Equal(1, remover.Runs);
        Assert.Equal(0, world.ObjectCount);
        Assert.Null(obj.Hooks);
        Assert.Null(remover.Owner);
        // The fade went back once: 63 + 1 (before the fix: 65, the fade returned twice).
        Assert.Equal(Capacity, world.FreeHookCount);

        // Two later fades on two objects get two different hooks, each in its own object's list only.
        PhysicsObj a = Create(world, 2);
        PhysicsObj b = Create(world, 3);
        a.SetTranslucency(0.5f, 1.0);
        b.SetTranslucency(0.5f, 1.0);
        Assert.NotNull(a.Hooks);
        Assert.NotNull(b.Hooks);
        Assert.NotSame(a.Hooks, b.Hooks);
        Assert.Same(a, a.Hooks!.Owner);
        Assert.Same(b, b.Hooks!.Owner);
        Assert.Null(a.Hooks.Next);
        Assert.Null(b.Hooks.Next);
        Assert.Equal(Capacity - 2, world.FreeHookCount);
    }

    [Fact]
    public void SelfRemovingHook_BeforeAnOlderFade_FadeIsNotRunAfterRemoval()
    {
        var world = new PhysicsWorld(0.0, hookPoolCapacity: Capacity);
        PhysicsObj obj = Create(world, 1);
        obj.SetTranslucency(0.5f, 1.0); // 0.05 of 1 s: would set translucency 0.025 if it ran
        obj.AddHook(new RemoveOwnerHook(false));

        world.Tick(0.05);

        // The walk stopped at the removal: the fade (returned to the pool) never ran.
        Assert.Equal(0f, obj.Translucency);
        Assert.Equal(Capacity, world.FreeHookCount);
    }

    [Fact]
    public void PoolIgnoresAHookItAlreadyHolds()
    {
        var world = new PhysicsWorld(0.0, hookPoolCapacity: 2);
        FPHook h = world.RentFPHook(PhysicsHookType.Scale, 0.0, 1.0, 1f, 2f, 0);
        Assert.Equal(1, world.FreeHookCount);
        world.ReturnFPHook(h);
        world.ReturnFPHook(h);
        Assert.Equal(2, world.FreeHookCount);
        FPHook x = world.RentFPHook(PhysicsHookType.Scale, 0.0, 1.0, 1f, 2f, 0);
        FPHook y = world.RentFPHook(PhysicsHookType.Scale, 0.0, 1.0, 1f, 2f, 0);
        Assert.NotSame(x, y);
        Assert.Equal(0, world.FreeHookCount);
    }

    [Fact]
    public void AnimHookRemovingItsObject_LaterAnimHooksAreDropped_NoThrow()
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = Create(world, 1);
        var later = new CountingAnimHook();
        obj.AddAnimHook(new RemoveOwnerAnimHook());
        obj.AddAnimHook(later);

        world.Tick(0.05);

        Assert.Equal(0, world.ObjectCount);
        Assert.Equal(0, later.Runs);
        Assert.Equal(0, obj.PendingAnimHookCount);
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void HookRemovingItsObject_TheOtherObjectsAreStillVisitedOnce(bool visitEveryObject)
    {
        var world = new PhysicsWorld(0.0) { VisitEveryObject = visitEveryObject };
        var steps = new StepCounter();
        world.StepObserver = steps;
        PhysicsObj first = Create(world, 1);
        Create(world, 2);
        Create(world, 3);
        first.AddHook(new RemoveOwnerHook(false));
        for (uint id = 2; id <= 3; id++)
        {
            world.GetObjectById(id)!.SetVelocity(new Vector3(0f, 1f, 0f)); // awake: visited every tick
        }

        world.Tick(0.05);

        // One step of 0.05 s each (one tick, dt below MaxQuantum); object 1 stepped once and was removed in that step.
        Assert.Equal(new[] { 0, 1, 1, 1 }, steps.Steps[..4]);
        Assert.Equal(2, world.ObjectCount);
        Assert.Equal(2u, world.GetObject(0).Id);
        Assert.Equal(3u, world.GetObject(1).Id);
    }

    [Fact]
    public void FadeOnARemovedObject_IsRefused_AndRentsNoHook()
    {
        // A removed object is never ticked again: a pooled fade on it would never return to the pool (64 fades on removed
        // objects would empty it). A removed object refuses every mutator; the pool keeps all 64.
        var world = new PhysicsWorld();
        PhysicsObj obj = Create(world, 1);
        float before = obj.Translucency;
        world.RemoveObject(obj);
        Assert.Equal(Capacity, world.FreeHookCount);
        Assert.Throws<System.InvalidOperationException>(() => obj.SetTranslucency(0.75f, 2.0));
        Assert.Equal(before, obj.Translucency);
        Assert.Equal(Capacity, world.FreeHookCount);
    }
}
