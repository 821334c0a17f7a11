using System.Numerics;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

// The conversions (adjust_motion, apply_run_to_command) and get_state_velocity, driven through DoMotion as the player's
// commands arrive. The objects have no GRAVITY, so contact_allows_move lets every motion start.
public class MotionInterpVelocityTests
{
    [Fact]
    public void Walk_StateVelocityIs312_AndTheTableWalks()
    {
        var (_, mm, mi, table) = MotionFixture.Create(new PlayerWeenie { RunSkill = 200 });
        Assert.Equal(MotionError.None, mm.DoMotion(MotionCommand.WalkForward, MotionFixture.Params()));
        // No hold key: WalkForward at speed 1; y = (float)(3.12f * 1.0) = 3.12f.
        Assert.Equal(MotionCommand.WalkForward, mi.InterpretedState.ForwardCommand);
        Assert.Equal(1f, mi.InterpretedState.ForwardSpeed);
        Assert.Equal(new Vector3(0f, 3.12f, 0f), mi.StateVelocity);
        Assert.Equal(new Vector3(0f, 3.12f, 0f), table.Velocity);
        Assert.Equal(MotionCommand.WalkForward, mi.RawState.ForwardCommand);
    }

    [Fact]
    public void Run_AtRunRate1_Is4()
    {
        // Run skill 0: GetRunRate = (0 + 4) / 4 = 1. WalkForward with the run key -> RunForward at 1 * 1 = 1; y = 4 * 1 = 4;
        // the clamp is 4 * rate = 4 (not exceeded).
        var (_, mm, mi, table) = MotionFixture.Create(new PlayerWeenie { RunSkill = 0 });
        Assert.Equal(MotionError.None, mm.DoMotion(MotionCommand.WalkForward, MotionFixture.Params(1f, HoldKey.Run)));
        Assert.Equal(MotionCommand.RunForward, mi.InterpretedState.ForwardCommand);
        Assert.Equal(1f, mi.InterpretedState.ForwardSpeed);
        Assert.Equal(new Vector3(0f, 4f, 0f), mi.StateVelocity);
        Assert.Equal(new Vector3(0f, 4f, 0f), table.Velocity);
        // The raw state keeps the command as given (WalkForward) and the run key as the current hold key.
        Assert.Equal(MotionCommand.WalkForward, mi.RawState.ForwardCommand);
        Assert.Equal(HoldKey.Run, mi.RawState.CurrentHoldKey);
    }

    [Fact]
    public void Run_AtRunRate2Point8256_Is4TimesTheRate()
    {
        // Speed = (float)(2.8256f * 1.0) = 2.8256f; y = (float)(4.0 * 2.8256f), exact since 4 is a power of two; the clamp
        // 4 * 2.8256f is the same value, so nothing is scaled.
        var (_, mm, mi, table) = MotionFixture.Create(new FixedRateWeenie(2.8256f));
        mm.DoMotion(MotionCommand.WalkForward, MotionFixture.Params(1f, HoldKey.Run));
        Assert.Equal(2.8256f, mi.InterpretedState.ForwardSpeed);
        Assert.Equal(new Vector3(0f, 4f * 2.8256f, 0f), mi.StateVelocity);
        Assert.Equal(4f * 2.8256f, table.Velocity.Y);
        Assert.Equal(4.0 * 2.8256f, mi.MaxSpeed);
    }

    [Fact]
    public void StateVelocity_WithoutWeenie_IsClampedTo4()
    {
        // No weenie: rate 1, clamp 4. A received run at 2.8256 (y = 11.3024) is scaled by 4 / 11.3024 to y = 4 (float).
        var (_, mm, mi, _) = MotionFixture.Create(null);
        var s = new InterpretedMotionState { ForwardCommand = MotionCommand.RunForward, ForwardSpeed = 2.8256f };
        mm.MoveToInterpretedState(s);
        Vector3 v = mi.StateVelocity;
        Assert.Equal(4f, v.Y, 5);
        Assert.Equal(0f, v.X);
    }

