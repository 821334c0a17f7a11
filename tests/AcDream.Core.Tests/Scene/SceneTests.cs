using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Scene;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Scene;

/// <summary>Scenes pay only for what they use: dormant objects are skipped with results identical to visiting every object.</summary>
public class SceneTests
{
    [Fact]
    public void MixedScene_SkippingDormantObjects_IsBitIdenticalToVisitingEveryObject()
    {
        var full = new PhysicsWorld(1000.0) { VisitEveryObject = true };
        var scene = new PhysicsWorld(1000.0);
        var fullHashes = new ulong[261];
        var visits = new int[261];
        SceneTestContext.RunMixedScene(full, (tick, w) => fullHashes[tick] = SceneTestContext.HashWorld(w));
        int mismatch = -1;
        SceneTestContext.RunMixedScene(scene, (tick, w) =>
        {
            visits[tick] = w.LastTickVisitCount;
            if (mismatch < 0 && SceneTestContext.HashWorld(w) != fullHashes[tick])
            {
                mismatch = tick;
            }
        });
        Assert.True(mismatch < 0, $"first differing tick: {mismatch}");
        // The scene really skipped objects: 181 objects; once the movers have stopped, only a handful are visited.
        Assert.True(visits[35] < 40, $"visited {visits[35]} at tick 35");
        Assert.True(scene.DormantCount > 100);
    }

    [Fact]
    public void MixedScene_PerObjectStateMatches_AfterEveryTick()
    {
        // The same comparison object by object, so that a failure names the object.
        var full = new PhysicsWorld(5.0) { VisitEveryObject = true };
        var scene = new PhysicsWorld(5.0);
        var snapshots = new System.Collections.Generic.Dictionary<(int, uint), ulong>();
        SceneTestContext.RunMixedScene(full, (tick, w) =>
        {
            for (int i = 0; i < w.ObjectCount; i++)
            {
                PhysicsObj o = w.GetObject(i);
                snapshots[(tick, o.Id)] = SceneTestContext.Hash(o);
            }
        }, ticks: 200);
        SceneTestContext.RunMixedScene(scene, (tick, w) =>
        {
            for (int i = 0; i < w.ObjectCount; i++)
            {
                PhysicsObj o = w.GetObject(i);
                Assert.True(snapshots[(tick, o.Id)] == SceneTestContext.Hash(o),
                    $"tick {tick}, object {o.Id}: dormant={o.IsDormant} active={o.IsActive} t={o.UpdateTime}");
            }
        }, ticks: 200);
    }

    [Fact]
    public void CreationOrder_DoesNotChangeTheResult()
    {
        var a = new PhysicsWorld(0.0);
        var b = new PhysicsWorld(0.0);
        ulong ha = 0, hb = 0;
        SceneTestContext.RunMixedScene(a, (tick, w) => ha = SceneTestContext.HashWorld(w), ticks: 150);
        SceneTestContext.RunMixedScene(b, (tick, w) => hb = SceneTestContext.HashWorld(w), ticks: 150, descendingCreation: true);
        Assert.Equal(ha, hb);
    }

    [Fact]
    public void RestingObject_FallsAsleep_AndAPushWakesItWithTheRetailFirstStep()
    {
        // Two identical objects in two worlds; one world visits everything. After the item has rested for a while it is
        // dormant in the scene; a SetVelocity wakes it and its motion matches the full world bit for bit.
        var full = new PhysicsWorld(0.0) { VisitEveryObject = true, Sweep = new FlatGroundSweep() };
        var scene = new PhysicsWorld(0.0) { Sweep = new FlatGroundSweep() };
        PhysicsObj pf = SceneTestContext.Add(full, 1, SceneTestContext.At(50f, 50f));
        PhysicsObj ps = SceneTestContext.Add(scene, 1, SceneTestContext.At(50f, 50f));
        full.Player = pf;
        scene.Player = ps;
        PhysicsObj f = SceneTestContext.Add(full, 5, SceneTestContext.At(60f, 50f));
        PhysicsObj s = SceneTestContext.Add(scene, 5, SceneTestContext.At(60f, 50f));
        double t = 0;
        for (int i = 1; i <= 20; i++)
        {
            t += 1.0 / 30.0;
            full.Tick(t);
            scene.Tick(t);
        }

        Assert.True(s.IsDormant);
        Assert.False(f.IsDormant);
        Assert.Equal(SceneTestContext.Hash(f), SceneTestContext.Hash(s));
        f.SetVelocity(new Vector3(3f, 0f, 0f));
        s.SetVelocity(new Vector3(3f, 0f, 0f));
        Assert.False(s.IsDormant);
        for (int i = 1; i <= 60; i++)
        {
            t += 1.0 / 30.0;
            full.Tick(t);
            scene.Tick(t);
            Assert.Equal(SceneTestContext.Hash(f), SceneTestContext.Hash(s));
        }

        // Friction stopped it (0.95 per second law: 3 m/s * 0.05^t drops under 0.25 m/s within a second), and it sleeps again.
        Assert.Equal(Vector3.Zero, s.Velocity);
        Assert.True(s.IsDormant);
    }

