using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Scene;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Scene;

/// <summary>
/// Dormant objects the player's travel carries across the 96 m gate: their crossings are found from the gate queues and applied
/// without a visit, and everything a client can read — after the tick and in the middle of it — is bit-identical to retail's
/// walk over every object.
/// </summary>
public class GateCrossingTests
{
    private const uint PlayerId = 5000;
    private const uint ObserverId = 50;

    /// <summary>
    /// A player (id 5000, in the middle of the visiting order) among 576 objects on a 9 m grid around it — resting items with and
    /// without spheres, idle objects hovering off walkable ground, statics, sliding movers — so that hundreds cross the 96 m
    /// gate both ways, before and after the player in the order. The player walks straight, then about a 2 m square, is
    /// teleported 150 m away and back, and the clock stalls for 0.45 s, 0.42 s (time left unconsumed) and 2.5 s (beyond
    /// HugeQuantum). An always-awake object (id 50) reads the bookkeeping of every object between it and the player at each of
    /// its steps, i.e. in the middle of the tick, before their turn.
    /// </summary>
    private static void RunCrossingScene(PhysicsWorld w, Action<int, PhysicsWorld, ulong> afterTick, int ticks = 480)
    {
        w.Sweep = new FlatGroundSweep();
        var probe = new MidTickProbe();
        w.StepObserver = probe;
        w.PlayerListener = probe;
        PhysicsObj observer = SceneTestContext.Add(w, ObserverId, SceneTestContext.At(90f, 90f));
        observer.GetOrCreateMotionInterpreter(); // a movement manager: never sleeps
        PhysicsObj player = SceneTestContext.Add(w, PlayerId, SceneTestContext.At(96f, 96f));
        player.SetState(player.State & ~PhysicsState.Gravity);
        player.CalcAcceleration();
        for (int k = 0; k < 576; k++)
        {
            uint id = 100u + 17u * (uint)k; // ids 100..9892: about half before the player in the order, half after
            float x = 96f - 108f + (k % 24) * 9f + 0.37f * (k % 7);
            float y = 96f - 108f + (k / 24) * 9f + 0.23f * (k % 5);
            switch (k % 5)
            {
                case 0:
                    SceneTestContext.Add(w, id, SceneTestContext.At(x, y), spheres: 1);
                    break;
                case 1:
                    SceneTestContext.Add(w, id, SceneTestContext.At(x, y), spheres: 0);
                    break;
                case 2:
                {
                    // Idle off walkable ground: no gravity, 3 m up (within 96 m it stays ACTIVE).
                    PhysicsObj o = SceneTestContext.Add(w, id, SceneTestContext.At(x, y, 3f), spheres: 1);
                    o.SetState(o.State & ~PhysicsState.Gravity);
                    o.CalcAcceleration();
                    break;
                }

                case 3:
                {
                    PhysicsObj o = SceneTestContext.Add(w, id, SceneTestContext.At(x, y), spheres: 1);
                    o.SetState(o.State | PhysicsState.Static);
                    break;
                }

                default:
                {
                    PhysicsObj o = SceneTestContext.Add(w, id, SceneTestContext.At(x, y), spheres: 1);
                    o.SetVelocity(new Vector3(1.5f * ((k & 8) != 0 ? 1f : -1f), 0.5f, 0f)); // slides, stops, far ones freeze
                    break;
                }
            }
        }

        w.Player = player;
        probe.Watch(w);
        Position home = player.Position;
        Position observerHome = observer.Position;
        double t = w.CurrentTime;
        for (int tick = 1; tick <= ticks; tick++)
        {
            if (tick < 120)
            {
                player.SetVelocity(new Vector3(5f, 0.8f, 0f)); // straight, east
            }
            else if (tick < 300)
            {
                float h = (tick / 20 % 4) * MathF.PI / 2f; // about a 2 m square at 3 m/s
                player.SetVelocity(new Vector3(3f * MathF.Sin(h), 3f * MathF.Cos(h), 0f));
            }
            else
            {
                player.SetVelocity(Vector3.Zero);
            }

            if (tick == 330)
            {
                Position away = player.Position;
                away.Frame.Origin += new Vector3(0f, 150f, 0f);
                Assert.True(away.TryAdjustToOutside());
                Assert.Equal(SetPositionError.Ok, player.SetPositionSimple(away, sliding: false));
                Position o = observer.Position; // the observer goes along (it must stay within 96 m to keep stepping)
                o.Frame.Origin += new Vector3(0f, 150f, 0f);
                Assert.True(o.TryAdjustToOutside());
                Assert.Equal(SetPositionError.Ok, observer.SetPositionSimple(o, sliding: false));
            }

            if (tick == 390)
            {
                Assert.Equal(SetPositionError.Ok, player.SetPositionSimple(home, sliding: false));
                Assert.Equal(SetPositionError.Ok, observer.SetPositionSimple(observerHome, sliding: false));
            }

            if (tick >= 420)
            {
                player.SetVelocity(new Vector3(-4f, -1f, 0f));
            }

            double dt = tick switch
            {
                200 => 0.45,
                230 => 0.42, // 2 x MaxQuantum + 0.02: the remainder is below MinQuantum and stays unconsumed
                260 => 2.5,
                _ => 1.0 / 30.0 + (tick % 5) * 0.003,
            };
            t += dt;
            probe.Hash = 0;
            w.Tick(t);
            afterTick(tick, w, probe.Hash);
        }
    }