    [Fact]
    public void Backwards_IsWalkForwardAtMinus065()
    {
        // WalkBackwards -> WalkForward at (float)(-0.65f * 1) = -0.65f; y = (float)(3.12f * -0.65f) = -2.0279999 m/s.
        var (_, mm, mi, table) = MotionFixture.Create(new PlayerWeenie { RunSkill = 200 });
        mm.DoMotion(MotionCommand.WalkBackwards, MotionFixture.Params());
        Assert.Equal(MotionCommand.WalkForward, mi.InterpretedState.ForwardCommand);
        Assert.Equal(-0.65f, mi.InterpretedState.ForwardSpeed);
        Assert.Equal(-2.0279998779296875f, mi.StateVelocity.Y);
        Assert.Equal(-2.0279998779296875f, table.Velocity.Y);
        Assert.Equal(MotionCommand.WalkBackwards, mi.RawState.ForwardCommand);
    }

    [Fact]
    public void Backwards_WithRunKey_StaysAWalk_AtRateTimesMinus065()
    {
        // apply_run_to_command: speed -0.65 is not > 0, so no run; speed = (float)(2.375 * -0.65f) = -1.54375;
        // y = (float)(3.12f * -1.54375f) = -4.8165 (below the 9.5 clamp).
        var (_, mm, mi, _) = MotionFixture.Create(new PlayerWeenie { RunSkill = 200 });
        mm.DoMotion(MotionCommand.WalkBackwards, MotionFixture.Params(1f, HoldKey.Run));
        Assert.Equal(MotionCommand.WalkForward, mi.InterpretedState.ForwardCommand);
        Assert.Equal(-1.54375f, mi.InterpretedState.ForwardSpeed, 6);
        Assert.Equal(-4.8165, mi.StateVelocity.Y, 4);
    }

    [Fact]
    public void SidestepRight_And_Left_Are125TimesTheRatio()
    {
        // adjust_motion: speed * 1.2479999542 = 1.2479999f (rounded); x = (float)(1.25 * 1.2479999f) = 1.5599999 m/s.
        var (_, mm, mi, table) = MotionFixture.Create(new PlayerWeenie { RunSkill = 200 });
        mm.DoMotion(MotionCommand.SideStepRight, MotionFixture.Params());
        Assert.Equal(MotionCommand.SideStepRight, mi.InterpretedState.SidestepCommand);
        Assert.Equal(1.247999906539917f, mi.InterpretedState.SidestepSpeed);
        Assert.Equal(1.559999942779541f, mi.StateVelocity.X);
        Assert.Equal(1.559999942779541f, table.Velocity.X);

        // Left: SideStepRight at -1, then * ratio: -1.2479999f; x = -1.5599999.
        mm.StopMotion(MotionCommand.SideStepRight, MotionFixture.Params());
        mm.DoMotion(MotionCommand.SideStepLeft, MotionFixture.Params());
        Assert.Equal(MotionCommand.SideStepRight, mi.InterpretedState.SidestepCommand);
        Assert.Equal(-1.247999906539917f, mi.InterpretedState.SidestepSpeed);
        Assert.Equal(-1.559999942779541f, mi.StateVelocity.X);
        Assert.Equal(MotionCommand.SideStepLeft, mi.RawState.SidestepCommand);
    }

    [Fact]
    public void Sidestep_WithRunKey_IsClampedTo3()
    {
        // Rate 2.8256: 1.2479999f * 2.8256 = 3.5264 > 3 -> speed 3; x = 1.25 * 3 = 3.75.
        var (_, mm, mi, _) = MotionFixture.Create(new FixedRateWeenie(2.8256f));
        mm.DoMotion(MotionCommand.SideStepLeft, MotionFixture.Params(1f, HoldKey.Run));
        Assert.Equal(-3f, mi.InterpretedState.SidestepSpeed);
        Assert.Equal(-3.75f, mi.StateVelocity.X);
    }

    [Fact]
    public void Turn_IsHalfPiPerSecond_15TimesWithRunKey_LeftIsNegativeSpeed()
    {
        // TurnRight at 1: omega.z = (float)(1 * -(double)1.5f) = -1.5 rad/s (clockwise seen from above).
        var (_, mm, mi, table) = MotionFixture.Create(new PlayerWeenie { RunSkill = 200 });
        mm.DoMotion(MotionCommand.TurnRight, MotionFixture.Params());
        Assert.Equal(1f, mi.InterpretedState.TurnSpeed);
        Assert.Equal(new Vector3(0f, 0f, -1.5f), table.Omega);
        Assert.Equal(Vector3.Zero, mi.StateVelocity);

        // TurnLeft with the run key: TurnRight at -1, then * 1.5 = -1.5; omega.z = (float)(-1.5 * -1.5) = 2.25.
        mm.StopMotion(MotionCommand.TurnRight, MotionFixture.Params());
        Assert.Equal(Vector3.Zero, table.Omega);
        mm.DoMotion(MotionCommand.TurnLeft, MotionFixture.Params(1f, HoldKey.Run));
        Assert.Equal(MotionCommand.TurnRight, mi.InterpretedState.TurnCommand);
        Assert.Equal(-1.5f, mi.InterpretedState.TurnSpeed);
        Assert.Equal(2.25f, table.Omega.Z);
    }

