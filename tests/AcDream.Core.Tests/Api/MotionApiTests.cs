using System;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Tests.Support;
using Xunit;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Core.Tests.Api;

public class MotionApiTests
{
    [Theory]
    [InlineData(float.NaN)]
    [InlineData(float.PositiveInfinity)]
    public void NonFiniteSpeed_Throws_AndChangesNothing(float speed)
    {
        var (obj, mm, mi, table) = MotionFixture.Create(new PlayerWeenie());
        bool autonomous = obj.LastMoveWasAutonomous;
        int pending = mi.PendingMotions.Count;
        Assert.Throws<ArgumentException>(() => mm.DoMotion(MotionCommand.WalkForward, MotionFixture.Params(speed)));
        Assert.Throws<ArgumentException>(() => mm.StopMotion(MotionCommand.WalkForward, MotionFixture.Params(speed)));
        Assert.Throws<ArgumentException>(() => mi.DoInterpretedMotion(MotionCommand.WalkForward, MotionFixture.Params(speed)));
        Assert.Throws<ArgumentException>(() => mi.Jump(speed, out _));
        Assert.Equal(autonomous, obj.LastMoveWasAutonomous);
        Assert.Equal(pending, mi.PendingMotions.Count);
        Assert.Equal(MotionCommand.Ready, mi.InterpretedState.ForwardCommand);
        Assert.Equal(System.Numerics.Vector3.Zero, table.Velocity);
    }

    [Fact]
    public void States_RejectNonFiniteSpeeds()
    {
        var s = new InterpretedMotionState();
        Assert.Throws<ArgumentException>(() => s.ForwardSpeed = float.NaN);
        Assert.Equal(1f, s.ForwardSpeed);
        var r = new RawMotionState();
        Assert.Throws<ArgumentException>(() => r.TurnSpeed = float.NegativeInfinity);
        Assert.Equal(1f, r.TurnSpeed);
    }

    [Fact]
    public void Interpreter_RejectsBadRates()
    {
        var (_, _, mi, _) = MotionFixture.Create(null);
        Assert.Throws<ArgumentException>(() => mi.CurrentSpeedFactor = 0f);
        Assert.Throws<ArgumentException>(() => mi.MyRunRate = float.NaN);
        Assert.Equal(1f, mi.CurrentSpeedFactor);
        Assert.Equal(1f, mi.MyRunRate);
    }

    [Fact]
    public void PlayerWeenie_RejectsNegativeSkills()
    {
        var w = new PlayerWeenie { RunSkill = 10 };
        Assert.Throws<ArgumentOutOfRangeException>(() => w.RunSkill = -200);
        Assert.Throws<ArgumentOutOfRangeException>(() => w.JumpSkill = -1300);
        Assert.Equal(10, w.RunSkill);
    }

    [Fact]
    public void MovementEvent_NullArguments_Throw()
    {
        var (obj, _, _, _) = MotionFixture.Create(null);
        Assert.Throws<ArgumentNullException>(() => MovementEvent.ApplyInterpretedMotion(null!, new InterpretedMotionState()));
        Assert.Throws<ArgumentNullException>(() => MovementEvent.ApplyInterpretedMotion(obj, null!));
    }

    [Fact]
    public void MovementManagerOf_ClientsOwnManager_Throws()
    {
        var world = new AcDream.Core.Physics.World.PhysicsWorld(0.0);
        var obj = world.CreateObject(1);
        obj.Movement = new AcDream.Core.Physics.Objects.Seams.BasicMovementManager();
        Assert.Throws<InvalidOperationException>(() => MovementManager.Of(obj));
        Assert.False(MovementEvent.ApplyInterpretedMotion(obj, new InterpretedMotionState()));
    }
}