    [Fact]
    public void CrossingObjects_AreBitIdenticalToVisitingEveryObject_AfterAndDuringEachTick()
    {
        var full = new PhysicsWorld(50.0) { VisitEveryObject = true };
        var after = new ulong[481];
        var during = new ulong[481];
        RunCrossingScene(full, (tick, w, mid) =>
        {
            after[tick] = SceneTestContext.HashWorld(w);
            during[tick] = mid;
        });

        var scene = new PhysicsWorld(50.0);
        int visits = 0;
        RunCrossingScene(scene, (tick, w, mid) =>
        {
            Assert.True(during[tick] == mid, $"tick {tick}: the mid-tick reads differ");
            Assert.True(after[tick] == SceneTestContext.HashWorld(w), $"tick {tick}: the state after the tick differs");
            visits += w.LastTickVisitCount;
        });

        // The scene really did the crossings without visits: hundreds of crossings, few wakes, far fewer visits than 578 x 480.
        Assert.True(scene.GateFlips > 300, $"flips {scene.GateFlips}");
        Assert.Equal(new GateStatistics(scene.GateRemeasures, scene.GateFlips, scene.GateWakes), scene.GateStatistics);
        Assert.Equal(new GateStatistics(0, 0, 0), full.GateStatistics); // visiting every object tracks nothing
        Assert.True(scene.GateWakes < scene.GateFlips / 4, $"wakes {scene.GateWakes}, flips {scene.GateFlips}");
        Assert.True(visits < 578 * 480 / 4, $"visits {visits}");
    }

    [Fact]
    public void CrossingScene_IsTheSame_ReadOrNotRead()
    {
        // Reading an object's bookkeeping materialises it; the result must not depend on whether (or when) anyone reads.
        var read = new PhysicsWorld(50.0);
        var hashes = new ulong[481];
        RunCrossingScene(read, (tick, w, _) => hashes[tick] = SceneTestContext.HashWorld(w));
        var unread = new PhysicsWorld(50.0);
        RunCrossingScene(unread, (tick, w, _) =>
        {
            if (tick % 97 == 0 || tick == 480)
            {
                Assert.True(hashes[tick] == SceneTestContext.HashWorld(w), $"tick {tick}");
            }
        });
    }

