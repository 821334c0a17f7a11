using System.Numerics;
using AcDream.Core.Fixtures.Wire;
using AcDream.Core.Physics.Input;
using AcDream.Core.Physics.Motion.Wire;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Allocation;

// UpdatePosition, VectorUpdate and SetState bodies decoded and applied through ServerMessageHandler.HandleMessage, with
// ticks between: nothing allocated in the steady state.
public class ServerMessageAllocationTests
{
    [Fact]
    public void HandleMessage_PositionsVectorsStates_SteadyState_AllocatesNothing()
    {
        PhysicsWorld world = ObjectScene.Flat(out _);
        PhysicsObj player = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f));
        PhysicsObj c = ObjectScene.Creature(world, 2, ObjectScene.At(105f, 100f));
        world.Player = player;
        var h = new ServerMessageHandler(world);
        byte[][] positions = new byte[300][];
        byte[][] vectors = new byte[300][];
        byte[][] states = new byte[300][];
        for (int i = 0; i < positions.Length; i++)
        {
            Position p = ObjectScene.At(105f + 0.1f * (i % 40), 100f);
            positions[i] = PhysicsMessageBytes.UpdatePosition(2, 0x34, p.ObjCellId, p.Frame.Origin, p.Frame.Rotation, 0, (ushort)(i + 1));
            vectors[i] = PhysicsMessageBytes.VectorUpdate(2, new Vector3(0f, 0f, 0.01f * (i % 7)), Vector3.Zero, 0, (ushort)(i + 1));
            states[i] = PhysicsMessageBytes.SetState(2, (uint)PhysicsGlobals.DefaultState, 0, (ushort)(i + 1));
        }

        int next = 0;
        void Window()
        {
            for (int k = 0; k < 30; k++)
            {
                h.HandleMessage(0xF748, positions[next]);
                h.HandleMessage(0xF74E, vectors[next]);
                h.HandleMessage(0xF74B, states[next]);
                next++;
                world.Tick(world.CurrentTime + 1.0 / 30.0);
            }
        }

        Window(); // warm: the position manager, the interpolation nodes
        AllocationProbe.AssertSteadyStateAllocatesNothing(Window);
        Assert.Equal((ushort)next, c.GetUpdateTime(PhysicsTimeStamp.Position));
    }

    // The outbound side: keys every few frames, the world's tick, TakeOutbound each frame (MoveToStates, AutonomousPositions
    // and a jump's body written into the input's buffers): nothing allocated.
    [Fact]
    public void TakeOutbound_KeysAndPositionsEachFrame_SteadyState_AllocatesNothing()
    {
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        var input = new PlayerInput(s.Player);
        double now = 0;
        int frame = 0, sent = 0;
        void Window()
        {
            for (int k = 0; k < 60; k++)
            {
                switch (frame++ % 40)
                {
                    case 0: input.KeyDown(MovementKeys.Forward); break;
                    case 10: input.KeyDown(MovementKeys.TurnLeft); break;
                    case 15: input.KeyUp(MovementKeys.TurnLeft); break;
                    case 25: input.KeyUp(MovementKeys.Forward); break;
                    case 30: input.KeyDown(MovementKeys.Jump); break;
                    case 36: input.KeyUp(MovementKeys.Jump); break;
                }

                s.World.Tick(now += 1.0 / 30.0);
                sent += input.TakeOutbound() != OutboundMessages.None ? 1 : 0;
            }
        }

        Window();
        AllocationProbe.AssertSteadyStateAllocatesNothing(Window);
        Assert.True(sent > 6);
    }
}
