using System;
using AcDream.Core.Physics.Motion;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class MotionConstantsTests
{
    private static uint Bits(float f) => BitConverter.SingleToUInt32Bits(f);

    [Fact]
    public void AnimationSpeeds_AreRetailValues_ByValueAndBits()
    {
        // get_state_velocity (acclient.c:343538): 1.25 * sidestep, 3.1199999 * walk, 4.0 * run.
        Assert.Equal(4.0, MotionInterp.RunAnimSpeed);
        Assert.Equal(0x4010000000000000ul, BitConverter.DoubleToUInt64Bits(MotionInterp.RunAnimSpeed));
        Assert.Equal(3.12f, MotionInterp.WalkAnimSpeed);
        Assert.Equal(0x4047AE14u, Bits(MotionInterp.WalkAnimSpeed));
        Assert.Equal(1.25, MotionInterp.SidestepAnimSpeed);
        // adjust_motion (acclient.c:343745): -0.64999998 = -0.65f.
        Assert.Equal(0.65f, MotionInterp.BackwardsFactor);
        Assert.Equal(0x3F266666u, Bits(MotionInterp.BackwardsFactor));
        Assert.Equal(0.5, MotionInterp.SidestepFactor);
        // apply_run_to_command (acclient.c:343438): clamp 3.0, turn 1.5.
        Assert.Equal(3.0, MotionInterp.MaxSidestepAnimRate);
        Assert.Equal(1.5, MotionInterp.RunTurnFactor);
        // get_jump_v_z (acclient.c:343342): 10.0 with no weenie.
        Assert.Equal(10.0, MotionInterp.NoWeenieJumpVelocity);
    }

    [Fact]
    public void SidestepSpeedRatio_Is312fOver125TimesHalf_InDouble()
    {
        // 3.12f = 3.119999885559082; / 1.25 = 2.4959999084472656; * 0.5 = 1.2479999542236328.
        Assert.Equal(1.2479999542236328, MotionInterp.SidestepSpeedRatio);
        Assert.Equal(BitConverter.DoubleToUInt64Bits(3.119999885559082 / 1.25 * 0.5),
            BitConverter.DoubleToUInt64Bits(MotionInterp.SidestepSpeedRatio));
    }

    [Fact]
    public void TurnAnimSpeed_IsTheHumanoidTablesOmega()
    {
        // Data-derived: the humanoid motion table 0x09000001's TurnRight modifier carries omega.z = -1.5 rad/s (the one
        // reading of the installed data found); no client constant exists (add_motion acclient.c:337430 multiplies the
        // motion data's omega by the speed).
        Assert.Equal(1.5f, SpeedOnlyMotionPlayer.TurnAnimSpeed);
        Assert.Equal(0x3FC00000u, Bits(SpeedOnlyMotionPlayer.TurnAnimSpeed));
    }

    [Fact]
    public void JumpAndRunConstants_AreRetailValues()
    {
        // GetJumpHeight (acclient.c:713805): floor 0.34999999 = 0.35f; InqJumpVelocity: sqrt(h * 19.6).
        Assert.Equal(0x3EB33333u, Bits(MovementSystem.MinJumpHeight));
        Assert.Equal(19.6, MovementSystem.TwiceGravity);
        // GetRunRate (acclient.c:713789): skill 800 -> 18.0 / 4.0.
        Assert.Equal(800.0, MovementSystem.TopRunSkill);
        Assert.Equal(4.5, MovementSystem.TopRunRate);
    }

    [Fact]
    public void MovementParameters_DefaultConstructor_IsRetails()
    {
        // MovementParameters::MovementParameters (acclient.c:339436): distance_to_object 0x3F19999A (0.6f),
        // fail_distance 0x7F7FFFFF, speed 1.0, walk_run_threshhold 0x41700000 (15f), bitfield 0x1EE0F.
        var p = new MovementParameters();
        Assert.Equal(0x3F19999Au, Bits(p.DistanceToObject));
        Assert.Equal(0x7F7FFFFFu, Bits(p.FailDistance));
        Assert.Equal(1f, p.Speed);
        Assert.Equal(0x41700000u, Bits(p.WalkRunThreshold));
        Assert.Equal(0f, p.MinDistance);
        Assert.Equal(0f, p.DesiredHeading);
        Assert.Equal(0u, p.ContextId);
        Assert.Equal(HoldKey.Invalid, p.HoldKeyToApply);
        Assert.Equal(0x1EE0Fu, (uint)p.Flags);
        Assert.True((p.Flags & MovementParameterFlags.ModifyInterpretedState) != 0);
        Assert.True((p.Flags & MovementParameterFlags.Autonomous) == 0);
    }

    [Fact]
    public void CommandIds_AreRetailValues()
    {
        Assert.Equal(0x41000003u, (uint)MotionCommand.Ready);
        Assert.Equal(0x45000005u, (uint)MotionCommand.WalkForward);
        Assert.Equal(0x45000006u, (uint)MotionCommand.WalkBackwards);
        Assert.Equal(0x44000007u, (uint)MotionCommand.RunForward);
        Assert.Equal(0x40000015u, (uint)MotionCommand.Falling);
        Assert.Equal(0x6500000Du, (uint)MotionCommand.TurnRight);
        Assert.Equal(0x6500000Eu, (uint)MotionCommand.TurnLeft);
        Assert.Equal(0x6500000Fu, (uint)MotionCommand.SideStepRight);
        Assert.Equal(0x65000010u, (uint)MotionCommand.SideStepLeft);
        Assert.Equal(0x8000003Du, (uint)MotionCommand.NonCombat);
    }
}
