using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// <see cref="PhysicsWorld.RemoveObject"/> called from any callback inside a tick — the step observer, the environment and
/// object collision listeners, the player listener — for the object being updated or another one: nothing throws, the removed
/// object's step ends there and its shadow leaves every cell for good (no ghost for others to collide with), and every other
/// object is still visited exactly once. (Hooks: <see cref="HookRemovesItsObjectTests"/>.)
/// </summary>
public class RemovalFromCallbacksTests
{
    private const float Speed = 2f; // m/s: 0.1 m per 0.05 s tick

    private sealed class Remover : IStepObserver, ICollisionListener, IObjectCollisionListener, IPlayerPhysicsListener
    {
        private readonly PhysicsWorld _world;

        public Remover(PhysicsWorld world) => _world = world;

        public uint RemoveOnStepOf { get; set; }

        public uint StepVictim { get; set; }

        public uint RemoveOnEnvCollision { get; set; }

        public uint RemoveOnObjectCollisionOf { get; set; }

        public uint ObjectCollisionVictim { get; set; }

        public uint PlayerVictim { get; set; }

        public int[] Steps { get; } = new int[16];

        public int ObjectCollisions { get; private set; }

        public void OnStep(PhysicsObj obj, float quantum, double physicsTime)
        {
            Steps[obj.Id]++;
            if (obj.Id == RemoveOnStepOf)
            {
                RemoveOnStepOf = 0;
                Remove(StepVictim);
            }
        }

        public void OnEnvironmentCollision(PhysicsObj obj, in EnvCollisionProfile profile)
        {
            if (obj.Id == RemoveOnEnvCollision)
            {
                RemoveOnEnvCollision = 0;
                Remove(obj.Id);
            }
        }

        public void OnObjectCollision(PhysicsObj obj, in ObjCollisionProfile profile)
        {
            ObjectCollisions++;
            if (obj.Id == RemoveOnObjectCollisionOf)
            {
                RemoveOnObjectCollisionOf = 0;
                Remove(ObjectCollisionVictim);
            }
        }

        public void OnAttackCollision(PhysicsObj obj, in AtkCollisionProfile profile)
        {
        }

        public void OnObjectCollisionEnd(PhysicsObj obj, uint otherId)
        {
        }

        public void PlayerPhysicsUpdated(PhysicsObj player)
        {
            if (PlayerVictim != 0)
            {
                Remove(PlayerVictim);
                PlayerVictim = 0;
            }
        }

        private void Remove(uint id)
        {
            PhysicsObj? o = _world.GetObjectById(id);
            if (o is not null)
            {
                _world.RemoveObject(o);
            }
        }
    }

