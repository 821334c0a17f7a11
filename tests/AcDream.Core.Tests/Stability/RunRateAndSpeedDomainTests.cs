using System;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Motion.Wire;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Retail;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// Issue #34, items 3 and 5: run rates are in (0, <see cref="InputLimits.MaxRunRate"/>] and motion speeds within
/// ±<see cref="InputLimits.MaxMotionSpeed"/> where they enter (the setters, the MovementEvent entries, the decoder, the motion
/// commands), refused before anything changes. Retail takes any float: a run rate of zero or below makes the state
/// velocity's cap (4 × rate) negative, so a standing object's state velocity is 0 × (1 / 0) = NaN
/// (<c>CMotionInterp::get_state_velocity</c>, acclient.c:343538), and the next leave-ground handed that NaN to
/// <c>set_local_velocity</c>; a speed of 3e38 overflows 4 × speed to infinity and gives the same NaN.
/// </summary>
public class RunRateAndSpeedDomainTests
{
    // A remote creature (its weenie does not give a run rate: the interpreter's MyRunRate is used) standing on flat ground.
    private static (PhysicsWorld World, PhysicsObj Obj, MotionInterp Mi) Remote()
    {
        PhysicsWorld world = MoveToScene.FlatWorld();
        PhysicsObj obj = MoveToScene.Creature(world, 5, RemoteCreatureWeenie.Creature, new Vector3(100f, 100f, 20f));
        MotionInterp mi = MovementManager.Of(obj).GetOrCreateMotionInterpreter();
        SweepScene.Run(world, 2);
        return (world, obj, mi);
    }

    private static InterpretedMotionState Running(float speed) =>
        new() { ForwardCommand = MotionCommand.RunForward, ForwardSpeed = speed };

    [Theory]
    [InlineData(-1f)]
    [InlineData(0f)]
    [InlineData(101f)]
    public void TypeZeroState_RunningAtAnOutOfDomainRate_IsRefused_AndAReadyAfterwardsStandsStill(float speed)
    {
        (_, PhysicsObj obj, MotionInterp mi) = Remote();
        Assert.Throws<ArgumentException>(() => MovementEvent.ApplyInterpretedMotion(obj, Running(speed)));
        Assert.Throws<ArgumentException>(() => MovementManager.Of(obj).MoveToInterpretedState(Running(speed)));
        Assert.Throws<ArgumentException>(() => mi.MoveToInterpretedState(Running(speed)));
        Assert.Equal(MotionCommand.Ready, mi.InterpretedState.ForwardCommand);
        Assert.Equal(1f, mi.MyRunRate);

        // The sequence, then Ready: with the rate kept at 1 a standing object's state velocity is exactly zero
        // (x = y = 0, the cap 4 × 1 = 4 is not exceeded).
        Assert.True(MovementEvent.ApplyInterpretedMotion(obj, new InterpretedMotionState()));
        Assert.Equal(Vector3.Zero, mi.StateVelocity);
    }

    [Fact]
    public void TypeZeroEvent_RunningAtMinusOne_IsRefusedByHandleMovementEvent_BeforeAnyStamp()
    {
        (_, PhysicsObj obj, MotionInterp mi) = Remote();
        var m = new MovementEventMessage { ObjectId = obj.Id, MovementTimestamp = 1 };
        m.State.ForwardCommand = MotionCommand.RunForward;
        m.State.ForwardSpeed = -1f;
        Assert.Throws<ArgumentException>(() => obj.HandleMovementEvent(m));
        Assert.Equal(MotionCommand.Ready, mi.InterpretedState.ForwardCommand);
        // The stamp was not taken: the same stamp with a good state is applied.
        m.State.ForwardSpeed = 2f;
        Assert.Equal(MovementEventResult.Applied, obj.HandleMovementEvent(m));
        Assert.Equal(MotionCommand.RunForward, mi.InterpretedState.ForwardCommand);
        Assert.Equal(2f, mi.MyRunRate);
    }

    [Theory]
    [InlineData(-1f)]
    [InlineData(0f)]
    [InlineData(1e38f)]
    [InlineData(100.00001f)]
    public void MoveToEvent_RunRateOutOfDomain_IsRefused_NothingChanges(float rate)
    {
        (PhysicsWorld world, PhysicsObj obj, MotionInterp mi) = Remote();
        foreach (MovementEventType type in new[] { MovementEventType.MoveToObject, MovementEventType.MoveToPosition })
        {
            var m = new MovementEventMessage
            {
                ObjectId = obj.Id, MovementTimestamp = 1, MovementType = type, RunRate = rate, TargetId = 0x50000009u,
                Origin = MoveToScene.At(100f, 150f),
            };
            Assert.Throws<ArgumentException>(() => obj.HandleMovementEvent(m));
        }

        Assert.Equal(1f, mi.MyRunRate);
        Assert.Null(MovementManager.Of(obj).MoveToManager);
        Assert.Throws<ArgumentException>(() => mi.MyRunRate = rate);
        Assert.Equal(1f, mi.MyRunRate);
        SweepScene.Run(world, 10);
        Assert.Equal(Vector3.Zero, mi.StateVelocity);
    }