    [Fact]
    public void StationaryObjectWithMovementManager_NeverSleeps()
    {
        // Retail: an object with a movement manager does not deactivate itself; the scene keeps visiting it.
        var scene = new PhysicsWorld(0.0) { Sweep = new FlatGroundSweep() };
        PhysicsObj o = SceneTestContext.Add(scene, 5, SceneTestContext.At(60f, 50f));
        o.GetOrCreateMotionInterpreter();
        double t = 0;
        for (int i = 1; i <= 20; i++)
        {
            t += 1.0 / 30.0;
            scene.Tick(t);
        }

        Assert.False(o.IsDormant);
        Assert.Equal(1, scene.LastTickVisitCount);
    }

    [Fact]
    public void SceneWithoutCollision_NeverCallsTheSweep()
    {
        var counting = new CountingTransition();
        var noCollision = new PhysicsWorld(0.0) { Effects = SceneEffects.All & ~SceneEffects.Collision, Sweep = counting };
        PhysicsObj o = SceneTestContext.Add(noCollision, 5, SceneTestContext.At(60f, 50f));
        int placementCalls = counting.Sweeps;
        o.SetVelocity(new Vector3(0f, 0f, 5f));
        double t = 0;
        for (int i = 1; i <= 30; i++)
        {
            t += 1.0 / 30.0;
            noCollision.Tick(t);
        }

        Assert.Equal(placementCalls, counting.Sweeps);
        // It still moved: free flight under gravity, z = 5 t - 4.9 t² > 0 after one second... (not swept, not blocked).
        Assert.NotEqual(0f, o.Position.Frame.Origin.Z);

        var withCollision = new PhysicsWorld(0.0) { Sweep = counting };
        PhysicsObj p = SceneTestContext.Add(withCollision, 5, SceneTestContext.At(60f, 50f));
        p.SetVelocity(new Vector3(0f, 0f, 5f));
        withCollision.Tick(1.0 / 30.0);
        withCollision.Tick(2.0 / 30.0);
        Assert.True(counting.Sweeps > placementCalls);
    }

    [Fact]
    public void SceneWithoutGravity_DoesNotAccelerate_AndWithoutHooks_FadesApplyAtOnce()
    {
        var w = new PhysicsWorld(0.0) { Effects = SceneEffects.All & ~(SceneEffects.Gravity | SceneEffects.Hooks) };
        PhysicsObj o = SceneTestContext.Add(w, 5, SceneTestContext.At(60f, 50f, 20f));
        o.CalcAcceleration();
        Assert.Equal(Vector3.Zero, o.Acceleration);
        o.SetTranslucency(1f, 0.5);
        o.SetVelocity(new Vector3(1f, 0f, 0f));
        double t = 0;
        for (int i = 1; i <= 30; i++)
        {
            t += 1.0 / 30.0;
            w.Tick(t);
        }

        // Constant velocity, no gravity: z unchanged at 20, x advanced by about 1 m.
        Assert.Equal(20f, o.Position.Frame.Origin.Z);
        Assert.InRange(o.Position.Frame.Origin.X, 60.9f, 61.1f);
        // Without the Hooks effect a fade is not a hook: it takes its end value at once and no hook list exists.
        Assert.Equal(1f, o.Translucency);
        Assert.Null(o.Hooks);
    }

    [Fact]
    public void TwoScenes_TickIndependently()
    {
        var a = new PhysicsWorld(0.0) { Sweep = new FlatGroundSweep() };
        var b = new PhysicsWorld(0.0) { Sweep = new FlatGroundSweep() };
        PhysicsObj oa = SceneTestContext.Add(a, 5, SceneTestContext.At(60f, 50f));
        PhysicsObj ob = SceneTestContext.Add(b, 5, SceneTestContext.At(60f, 50f));
        oa.SetVelocity(new Vector3(2f, 0f, 0f));
        double t = 0;
        for (int i = 1; i <= 10; i++)
        {
            t += 1.0 / 30.0;
            a.Tick(t);
        }

        Assert.Equal(60f, ob.Position.Frame.Origin.X);
        Assert.True(oa.Position.Frame.Origin.X > 60f);
        Assert.Equal(0.0, b.LastUpdate);
    }

