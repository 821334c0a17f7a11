using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using System.Reflection;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// An object removed from its world is not a zombie: it reports no cell and no contact, walkable or active bit, and every
/// public mutator refuses it with an <see cref="InvalidOperationException"/> naming the removal (before anything changes);
/// its reads stay allowed. The same when it is removed from inside a callback of its own step.
/// </summary>
public sealed class RemovedObjectRefusesMutatorsTests
{
    private const int Bx = 0x80;
    private const int By = 0x80;

    // Members of PhysicsObj that only read (allowed on a removed object).
    private static readonly HashSet<string> Reads = new(StringComparer.Ordinal)
    {
        "GetRenderPose", "GetUpdateTime", "IsMovingTo",
    };

    // No member is left out: the movement members (GetOrCreateMotionInterpreter, MakeMovementManager, the Movement setter)
    // are mutators too.
    private static readonly HashSet<string> MotionMembers = new(StringComparer.Ordinal);

    // Flat landblock 0x8080 at index 10 of the one-metre table: the ground is the plane z = 10.
    private static TerrainWorld Flat() => SyntheticTerrain.FlatBlock(Bx, By, 10);

    private static (PhysicsWorld World, PhysicsObj Obj, Position Spawn) Grounded()
    {
        TerrainWorld terrain = Flat();
        var world = new PhysicsWorld(terrain);
        PhysicsObj obj = world.CreateObject(1);
        obj.PartArray = new SimplePartArray(SetupPhysics.Human, 1);
        obj.Movement = new AcDream.Core.Physics.Objects.Seams.BasicMovementManager();
        Position spawn = SyntheticTerrain.OnGround(terrain, SyntheticTerrain.CellId(Bx, By, 4, 4), 100f, 100f);
        Assert.True(obj.EnterWorld(spawn));
        world.Tick(0.05);
        TransientState grounded = TransientState.Contact | TransientState.OnWalkable | TransientState.Active;
        Assert.Equal(grounded, obj.TransientState & grounded);
        return (world, obj, spawn);
    }

    private static void AssertNotAZombie(PhysicsObj obj)
    {
        Assert.Equal(0u, obj.CellId);
        Assert.Equal((TransientState)0, obj.TransientState & (TransientState.Contact | TransientState.OnWalkable | TransientState.Active));
        Assert.False(obj.IsActive);
    }

    [Fact]
    public void RemovedObject_ReportsNoCellNoContact_AndEnterWorldIsRefused()
    {
        (PhysicsWorld world, PhysicsObj obj, Position spawn) = Grounded();
        Position last = obj.Position;

        world.RemoveObject(obj);

        AssertNotAZombie(obj);
        Assert.Equal(last, obj.Position); // the last position stays readable
        var e = Assert.Throws<InvalidOperationException>(() => obj.EnterWorld(spawn));
        Assert.Contains("removed from its world", e.Message, StringComparison.Ordinal);
        AssertNotAZombie(obj);
        Assert.Equal(0, world.ObjectCount);
    }

    [Fact]
    public void EveryPublicMutator_OfARemovedObject_Throws_AndChangesNothing()
    {
        (PhysicsWorld world, PhysicsObj obj, _) = Grounded();
        PhysicsObj other = world.CreateObject(2);
        world.RemoveObject(obj);
        string before = Snapshot(obj);

        var called = new List<string>();
        foreach (MethodInfo m in typeof(PhysicsObj).GetMethods(BindingFlags.Public | BindingFlags.Instance))
        {
            if (m.DeclaringType != typeof(PhysicsObj) || (m.IsSpecialName && m.Name.StartsWith("get_", StringComparison.Ordinal))
                || m.Name is "ToString" || Reads.Contains(m.Name) || MotionMembers.Contains(m.Name))
            {
                continue;
            }

            object?[] args = m.GetParameters().Select(p => Argument(p, other)).ToArray();
            Exception? thrown = null;
            try
            {
                m.Invoke(obj, args);
            }
            catch (TargetInvocationException e)
            {
                thrown = e.InnerException;
            }

            Assert.True(thrown is InvalidOperationException, m.Name + " threw " + (thrown?.ToString() ?? "nothing"));
            Assert.Contains("removed from its world", thrown!.Message, StringComparison.Ordinal);
            Assert.Equal(before, Snapshot(obj));
            called.Add(m.Name);
        }

        // The catalogue found the mutators named in issue #23, and reads still work.
        Assert.Contains("EnterWorld", called);
        Assert.Contains("SetPosition", called);
        Assert.Contains("SetVelocity", called);
        Assert.Contains("SetParent", called);
        Assert.Contains("set_PartArray", called);
        Assert.Contains("AddAnimHook", called);
        Assert.True(called.Count >= 40, "only " + called.Count + " mutators found");
        Assert.False(obj.IsInterpolating);
        Assert.Equal(0u, obj.StickyObjectId);
        Assert.Equal(100.0, obj.AutonomyBlipDistance);
    }

