using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Replay.Harness;
using Xunit;

namespace AcDream.Core.Tests.Allocation;

/// <summary>A long run in the steady state allocates nothing: bytes counted with
/// <see cref="GC.GetAllocatedBytesForCurrentThread"/> over thousands of ticks after a warm-up.</summary>
public class LongRunAllocationTests
{
    [Fact]
    public void ThirtyHertz_1001Objects_50Walking_AllocatesNothingOverTenMinutes_AfterWarmUp()
    {
        // 1,001 objects at 30 Hz: a player walking a fixed 48 m square, 49 creatures wandering (a new pseudo-random heading
        // every 3 s, turned back towards the middle once 70 m out) and 951 resting items (half of them static) on a 6 m grid
        // over the landblock. The wanderers keep going far from the player and back, so they keep falling asleep in the gate
        // queue and waking again, each time in a different place: the places the gate's grid must hold entries in keep
        // changing while their total stays the same. Before the grid kept all its cells in one shared buffer, each cell grew
        // its own array whenever it held more entries than ever before (600 B at a time, all through the run).
        var scene = new LongRunScene();
        scene.Run(7200); // warm-up: two and a half laps
        long before = GC.GetAllocatedBytesForCurrentThread();
        scene.Run(18000); // ten minutes of play (18,000 / 30 s): six and a quarter more laps
        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        Assert.Equal(0L, allocated);
        // The run did what it is meant to: wanderers slept in the gate queue and woke through it.
        Assert.True(scene.World.GateWakes > 0 && scene.World.DormantCount > 900, $"wakes {scene.World.GateWakes} dormant {scene.World.DormantCount}");
    }

    private sealed class LongRunScene
    {
        private const double Dt = 1.0 / 30.0;
        private readonly PhysicsObj _player;
        private readonly PhysicsObj[] _wanderers = new PhysicsObj[49];
        private readonly Random _random = new(5);
        private readonly Position _middle = At(96f, 96f);
        private int _tick;

        public LongRunScene()
        {
            World = new PhysicsWorld(0.0) { Sweep = new ReplayGroundSweep() };
            _player = Mover(1u, 72f, 72f);
            for (int i = 0; i < _wanderers.Length; i++)
            {
                _wanderers[i] = Mover((uint)(2 + i), 60f + (i % 7) * 12f, 60f + (i / 7) * 12f);
            }

            for (int i = 0; i < 951; i++)
            {
                PhysicsObj o = Item((uint)(1000 + i), 4f + (i % 31) * 6f, 4f + (i / 31) * 6f);
                if ((i & 1) == 1)
                {
                    o.SetState(o.State | PhysicsState.Static);
                }
            }

            World.Player = _player;
        }

        public PhysicsWorld World { get; }

        public void Run(int ticks)
        {
            for (int t = 0; t < ticks; t++)
            {
                // The player walks 48 m (720 ticks at 2 m/s, 1/30 s each), then turns 90 degrees: a lap is 2,880 ticks.
                if (_tick % 720 == 0)
                {
                    _player.SetHeading(_tick / 720 % 4 * 90f);
                }

                for (int i = 0; i < _wanderers.Length; i++)
                {
                    PhysicsObj w = _wanderers[i];
                    if (w.IsDormant)
                    {
                        continue;
                    }

                    Vector3 off = _middle.GetOffset(w.Position);
                    if (off.X * off.X + off.Y * off.Y > 70f * 70f)
                    {
                        w.SetHeading(Heading(-off.X, -off.Y));
                    }
                    else if ((_tick + i * 7) % 90 == 0)
                    {
                        w.SetHeading((float)(_random.NextDouble() * 360.0));
                    }
                }

                _tick++;
                World.Tick(World.CurrentTime + Dt);
            }
        }

        private static float Heading(float dx, float dy)
        {
            float h = MathF.Atan2(dx, dy) * (180f / MathF.PI);
            return h < 0f ? h + 360f : h;
        }

        private static Position At(float x, float y)
        {
            var p = new Position(0xA9B40001u, new Vector3(x, y, 0f));
            p.TryAdjustToOutside();
            return p;
        }

        private PhysicsObj Item(uint id, float x, float y)
        {
            PhysicsObj o = World.CreateObject(id);
            o.PartArray = new SimplePartArray(numParts: 1, numSpheres: 1);
            o.EnterWorld(At(x, y));
            return o;
        }

        private PhysicsObj Mover(uint id, float x, float y)
        {
            PhysicsObj o = Item(id, x, y);
            o.GetOrCreateMotionInterpreter();
            ((SimplePartArray)o.PartArray!).SequenceVelocity = new Vector3(0f, 2f, 0f);
            return o;
        }
    }
}