    [Fact]
    public void ObjectsHoveringOnTheBoundary_AreDecidedExactly()
    {
        // 40 resting objects at 96 m +- up to 0.8 mm (some before the player in the order, some after) while the player is placed
        // back and forth by 0.1 to 0.4 mm a tick: sides flip again and again, often within the estimate's rounding band, where
        // retail's own arithmetic must decide. Bit-identical to the retail walk.
        static void Run(PhysicsWorld w, Action<int, PhysicsWorld> afterTick)
        {
            w.Sweep = new FlatGroundSweep();
            PhysicsObj player = SceneTestContext.Add(w, 500u, SceneTestContext.At(96f, 96f));
            player.SetState(player.State & ~PhysicsState.Gravity);
            player.CalcAcceleration();
            for (int k = 0; k < 40; k++)
            {
                double a = k * Math.PI / 20.0;
                double r = 96.0 + (k % 9 - 4) * 0.0002;
                uint id = k % 2 == 0 ? 100u + (uint)k : 1000u + (uint)k;
                SceneTestContext.Add(w, id, SceneTestContext.At(96f + (float)(r * Math.Cos(a)), 96f + (float)(r * Math.Sin(a))));
            }

            w.Player = player;
            double t = w.CurrentTime;
            for (int tick = 1; tick <= 300; tick++)
            {
                // The client places the player (retail ignores velocities this small): 0.1 to 0.4 mm a tick.
                float step = (tick / 3 % 2 == 0 ? 1f : -1f) * ((tick / 50 % 2 == 0) ? 0.0004f : 0.0001f);
                Position p = player.Position;
                p.Frame.Origin += new Vector3(step, 0.6f * step, 0f);
                Assert.Equal(SetPositionError.Ok, player.SetPositionSimple(p, sliding: false));
                t += 1.0 / 30.0;
                w.Tick(t);
                afterTick(tick, w);
            }
        }

        PhysicsWorld scene = AssertTickByTickAsVisitingEveryObject(10.0, 300, Run);
        Assert.True(scene.GateFlips > 20, $"flips {scene.GateFlips} remeasures {scene.GateRemeasures} wakes {scene.GateWakes} dormant {scene.DormantCount}");
        Assert.True(scene.DormantCount >= 35, $"dormant {scene.DormantCount}");
    }

    [Fact]
    public void PlayerChangedInTheMiddleOfATick_IsBitIdenticalToVisitingEveryObject()
    {
        // The client switches the player from inside the tick: once from the player listener (after the old player's update),
        // once from a step of another object. Objects visited later in that tick measure against the new player, as retail's do.
        static void Run(PhysicsWorld w, Action<int, PhysicsWorld> afterTick)
        {
            w.Sweep = new FlatGroundSweep();
            PhysicsObj a = SceneTestContext.Add(w, 500u, SceneTestContext.At(96f, 96f));
            PhysicsObj b = SceneTestContext.Add(w, 20u, SceneTestContext.At(150f, 40f));
            PhysicsObj stepper = SceneTestContext.Add(w, 300u, SceneTestContext.At(100f, 100f));
            stepper.GetOrCreateMotionInterpreter(); // never sleeps: its steps drive the second switch
            for (int k = 0; k < 400; k++)
            {
                uint id = 100u + 3u * (uint)k; // 100..1297: before and after both players in the order
                SceneTestContext.Add(w, id, SceneTestContext.At(-30f + (k % 20) * 13f, -30f + (k / 20) * 13f), spheres: k % 3 == 0 ? 0 : 1);
            }

            var switcher = new Switcher(w, a, b);
            w.PlayerListener = switcher;
            w.StepObserver = switcher;
            w.Player = a;
            double t = w.CurrentTime;
            for (int tick = 1; tick <= 200; tick++)
            {
                switcher.Tick = tick;
                a.SetVelocity(new Vector3(4f, 1f, 0f));
                t += 1.0 / 30.0;
                w.Tick(t);
                afterTick(tick, w);
            }
        }

        PhysicsWorld scene = AssertTickByTickAsVisitingEveryObject(20.0, 200, Run);
        Assert.True(scene.DormantCount > 200, $"dormant {scene.DormantCount}");
    }

    private sealed class Switcher(PhysicsWorld world, PhysicsObj a, PhysicsObj b) : IPlayerPhysicsListener, IStepObserver
    {
        public int Tick { get; set; }

        public void PlayerPhysicsUpdated(PhysicsObj player)
        {
            if (Tick == 60)
            {
                world.Player = b;
            }
        }