    [Fact]
    public void MyRunRate_DomainEdges_AreAccepted()
    {
        (_, _, MotionInterp mi) = Remote();
        mi.MyRunRate = InputLimits.MaxRunRate;
        Assert.Equal(100f, mi.MyRunRate);
        mi.MyRunRate = float.Epsilon;
        Assert.Equal(float.Epsilon, mi.MyRunRate);
    }

    [Theory]
    [InlineData(3e38f)]
    [InlineData(-3e38f)]
    [InlineData(100.00001f)]
    public void DoMotion_AtAHugeSpeed_IsRefused_BeforeAnythingChanges(float speed)
    {
        (_, PhysicsObj obj, MotionInterp mi) = Remote();
        var p = new MovementParameters { Speed = speed };
        Assert.Throws<ArgumentException>(() => obj.DoMotion(MotionCommand.WalkForward, p));
        Assert.Throws<ArgumentException>(() => mi.DoMotion(MotionCommand.WalkForward, p));
        Assert.Throws<ArgumentException>(() => mi.DoInterpretedMotion(MotionCommand.WalkForward, p));
        Assert.Throws<ArgumentException>(() => mi.StopMotion(MotionCommand.WalkForward, p));
        Assert.Throws<ArgumentException>(() => mi.InterpretedState.ApplyMotion(MotionCommand.WalkForward, p));
        Assert.Throws<ArgumentException>(() => mi.RawState.ApplyMotion(MotionCommand.WalkForward, p));
        Assert.Throws<ArgumentException>(() => mi.InterpretedState.ForwardSpeed = speed);
        Assert.Throws<ArgumentException>(() => mi.RawState.TurnSpeed = speed);
        Assert.False(obj.LastMoveWasAutonomous);
        Assert.Equal(MotionCommand.Ready, mi.InterpretedState.ForwardCommand);
        Assert.Equal(MotionCommand.Ready, mi.RawState.ForwardCommand);
        Assert.Equal(1f, mi.InterpretedState.ForwardSpeed);
    }

    [Fact]
    public void DoMotion_AtTheLargestSpeed_WithTheRunKey_RunsAtSpeedTimesRate_AndLeavesTheGroundFinite()
    {
        // Speed 100 with the run key and run rate 2: apply_run_to_command makes a run at 2 × 100 = 200 (beyond the given
        // speeds' bound: the interpreter's own conversion is kept), capped by get_state_velocity to 4 × rate = 8 m/s.
        (PhysicsWorld world, PhysicsObj obj, MotionInterp mi) = Remote();
        mi.MyRunRate = 2f;
        var p = new MovementParameters { Speed = InputLimits.MaxMotionSpeed, HoldKeyToApply = HoldKey.Run };
        Assert.Equal(MotionError.None, obj.DoMotion(MotionCommand.WalkForward, p));
        Assert.Equal(MotionCommand.RunForward, mi.InterpretedState.ForwardCommand);
        Assert.Equal(200f, mi.InterpretedState.ForwardSpeed);
        Assert.Equal(new Vector3(0f, 8f, 0f), mi.StateVelocity);

        // Placed 5 m up: it leaves the ground with the state velocity (8 m/s forward, no jump): finite, and the ticks run.
        Position up = obj.Position;
        up.Frame.Origin += new Vector3(0f, 0f, 5f);
        obj.SetPosition(up, SetPositionFlags.Placement);
        Assert.True(float.IsFinite(obj.Velocity.Y));
        SweepScene.Run(world, 20);
        Assert.True(float.IsFinite(obj.Position.Frame.Origin.Y));
    }

    [Fact]
    public void HandEditedInterpretedState_RunningBackwardsAtARate_DoesNotBecomeTheRunRate()
    {
        // A client edits the interpreter's own state (each speed within ±100, so accepted) and re-applies it: retail would
        // take −1 as my_run_rate (apply_interpreted_movement, acclient.c:344146) and a Ready afterwards would stand at NaN.
        (PhysicsWorld world, PhysicsObj obj, MotionInterp mi) = Remote();
        mi.InterpretedState.ForwardCommand = MotionCommand.RunForward;
        mi.InterpretedState.ForwardSpeed = -1f;
        mi.ApplyCurrentMovement(false, false);
        Assert.Equal(1f, mi.MyRunRate);
        Assert.True(MovementEvent.ApplyInterpretedMotion(obj, new InterpretedMotionState()));
        Assert.Equal(Vector3.Zero, mi.StateVelocity);

        // The next leave-ground takes a finite velocity, and SetPosition does not throw.
        Position up = obj.Position;
        up.Frame.Origin += new Vector3(0f, 0f, 5f);
        obj.SetPosition(up, SetPositionFlags.Placement);
        Assert.Equal(Vector3.Zero, obj.Velocity);
        SweepScene.Run(world, 5);
    }