    private static object? Argument(ParameterInfo p, PhysicsObj other)
    {
        Type t = p.ParameterType.IsByRef ? p.ParameterType.GetElementType()! : p.ParameterType;
        if (t == typeof(PhysicsObj))
        {
            return other;
        }

        if (t == typeof(Position))
        {
            return new Position(TickTestContext.OutdoorCell, new Vector3(10f, 10f, 0f));
        }

        if (t == typeof(Frame))
        {
            return Frame.Identity;
        }

        if (t == typeof(float))
        {
            return 1f;
        }

        if (t == typeof(double))
        {
            return 0.5;
        }

        if (t == typeof(IAnimHook))
        {
            return new NoHook();
        }

        return t.IsValueType ? Activator.CreateInstance(t) : null;
    }

    private static string Snapshot(PhysicsObj o) =>
        string.Join("|", o.CellId, o.Position, o.TransientState, o.State, o.Velocity, o.Omega, o.Acceleration, o.Scale,
            o.Translucency, o.Friction, o.Elasticity, o.PartArray?.GetType().Name, o.Parent?.Id, o.Hooks is null,
            o.PendingAnimHookCount, o.PositionManager is null, o.Weenie is null, o.LastMoveWasAutonomous);

    private sealed class NoHook : IAnimHook
    {
        public void Execute(PhysicsObj obj)
        {
        }
    }

    private sealed class RemoveOwnerAnimHook : IAnimHook
    {
        public void Execute(PhysicsObj obj) => obj.World.RemoveObject(obj);
    }

    [Fact]
    public void RemovedFromItsOwnAnimHook_ReportsNoCellNoContact_AndRefusesMutators()
    {
        (PhysicsWorld world, PhysicsObj obj, Position spawn) = Grounded();
        obj.AddAnimHook(new RemoveOwnerAnimHook());

        world.Tick(0.10);

        AssertNotAZombie(obj);
        Assert.Throws<InvalidOperationException>(() => obj.SetVelocity(Vector3.UnitX));
        Assert.Throws<InvalidOperationException>(() => obj.EnterWorld(spawn));
        world.Tick(0.15);
        AssertNotAZombie(obj);
    }

    private sealed class RemoveOnEnvironmentCollision : ICollisionListener
    {
        public void OnEnvironmentCollision(PhysicsObj obj, in EnvCollisionProfile profile) => obj.World.RemoveObject(obj);
    }

    [Fact]
    public void RemovedFromItsCollisionListener_WhileFalling_ReportsNoCellNoContact()
    {
        // Dropped 3 m onto flat ground (beyond the human's 1.5 m step down): the landing reports an environment collision
        // (report_environment_collision on !prevOnWalkable && onWalkable), whose listener removes the object in the middle of
        // its commit; its managers do not run on it afterwards.
        TerrainWorld terrain = Flat();
        var world = new PhysicsWorld(terrain);
        PhysicsObj obj = world.CreateObject(1);
        obj.PartArray = new SimplePartArray(SetupPhysics.Human, 1);
        obj.Movement = new AcDream.Core.Physics.Objects.Seams.BasicMovementManager();
        Position spawn = SyntheticTerrain.OnGround(terrain, SyntheticTerrain.CellId(Bx, By, 4, 4), 100f, 100f);
        spawn.Frame.Origin += new Vector3(0f, 0f, 3f);
        Assert.True(obj.EnterWorld(spawn));
        ((RetailSweep)world.Sweep).CollisionListener = new RemoveOnEnvironmentCollision();

        for (int k = 1; k <= 40 && world.ObjectCount == 1; k++)
        {
            world.Tick(k * 0.05);
        }

        Assert.Equal(0, world.ObjectCount);
        AssertNotAZombie(obj);
        Assert.Throws<InvalidOperationException>(() => obj.SetPositionSimple(spawn, false));
    }
}