        public void OnStep(PhysicsObj obj, float quantum, double physicsTime)
        {
            if (Tick == 130 && obj.Id == 300u && world.Player == b)
            {
                world.Player = a;
            }
        }
    }

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void ObjectsWokenAgainAndAgain_LeaveABoundedQueue(bool playerWalks)
    {
        // Objects kicked awake every few ticks leave dead grid entries and stale band copies behind in the gate queues each time
        // they fall asleep again; the queues drop them (grid cells swept every tick, copies when met or by compaction), so a long
        // walk, or a long wait, keeps them bounded.
        var churn = new ChurnScene();
        int maxEntries = 0;
        for (int tick = 1; tick <= 3000; tick++)
        {
            churn.Step(playerWalks);
            if (tick > 100)
            {
                maxEntries = Math.Max(maxEntries, churn.World.GateEntryCount);
            }
        }

        PhysicsWorld w = churn.World;
        Assert.True(w.DormantCount > 500, $"dormant {w.DormantCount}");
        Assert.True(maxEntries <= 2 * ChurnScene.Items + 1100, $"entries up to {maxEntries} for {ChurnScene.Items} objects");
    }

    [Fact]
    public void GateTracking_WithAWalkingPlayerAndObjectsWakingAndSleeping_AllocatesNothingOnceGrown()
    {
        // The per-tick path of the gate (ring scans, crossings, ring and band rebuilds, grid sweeps), with objects woken and
        // falling asleep again all the while: once its arrays have grown, a lap of the player's square allocates nothing.
        var churn = new ChurnScene();
        void Run(int ticks)
        {
            for (int i = 0; i < ticks; i++)
            {
                churn.Step(playerWalks: true);
            }
        }

        Run(3200);
        PhysicsWorld w = churn.World;
        Assert.True(w.GateFlips > 0 && w.DormantCount > 500, $"flips {w.GateFlips} dormant {w.DormantCount}");
        AllocationProbe.AssertSteadyStateAllocatesNothing(() => Run(160));
    }

    [Fact]
    public void StillPlayer_ReMeasuresNothing()
    {
        var w = new PhysicsWorld(50.0);
        long before = 0;
        RunCrossingScene(w, (tick, world, _) =>
        {
            if (tick == 310)
            {
                before = world.GateRemeasures;
            }
        }, ticks: 329);
        // Ticks 310..329: the player stands still (velocity zero from tick 300 on, settled by 310).
        Assert.Equal(before, w.GateRemeasures);
    }

    [Fact]
    public void PlayerMovingAboutOneSpot_NeverReMeasuresObjectsFarFromTheGate()
    {
        // Objects more than the band's half-width (GateQueue.BandHalfWidth, 12 m) from the 96 m boundary are in neither band:
        // a player walking a 2 m square (within 4 m of where it started) never re-measures them, however long it walks; a
        // straight walk of 80 m rebuilds the bands from every slot, which does.
        var w = new PhysicsWorld(50.0) { Sweep = new FlatGroundSweep() };
        PhysicsObj player = SceneTestContext.Add(w, 1u, SceneTestContext.At(96f, 96f));
        player.SetState(player.State & ~PhysicsState.Gravity);
        player.CalcAcceleration();
        for (int k = 0; k < 400; k++)
        {
            float r = k < 200 ? 130f : 40f; // margins 34 m and 56 m
            float a = k * 2f * MathF.PI / 200f;
            SceneTestContext.Add(w, 100u + (uint)k, SceneTestContext.At(96f + r * MathF.Sin(a), 96f + r * MathF.Cos(a)));
        }

        w.Player = player;
        double t = w.CurrentTime;
        long settled = 0;
        for (int tick = 1; tick <= 600; tick++)
        {
            float h = (tick / 20 % 4) * MathF.PI / 2f; // 2 m a side at 3 m/s
            player.SetVelocity(tick <= 400 ? new Vector3(3f * MathF.Sin(h), 3f * MathF.Cos(h), 0f) : new Vector3(12f, 0f, 0f));
            t += 1.0 / 30.0;
            w.Tick(t);
            if (tick == 5)
            {
                Assert.True(w.DormantCount >= 400, $"dormant {w.DormantCount}");
                settled = w.GateRemeasures;
            }

            if (tick == 400)
            {
                Assert.Equal(settled, w.GateRemeasures); // 395 ticks, 39.5 m of path: nothing re-measured
            }
        }

        Assert.True(w.GateRemeasures > settled + 100, $"straight walk re-measured {w.GateRemeasures - settled}, player at {player.Position.Frame.Origin} cell {player.CellId:X8} flips {w.GateFlips} wakes {w.GateWakes} dormant {w.DormantCount}");
    }