    [Fact]
    public void HoldRun_TogglesWalkAndRun_AndIgnoresNoChange()
    {
        var (_, mm, mi, table) = MotionFixture.Create(new PlayerWeenie { RunSkill = 200 });
        mm.DoMotion(MotionCommand.WalkForward, MotionFixture.Params());
        Assert.Equal(MotionCommand.WalkForward, mi.InterpretedState.ForwardCommand);

        // set_hold_run(1): the raw WalkForward is re-interpreted with the run key: RunForward at 2.375; y = 9.5.
        mi.SetHoldRun(true, cancelMoveToOnChange: false);
        Assert.Equal(HoldKey.Run, mi.RawState.CurrentHoldKey);
        Assert.Equal(MotionCommand.RunForward, mi.InterpretedState.ForwardCommand);
        Assert.Equal(2.375f, mi.InterpretedState.ForwardSpeed);
        Assert.Equal(9.5f, table.Velocity.Y);
        Assert.Equal(2.375f, mi.MyRunRate);   // apply_interpreted_movement records a run's speed

        int pending = mi.PendingMotions.Count;
        mi.SetHoldRun(true, cancelMoveToOnChange: false);           // no change: nothing re-applied
        Assert.Equal(pending, mi.PendingMotions.Count);

        mi.SetHoldRun(false, cancelMoveToOnChange: false);
        Assert.Equal(HoldKey.None, mi.RawState.CurrentHoldKey);
        Assert.Equal(MotionCommand.WalkForward, mi.InterpretedState.ForwardCommand);
        Assert.Equal(1f, mi.InterpretedState.ForwardSpeed);
        Assert.Equal(3.12f, table.Velocity.Y);
    }

    [Fact]
    public void StopMotion_ReturnsToReady()
    {
        var (_, mm, mi, table) = MotionFixture.Create(new PlayerWeenie { RunSkill = 200 });
        mm.DoMotion(MotionCommand.WalkForward, MotionFixture.Params());
        Assert.Equal(MotionError.None, mm.StopMotion(MotionCommand.WalkForward, MotionFixture.Params()));
        Assert.Equal(MotionCommand.Ready, mi.InterpretedState.ForwardCommand);
        Assert.Equal(MotionCommand.Ready, mi.RawState.ForwardCommand);
        Assert.Equal(Vector3.Zero, table.Velocity);
    }

    [Fact]
    public void DoMotion_WithoutMotionTable_Fails7_AndRecordsNothing()
    {
        // CPartArray::DoInterpretedMotion returns 7 without a motion-table manager: nothing is queued or recorded.
        var (obj, mm, mi, _) = MotionFixture.Create(new PlayerWeenie());
        ((AcDream.Core.Physics.Objects.Parts.SimplePartArray)obj.PartArray!).MotionPlayer = null;
        Assert.Equal(MotionError.NoMotionTable, mm.DoMotion(MotionCommand.WalkForward, MotionFixture.Params()));
        Assert.Equal(MotionCommand.Ready, mi.InterpretedState.ForwardCommand);
        Assert.Equal(MotionCommand.Ready, mi.RawState.ForwardCommand);
    }

    [Fact]
    public void CompletedMotions_EmptyThePendingList()
    {
        // enter_default_state queues a Ready (twice: get_minterp then EnterDefaultState), each matched by the table's
        // initial cycle. DoMotion queues one more node; the table completes at once, and PerformMovement's
        // CheckForCompletedMotions pops one node per completion: 2 + 1 - 3 = 0.
        var (_, mm, mi, _) = MotionFixture.Create(new PlayerWeenie());
        Assert.Equal(2, mi.PendingMotions.Count);
        mm.DoMotion(MotionCommand.WalkForward, MotionFixture.Params());
        Assert.Equal(0, mi.PendingMotions.Count);
        Assert.False(mm.MotionsPending());
    }
}