    [Fact]
    public void RemovingAndRecreatingAnObject_GivesTheSameTick()
    {
        var a = new PhysicsWorld(0.0) { Sweep = new FlatGroundSweep() };
        var b = new PhysicsWorld(0.0) { Sweep = new FlatGroundSweep() };
        foreach (PhysicsWorld w in new[] { a, b })
        {
            for (uint id = 1; id <= 20; id++)
            {
                PhysicsObj o = SceneTestContext.Add(w, id, SceneTestContext.At(10f + id * 5f, 30f));
                o.SetVelocity(new Vector3(1f, id * 0.1f, 0f));
            }
        }

        // In b, remove three objects and create them again with the same state.
        for (uint id = 5; id <= 7; id++)
        {
            b.RemoveObject(b.GetObjectById(id)!);
        }

        for (uint id = 7; id >= 5; id--)
        {
            PhysicsObj o = SceneTestContext.Add(b, id, SceneTestContext.At(10f + id * 5f, 30f));
            o.SetVelocity(new Vector3(1f, id * 0.1f, 0f));
        }

        double t = 0;
        for (int i = 1; i <= 40; i++)
        {
            t += 1.0 / 30.0;
            a.Tick(t);
            b.Tick(t);
            Assert.Equal(SceneTestContext.HashWorld(a), SceneTestContext.HashWorld(b));
        }
    }

    private sealed class CountingTransition : CollisionSweep
    {
        private readonly FlatGroundSweep _inner = new();

        public int Sweeps { get; private set; }

        public override bool SweepObject(PhysicsObj obj, in Position oldPos, in Position newPos, bool adminMove, ref TransitionResult result)
        {
            Sweeps++;
            return _inner.SweepObject(obj, oldPos, newPos, adminMove, ref result);
        }

        public override SetPositionError SetPosition(PhysicsObj obj, in Position pos, SetPositionFlags flags) => _inner.SetPosition(obj, pos, flags);
    }
}

/// <summary>Two worlds never share the cells that hold their objects' shadows.</summary>
public class SceneIsolationTests
{
    [Fact]
    public void OneTerrainWorld_CannotServeTwoPhysicsWorlds()
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, 0x20, 0x20, (x, y) => 0);
        var a = new PhysicsWorld(0.0) { Sweep = new RetailSweep(terrain) };
        var b = new PhysicsWorld(0.0);
        CollisionSweep before = b.Sweep;
        Assert.Throws<System.ArgumentException>(() => b.Sweep = new RetailSweep(terrain));
        Assert.Same(before, b.Sweep);
        // The same world may take a new sweep over its own terrain.
        a.Sweep = new RetailSweep(terrain);
    }
}

/// <summary>The cheaper gate tracking keeps motion identical; only idle objects' bookkeeping may differ.</summary>
public class SceneGateTrackingTests
{
    private static ulong MotionHash(PhysicsWorld w)
    {
        var h = new StateHasher();
        for (int i = 0; i < w.ObjectCount; i++)
        {
            PhysicsObj o = w.GetObject(i);
            h.Add(o.Id);
            h.Add(o.Position);
            h.Add(o.CellId);
            h.Add(o.Velocity);
            h.Add(o.Omega);
            h.Add(o.CachedVelocity);
            h.Add((uint)(o.TransientState & ~TransientState.Active));
        }

        return h.Value;
    }

    [Fact]
    public void MovingObjectsOnly_KeepsEveryPositionVelocityAndCellOfTheRetailWalk()
    {
        var full = new PhysicsWorld(0.0) { VisitEveryObject = true };
        var cheap = new PhysicsWorld(0.0) { GateTracking = GateTracking.MovingObjectsOnly };
        var hashes = new ulong[261];
        SceneTestContext.RunMixedScene(full, (tick, w) => hashes[tick] = MotionHash(w));
        int mismatch = -1;
        SceneTestContext.RunMixedScene(cheap, (tick, w) =>
        {
            if (mismatch < 0 && MotionHash(w) != hashes[tick])
            {
                mismatch = tick;
            }
        });
        Assert.True(mismatch < 0, $"first differing tick: {mismatch}");
    }
}