    /// <summary>Runs a scene twice, visiting every object and as a scene, and asserts the two are bit-identical after every tick;
    /// returns the scene world.</summary>
    private static PhysicsWorld AssertTickByTickAsVisitingEveryObject(double start, int ticks,
        Action<PhysicsWorld, Action<int, PhysicsWorld>> run)
    {
        var hashes = new ulong[ticks + 1];
        run(new PhysicsWorld(start) { VisitEveryObject = true }, (tick, w) => hashes[tick] = SceneTestContext.HashWorld(w));
        var scene = new PhysicsWorld(start);
        run(scene, (tick, w) => Assert.True(hashes[tick] == SceneTestContext.HashWorld(w), $"tick {tick}"));
        return scene;
    }

    /// <summary>A player at (96, 96) among 600 items on an 8 m grid; each tick it walks a 4 m square at 3 m/s (or stands) and one
    /// item is kicked awake, slides to rest and falls asleep again.</summary>
    private sealed class ChurnScene
    {
        public const int Items = 600;
        private readonly PhysicsObj _player;
        private readonly PhysicsObj[] _items = new PhysicsObj[Items];
        private double _time;
        private int _tick;

        public ChurnScene()
        {
            World = new PhysicsWorld(0.0) { Sweep = new FlatGroundSweep() };
            _player = SceneTestContext.Add(World, 1u, SceneTestContext.At(96f, 96f));
            for (int k = 0; k < Items; k++)
            {
                _items[k] = SceneTestContext.Add(World, 100u + (uint)k, SceneTestContext.At(-20f + (k % 30) * 8f, -20f + (k / 30) * 8f));
            }

            World.Player = _player;
        }

        public PhysicsWorld World { get; }

        public void Step(bool playerWalks)
        {
            _tick++;
            float h = (_tick / 40 % 4) * MathF.PI / 2f;
            _player.SetVelocity(playerWalks ? new Vector3(3f * MathF.Sin(h), 3f * MathF.Cos(h), 0f) : Vector3.Zero);
            _items[_tick * 7 % Items].SetVelocity(new Vector3(0.6f, 0f, 0f)); // wakes; it slides to rest and sleeps again
            _time += 1.0 / 30.0;
            World.Tick(_time);
        }
    }

    /// <summary>Hashes, in the middle of the tick, the bookkeeping of objects not yet visited: at each step of the observer, those
    /// after it and before the player in the order; after the player's update, those after the player.</summary>
    private sealed class MidTickProbe : IStepObserver, IPlayerPhysicsListener
    {
        private PhysicsWorld? _world;

        public ulong Hash { get; set; }

        public void Watch(PhysicsWorld w) => _world = w;

        public void OnStep(PhysicsObj obj, float quantum, double physicsTime)
        {
            if (_world is null || obj.Id != ObserverId)
            {
                return;
            }

            Read(ObserverId, PlayerId);
        }

        public void PlayerPhysicsUpdated(PhysicsObj player) => Read(PlayerId, uint.MaxValue);

        private void Read(uint afterId, uint beforeId)
        {
            if (_world is null)
            {
                return;
            }

            var h = new StateHasher();
            h.Add(Hash);
            for (int i = 0; i < _world.ObjectCount; i++)
            {
                PhysicsObj o = _world.GetObject(i);
                if (o.Id > afterId && o.Id < beforeId)
                {
                    h.Add((uint)o.TransientState);
                    h.Add(o.UpdateTime);
                    h.Add(o.PlayerDistance);
                }
            }

            Hash = h.Value;
        }
    }
}