    [Fact]
    public void AddAction_NaNSpeed_IsRefused_AndTheStateAppliesCleanly()
    {
        // Item 5: the action's speed was not checked, so applying the state ran its movement (RunForward) and only then threw
        // on the action. Now the action is refused where it enters, and the state applies whole.
        (_, PhysicsObj obj, MotionInterp mi) = Remote();
        InterpretedMotionState s = Running(2f);
        Assert.Throws<ArgumentException>(() => s.AddAction((MotionCommand)0x10000057u, float.NaN, 1, false));
        Assert.Throws<ArgumentException>(() => s.Actions.Add(new ActionNode((MotionCommand)0x10000057u, 1e30f, 1, false)));
        Assert.Throws<ArgumentException>(() => mi.RawState.AddAction((MotionCommand)0x10000057u, float.PositiveInfinity, 1, false));
        Assert.Equal(0, s.Actions.Count);
        Assert.Equal(0, mi.RawState.Actions.Count);
        Assert.True(MovementEvent.ApplyInterpretedMotion(obj, s));
        Assert.Equal(MotionCommand.RunForward, mi.InterpretedState.ForwardCommand);
    }

    [Fact]
    public void Decoder_RunRateOrSpeedOutOfDomain_IsANamedFormatError()
    {
        var m = new MovementEventMessage();
        byte[] runningBackwards = MovementEventBytes.Body(1, 0, false, MovementEventBytes.Forward(0x3D, 7, -1f));
        Assert.Contains("run rate", Assert.Throws<RetailDataFormatException>(() => MovementEventDecoder.Decode(runningBackwards, m)).Reason,
            StringComparison.Ordinal);
        // A walk (index 5, 0x45000005) at 1e30: beyond ±100.
        byte[] hugeWalk = MovementEventBytes.Body(1, 0, false, MovementEventBytes.Forward(0x3D, 5, 1e30f));
        Assert.Contains("forward speed", Assert.Throws<RetailDataFormatException>(() => MovementEventDecoder.Decode(hugeWalk, m)).Reason,
            StringComparison.Ordinal);
        // A walk backwards at −1 is a speed, not a rate: decoded.
        MovementEventDecoder.Decode(MovementEventBytes.Body(1, 0, false, MovementEventBytes.Forward(0x3D, 5, -1f)), m);
        Assert.Equal(-1f, m.State.ForwardSpeed);

        // Type 7 with run rate 0 (the last four bytes).
        byte[] body = MovementEventBytes.Body(1, 0, false, new RetailDataWriter().Byte(7).Byte(0).UInt16(0x3D)
            .UInt32(0xA9B3000Cu).Single(10f).Single(20f).Single(94f)
            .UInt32(0x1EE4Fu).Single(0.6f).Single(0f).Single(float.MaxValue).Single(2f).Single(15f).Single(0f)
            .Single(0f).ToArray());
        Assert.Contains("run rate", Assert.Throws<RetailDataFormatException>(() => MovementEventDecoder.Decode(body, m)).Reason,
            StringComparison.Ordinal);
    }
    private sealed class NegativeRateWeenie : IMotionWeenie
    {
        public bool IsThePlayer => false;
        public bool IsCreature => true;
        public bool IsPlayer => false;
        public bool IsImpenetrable => false;
        public bool IsPK => false;
        public bool IsPKLite => false;

        public bool InqRunRate(out float rate)
        {
            rate = -1f;
            return true;
        }

        public bool InqJumpVelocity(float extent, out float vz)
        {
            vz = float.NaN;
            return true;
        }

        public bool CanJump(float extent) => true;

        public bool JumpStaminaCost(float extent, out int cost)
        {
            cost = 0;
            return true;
        }
    }

    [Fact]
    public void AClientsWeenieWithANegativeRate_LeavingTheGround_DoesNotThrow_AndKeepsTheVelocity()
    {
        // The one source of a non-finite leave-ground velocity the domains cannot refuse: a client's own weenie (rate −1: a
        // standing object's state velocity 0 / 0; jump velocity NaN). The velocity is not applied; SetPosition does not throw.
        PhysicsWorld world = MoveToScene.FlatWorld();
        PhysicsObj obj = MoveToScene.Creature(world, 5, new NegativeRateWeenie(), new Vector3(100f, 100f, 20f));
        MovementManager.Of(obj);
        SweepScene.Run(world, 2);
        Position up = obj.Position;
        up.Frame.Origin += new Vector3(0f, 0f, 5f);
        Assert.Equal(SetPositionError.Ok, obj.SetPosition(up, SetPositionFlags.Placement));
        Assert.Equal(Vector3.Zero, obj.Velocity);
        SweepScene.Run(world, 10);
        Assert.True(float.IsFinite(obj.Position.Frame.Origin.Z));
    }
}
