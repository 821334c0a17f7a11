using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// <see cref="PhysicsWorld.Tick"/> (and <see cref="PhysicsWorld.UseTime"/>, <see cref="PhysicsWorld.SetCurrentTime"/>, setting
/// <see cref="PhysicsWorld.Sweep"/>) called from
/// a callback inside the same world's tick throws <see cref="InvalidOperationException"/> and changes nothing: the outer tick
/// goes on and ends exactly as a tick without the call.
/// </summary>
public class ReentrantTickRefusedTests
{
    private sealed class ReentrantObserver : IStepObserver
    {
        private readonly PhysicsWorld _world;
        private readonly int _call;

        public ReentrantObserver(PhysicsWorld world, int call)
        {
            _world = world;
            _call = call;
        }

        public Exception? Caught { get; private set; }

        public double ClockSeen { get; private set; }

        private int _depth;

        public void OnStep(PhysicsObj obj, float quantum, double physicsTime)
        {
            // Only the first step calls back (and never from inside its own call: without the guard that would recurse).
            if (Caught is not null || _depth > 0 || ClockSeen != 0.0)
            {
                return;
            }

            _depth++;
            try
            {
                switch (_call)
                {
                    case 0: _world.Tick(_world.CurrentTime + 1.0); break;
                    case 1: _world.UseTime(); break;
                    case 2: _world.SetCurrentTime(_world.CurrentTime + 1.0); break;
                    default: _world.Sweep = new BlockedTransition(); break;
                }
            }
            catch (Exception e)
            {
                Caught = e;
            }

            _depth--;
            ClockSeen = _world.CurrentTime;
        }
    }

    private sealed class ReentrantPlayerListener : IPlayerPhysicsListener
    {
        public Exception? Caught { get; private set; }

        private int _depth;

        public void PlayerPhysicsUpdated(PhysicsObj player)
        {
            if (_depth++ > 0)
            {
                _depth--;
                return;
            }

            try
            {
                player.World.Tick(player.World.CurrentTime + 1.0);
            }
            catch (Exception e)
            {
                Caught = e;
            }

            _depth--;
        }
    }

    private static PhysicsWorld Scene(bool visitEveryObject, out PhysicsObj mover)
    {
        var world = new PhysicsWorld(0.0) { VisitEveryObject = visitEveryObject };
        mover = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f), id: 1);
        mover.SetState(mover.State & ~PhysicsState.Gravity);
        mover.SetVelocity(new Vector3(0f, 2f, 0f));
        TickTestContext.CreateObject(world, new Vector3(12f, 10f, 0f), id: 2);
        return world;
    }

    [Theory]
    [InlineData(0, false)]
    [InlineData(1, false)]
    [InlineData(2, false)]
    [InlineData(3, false)]
    [InlineData(0, true)]
    [InlineData(1, true)]
    [InlineData(2, true)]
    [InlineData(3, true)]
    public void CallFromStepObserver_Throws_AndTheTickEndsAsWithoutIt(int call, bool visitEveryObject)
    {
        PhysicsWorld reference = Scene(visitEveryObject, out PhysicsObj refMover);
        reference.Tick(0.05);

        PhysicsWorld world = Scene(visitEveryObject, out PhysicsObj mover);
        var observer = new ReentrantObserver(world, call);
        world.StepObserver = observer;
        Assert.True(world.Tick(0.05));

        Assert.IsType<InvalidOperationException>(observer.Caught);
        Assert.Equal(0.05, observer.ClockSeen); // the clock was not moved by the refused call
        Assert.Equal(0.05, world.CurrentTime);
        Assert.Equal(0.05, world.LastUpdate);
        Assert.Same(FreeSpaceSweep.Instance, world.Sweep);
        // 2 m/s for one 0.05 s step, bit for bit the reference run's.
        Assert.Equal(refMover.Position.Frame.Origin, mover.Position.Frame.Origin);
        Assert.Equal(refMover.UpdateTime, mover.UpdateTime);

        // The world ticks normally afterwards.
        world.StepObserver = null;
        reference.Tick(0.10);
        Assert.True(world.Tick(0.10));
        Assert.Equal(refMover.Position.Frame.Origin, mover.Position.Frame.Origin);
    }

    [Fact]
    public void CallFromPlayerListener_Throws()
    {
        PhysicsWorld world = Scene(false, out PhysicsObj mover);
        world.Player = mover;
        var listener = new ReentrantPlayerListener();
        world.PlayerListener = listener;

        Assert.True(world.Tick(0.05));

        Assert.IsType<InvalidOperationException>(listener.Caught);
        Assert.Equal(0.05, world.LastUpdate);
        Assert.True(world.Tick(0.10));
    }
}