    private static PhysicsWorld Scene(bool visitEveryObject, out RetailSweep sweep, out Remover remover)
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20); // flat, z = 20
        var world = new PhysicsWorld(0.0) { VisitEveryObject = visitEveryObject };
        sweep = new RetailSweep(terrain);
        world.Sweep = sweep;
        remover = new Remover(world);
        world.StepObserver = remover;
        world.PlayerListener = remover;
        sweep.CollisionListener = remover;
        sweep.ObjectCollisionListener = remover;
        return world;
    }

    // True when any cell of landblock 0x8080 lists a shadow of obj.
    private static bool AnyCellLists(RetailSweep sweep, PhysicsObj obj)
    {
        for (int cx = 0; cx < 8; cx++)
        {
            for (int cy = 0; cy < 8; cy++)
            {
                ObjCell? cell = sweep.Cells.GetVisible(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, cx, cy));
                if (cell is not null && ObjectScene.CellLists(cell, obj))
                {
                    return true;
                }
            }
        }

        return false;
    }

    private static PhysicsObj Walker(PhysicsWorld world, uint id, float x)
    {
        PhysicsObj o = ObjectScene.Creature(world, id, ObjectScene.At(x, 100f, heading: 90f)); // facing east (+x)
        SweepScene.SetWalk(o, new Vector3(0f, Speed, 0f));
        return o;
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void StepObserver_RemovesTheSteppingObject_NoGhost_AnotherWalksThroughWhereItWas(bool visitEveryObject)
    {
        PhysicsWorld world = Scene(visitEveryObject, out RetailSweep sweep, out Remover remover);
        // B (id 1) 3 m behind A (id 2), both walking east at 2 m/s. A is removed at the start of its first step.
        PhysicsObj b = Walker(world, 1, 97f);
        PhysicsObj a = Walker(world, 2, 100f);
        remover.RemoveOnStepOf = 2;
        remover.StepVictim = 2;

        SweepScene.Run(world, 1);

        Assert.Equal(1, world.ObjectCount);
        Assert.Equal(0, a.NumShadowObjects);
        Assert.False(AnyCellLists(sweep, a));
        // A was not moved by the rest of its step: it stays where it entered.
        Assert.Equal(100f, a.Position.Frame.Origin.X);

        // 40 more ticks: B walks 4.1 m in all, through x = 100 where A stood (a ghost there would stop it at 99 - EPSILON).
        SweepScene.Run(world, 40);
        Assert.Equal(0, remover.ObjectCollisions);
        Assert.Equal(97f + 41 * 0.1f, b.Position.Frame.Origin.X, 3);
        Assert.Equal(41, remover.Steps[1]);
        Assert.Equal(1, remover.Steps[2]);
    }

    [Theory]
    [InlineData(1u, 2u, false)]
    [InlineData(2u, 1u, false)]
    [InlineData(1u, 2u, true)]
    [InlineData(2u, 1u, true)]
    public void StepObserver_RemovesAnotherObject_EveryOtherIsVisitedOnce(uint stepping, uint victim, bool visitEveryObject)
    {
        PhysicsWorld world = Scene(visitEveryObject, out RetailSweep sweep, out Remover remover);
        PhysicsObj one = Walker(world, 1, 90f);
        PhysicsObj two = Walker(world, 2, 100f);
        PhysicsObj three = Walker(world, 3, 110f);
        remover.RemoveOnStepOf = stepping;
        remover.StepVictim = victim;

        SweepScene.Run(world, 1);

        PhysicsObj removed = victim == 1 ? one : two;
        Assert.False(AnyCellLists(sweep, removed));
        Assert.Equal(2, world.ObjectCount);
        // The stepping object and object 3 stepped once. The victim stepped once when it comes first (removed later, by
        // object 2's step), not at all when it comes after the remover.
        Assert.Equal(1, remover.Steps[stepping]);
        Assert.Equal(1, remover.Steps[3]);
        Assert.Equal(victim < stepping ? 1 : 0, remover.Steps[victim]);
        Assert.Equal(110f + 0.1f, three.Position.Frame.Origin.X, 4);
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void EnvironmentCollisionListener_RemovesTheLandingObject_NoGhost(bool visitEveryObject)
    {
        PhysicsWorld world = Scene(visitEveryObject, out RetailSweep sweep, out Remover remover);
        // Enters 2 m above the ground (beyond its 0.6 m step down): it falls and the landing is reported (report_environment
        // _collision on !prevOnWalkable && onWalkable).
        PhysicsObj faller = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f, 22f));
        remover.RemoveOnEnvCollision = 1;

        SweepScene.Run(world, 40);

        Assert.Equal(0, world.ObjectCount);
        Assert.False(AnyCellLists(sweep, faller));
        Assert.Equal(0, faller.NumShadowObjects);
    }

    [Theory]
    [InlineData(1u, false)] // the mover removes itself on touching the obstacle
    [InlineData(2u, false)] // the mover removes the obstacle
    [InlineData(1u, true)]
    [InlineData(2u, true)]
    public void ObjectCollisionListener_RemovesAnObject_NoGhost(uint victim, bool visitEveryObject)
    {
        PhysicsWorld world = Scene(visitEveryObject, out RetailSweep sweep, out Remover remover);
        PhysicsObj mover = Walker(world, 1, 97f);
        PhysicsObj obstacle = ObjectScene.Obstacle(world, 2, ObjectScene.At(100f, 100f),
            spheres: new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) });
        remover.RemoveOnObjectCollisionOf = 1;
        remover.ObjectCollisionVictim = victim;

        SweepScene.Run(world, 60);

        PhysicsObj removed = victim == 1 ? mover : obstacle;
        Assert.Equal(1, world.ObjectCount);
        Assert.False(AnyCellLists(sweep, removed));
        Assert.Equal(0, removed.NumShadowObjects);
        if (victim == 2)
        {
            // A walker crossing where the obstacle stood (north along x = 100.3, 0.3 m from the obstacle's centre, 1.3 m from
            // the mover's) passes: 40 ticks × 0.1 m from y = 97 to y = 101, with no further collision reported.
            int reported = remover.ObjectCollisions;
            PhysicsObj crosser = ObjectScene.Creature(world, 3, ObjectScene.At(100.3f, 97f, heading: 0f));
            SweepScene.SetWalk(crosser, new Vector3(0f, Speed, 0f));
            SweepScene.Run(world, 40);
            Assert.Equal(101f, crosser.Position.Frame.Origin.Y, 3);
            Assert.Equal(reported, remover.ObjectCollisions);
        }
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void PlayerListener_RemovesThePlayer_ThenAnotherObject(bool visitEveryObject)
    {
        PhysicsWorld world = Scene(visitEveryObject, out RetailSweep sweep, out Remover remover);
        PhysicsObj one = Walker(world, 1, 90f);
        PhysicsObj player = Walker(world, 2, 100f);
        PhysicsObj three = Walker(world, 3, 110f);
        world.Player = player;
        remover.PlayerVictim = 2;

        SweepScene.Run(world, 1);
        Assert.Null(world.Player);
        Assert.False(AnyCellLists(sweep, player));
        Assert.Equal(1, remover.Steps[3]);

        world.Player = three;
        remover.PlayerVictim = 1; // already visited this tick
        SweepScene.Run(world, 1);
        Assert.False(AnyCellLists(sweep, one));
        Assert.Equal(1, world.ObjectCount);
        Assert.Equal(2, remover.Steps[3]);
        Assert.Equal(110f + 0.2f, three.Position.Frame.Origin.X, 4);
    }

    private sealed class Creator : IStepObserver
    {
        private readonly PhysicsWorld _world;

        public Creator(PhysicsWorld world) => _world = world;

        public int[] Steps { get; } = new int[16];

        public void OnStep(PhysicsObj obj, float quantum, double physicsTime)
        {
            Steps[obj.Id]++;
            if (obj.Id == 5 && _world.GetObjectById(1) is null)
            {
                // Ids 1 (before every object) and 9 (after): created while object 5 steps.
                TickTestContext.CreateObject(_world, new Vector3(3f, 3f, 0f), id: 1);
                TickTestContext.CreateObject(_world, new Vector3(4f, 3f, 0f), id: 9);
            }
        }
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void ObjectsCreatedFromACallback_EveryObjectIsVisitedOnce(bool visitEveryObject)
    {
        var world = new PhysicsWorld(0.0) { VisitEveryObject = visitEveryObject };
        var creator = new Creator(world);
        for (uint id = 3; id <= 7; id += 2)
        {
            TickTestContext.CreateObject(world, new Vector3(2f + id, 10f, 0f), id: id).SetVelocity(new Vector3(0f, 1f, 0f));
        }

        world.StepObserver = creator;
        world.Tick(0.05);

        // 3, 5, 7 step once each. 1 (ordered before the object in progress) waits for the next tick; 9 (after it) is visited
        // in this one, as an object woken mid-tick is, but takes no step: it entered the world at this tick's time (dt = 0).
        // Four visits: 3, 5, 7, 9 (object 5 is not visited a second time although 1 was inserted before it).
        Assert.Equal(new[] { 0, 0, 0, 1, 0, 1, 0, 1, 0, 0 }, creator.Steps[..10]);
        Assert.Equal(4, world.LastTickVisitCount);
        world.Tick(0.10);
        Assert.Equal(new[] { 0, 1, 0, 2, 0, 2, 0, 2, 0, 1 }, creator.Steps[..10]);
        Assert.Equal(5, world.LastTickVisitCount);
    }

    private sealed class RemoveThenWake : IStepObserver
    {
        private readonly PhysicsWorld _world;

        public RemoveThenWake(PhysicsWorld world) => _world = world;

        public bool Armed { get; set; }

        public void OnStep(PhysicsObj obj, float quantum, double physicsTime)
        {
            if (Armed && obj.Id == 2)
            {
                Armed = false;
                _world.RemoveObject(obj);
                // Object 1 comes before 2: this tick has already passed it (visited, or dormant with its visit evaluated).
                _world.GetObjectById(1)!.SetVelocity(new Vector3(1f, 0f, 0f));
            }
        }
    }

    [Fact]
    public void RemovingTheObjectInProgress_ThenWakingAnEarlierOne_MatchesVisitingEveryObject()
    {
        (double UpdateTime, Vector3 Origin) Run(bool visitEveryObject, out int dormantBefore)
        {
            // On flat ground (no movement manager): the resting object goes inactive, then dormant.
            var world = new PhysicsWorld(0.0) { VisitEveryObject = visitEveryObject, Sweep = new FlatGroundSweep() };
            PhysicsObj rest = TickTestContext.CreateObject(world, new Vector3(5f, 10f, 0f), id: 1);
            PhysicsObj mover = TickTestContext.CreateObject(world, new Vector3(8f, 10f, 0f), id: 2);
            mover.SetVelocity(new Vector3(0f, 1f, 0f));
            var observer = new RemoveThenWake(world);
            world.StepObserver = observer;
            for (int k = 1; k <= 10; k++)
            {
                world.Tick(k * 0.05);
            }

            dormantBefore = world.DormantCount;
            observer.Armed = true;
            world.Tick(0.55);
            world.Tick(0.60);
            return (rest.UpdateTime, rest.Position.Frame.Origin);
        }

        var retail = Run(true, out _);
        var scene = Run(false, out int dormant);

        Assert.Equal(1, dormant); // object 1 was dormant when it was woken
        // Woken at 0.55 after its place in the order: it steps at 0.60 only, one 0.05 s step, as when every object is visited.
        Assert.Equal(retail.UpdateTime, scene.UpdateTime);
        Assert.Equal(retail.Origin, scene.Origin);
        Assert.True(scene.Origin.X > 5f);
    }
}
