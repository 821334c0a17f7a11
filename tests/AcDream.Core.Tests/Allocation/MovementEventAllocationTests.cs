using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Retail;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Shared;
using Xunit;
using AcDream.Core.Physics.Motion.MoveTo;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Core.Tests.Allocation;

// A MovementEvent decoded into a reused MovementEventMessage and applied through the retail entry point, with ticks between:
// nothing allocated in the steady state (type 0, and a MoveToPosition that the world then walks).
public class MovementEventAllocationTests
{
    [Fact]
    public void DecodeAndHandleMovementEvent_SteadyState_AllocatesNothing()
    {
        var world = new PhysicsWorld(0.0) { Sweep = new AcDream.Core.Tests.Replay.Harness.LastReportGroundSweep { GroundZ = 0f } };
        PhysicsObj obj = world.CreateObject(MovementEventBytes.ObjectId);
        obj.Weenie = RemoteCreatureWeenie.Creature;
        var parts = Walkers.OneSphere();
        parts.MotionPlayer = new SpeedOnlyMotionPlayer();
        obj.PartArray = parts;
        Assert.True(obj.EnterWorld(new Position(0xA9B40001u, new Vector3(50f, 50f, 0f))));
        // The bodies: run forward (type 0), and a MoveToPosition 5 m north (type 7, retail's default parameters).
        byte[][] bodies = new byte[60][];
        for (int i = 0; i < bodies.Length; i++)
        {
            ushort stamp = (ushort)(i + 1);
            bodies[i] = i % 2 == 0
                ? MovementEventBytes.Body(stamp, 0, false, MovementEventBytes.Forward(0x3D, 0x07, 2f))
                : MovementEventBytes.Body(stamp, 0, false, new RetailDataWriter().Byte(7).Byte(0).UInt16(0x3D)
                    .UInt32(0xA9B40001u).Single(50f).Single(55f).Single(0f)
                    .UInt32(0x1EE0Fu).Single(0.6f).Single(0f).Single(float.MaxValue).Single(1f).Single(15f).Single(0f)
                    .Single(1f).ToArray());
        }

        var message = new MovementEventMessage();
        int next = 0, notApplied = 0;
        void Window()
        {
            for (int i = 0; i < 30; i++)
            {
                MovementEventDecoder.Decode(bodies[next % bodies.Length], message);
                // Each event's movement stamp is the next one: always newer, always applied.
                message.MovementTimestamp = (ushort)(next + 1);
                next++;
                if (obj.HandleMovementEvent(message) != MovementEventResult.Applied)
                {
                    notApplied++;
                }
                world.Tick(world.CurrentTime + 1.0 / 30.0);
            }
        }

        Window();   // warm-up: managers created
        AllocationProbe.AssertSteadyStateAllocatesNothing(Window);
        Assert.Equal(0, notApplied);
        Assert.True(obj.Movement is MovementManager { MoveToManager: not null });
    }
}
