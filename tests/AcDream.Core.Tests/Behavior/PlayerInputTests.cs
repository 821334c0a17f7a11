using System;
using System.Numerics;
using AcDream.Core.Physics.Input;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// PlayerInput: key transitions in, retail's command-interpreter commands (the raw motion state records what was sent) and
/// the resulting motion out. The player: RunSkill 200 (run rate (200 / 400 · 11 + 4) / 4 = 2.375, running 4 · 2.375 = 9.5 m/s),
/// JumpSkill 100, starting at (100, 20) facing north on flat ground. The world ticks every 0.05 s (always past the 1/30 s gate).
/// </summary>
public sealed class PlayerInputTests
{
    private static void Run(WalkingPlayerScene s, ref double now, double seconds)
    {
        int n = (int)Math.Round(seconds / 0.05);
        for (int i = 0; i < n; i++)
        {
            now += 0.05;
            s.World.Tick(now);
        }
    }

    [Fact]
    public void ForwardAndRun_HeldOneSecond_RunsNineAndAHalfMetres()
    {
        // Forward down: DoMotion(WalkForward) with hold key Invalid; Run down: set_hold_run(1): the walk becomes RunForward at
        // the run rate 2.375 (apply_run_to_command), 4.0 · 2.375 = 9.5 m/s. One second: y = 20 + 9.5 = 29.5.
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        var input = new PlayerInput(s.Player);
        input.KeyDown(MovementKeys.Forward);
        input.KeyDown(MovementKeys.Run);
        MotionInterp mi = s.Movement.GetOrCreateMotionInterpreter();
        Assert.Equal(MotionCommand.WalkForward, mi.RawState.ForwardCommand);
        Assert.Equal(HoldKey.Run, mi.RawState.CurrentHoldKey);
        Assert.Equal(MotionCommand.RunForward, mi.InterpretedState.ForwardCommand);
        Assert.Equal(2.375f, mi.InterpretedState.ForwardSpeed);
        double now = 0;
        Run(s, ref now, 1.0);
        Assert.Equal(29.5f, s.Player.Position.Frame.Origin.Y, 3);
        Assert.Equal(100f, s.Player.Position.Frame.Origin.X, 4);
        Assert.Equal(MotionError.None, input.LastError);
    }

    [Fact]
    public void Forward_ThenBackward_NewestWins_ReleasingItReturnsToTheOther()
    {
        // Both keys are in the substate list; the newest is the head. Backward: WalkBackwards, walked as WalkForward at -0.65
        // (adjust_motion): 3.12 · 0.65 = 2.028 m/s south. Releasing the head hands back to Forward (DoMotion(WalkForward));
        // releasing a key that is not the head sends nothing (NukeCommand).
        var s = new WalkingPlayerScene(new Vector3(100f, 100f, 0f));
        var input = new PlayerInput(s.Player);
        MotionInterp mi = s.Movement.GetOrCreateMotionInterpreter();
        double now = 0;
        input.KeyDown(MovementKeys.Forward);
        Run(s, ref now, 1.0);                                   // +3.12
        input.KeyDown(MovementKeys.Backward);
        Assert.Equal(MotionCommand.WalkBackwards, mi.RawState.ForwardCommand);
        Run(s, ref now, 1.0);                                   // -2.028
        input.KeyUp(MovementKeys.Backward);
        Assert.Equal(MotionCommand.WalkForward, mi.RawState.ForwardCommand);
        Run(s, ref now, 1.0);                                   // +3.12
        Assert.Equal(100f + 3.12f - 2.028f + 3.12f, s.Player.Position.Frame.Origin.Y, 3);

        input.KeyDown(MovementKeys.Backward);
        input.KeyUp(MovementKeys.Forward);                      // not the head: nothing sent, still backwards
        Assert.Equal(MotionCommand.WalkBackwards, mi.RawState.ForwardCommand);
        input.KeyUp(MovementKeys.Backward);                     // the list is empty: StopMotion -> Ready
        Assert.Equal(MotionCommand.Ready, mi.RawState.ForwardCommand);
        float y = s.Player.Position.Frame.Origin.Y;
        Run(s, ref now, 0.5);
        Assert.Equal(y, s.Player.Position.Frame.Origin.Y, 4);
    }

    [Fact]
    public void StrafeRight_MovesEast_AtTheSidestepSpeed()
    {
        // SideStepRight at speed 1 becomes 1 · SidestepSpeedRatio = 3.12 / 1.25 · 0.5 = 1.248 (adjust_motion); its velocity is
        // SidestepAnimSpeed 1.25 · 1.248 = 1.56 m/s east (get_state_velocity). One second: x = 101.56.
        var s = new WalkingPlayerScene(new Vector3(100f, 100f, 0f));
        var input = new PlayerInput(s.Player);
        input.KeyDown(MovementKeys.StrafeRight);
        Assert.Equal(MotionCommand.SideStepRight, s.Movement.GetOrCreateMotionInterpreter().RawState.SidestepCommand);
        double now = 0;
        Run(s, ref now, 1.0);
        Assert.Equal(101.56f, s.Player.Position.Frame.Origin.X, 3);
        Assert.Equal(100f, s.Player.Position.Frame.Origin.Y, 3);
        input.KeyUp(MovementKeys.StrafeRight);
        Assert.Equal(MotionCommand.None, s.Movement.GetOrCreateMotionInterpreter().RawState.SidestepCommand);
    }

    [Fact]
    public void TurnRight_ThenTurnLeft_NewestTurnWins()
    {
        // The turn list: TurnRight then TurnLeft held, the left turn is in force; releasing it turns right again.
        var s = new WalkingPlayerScene(new Vector3(100f, 100f, 0f));
        var input = new PlayerInput(s.Player);
        MotionInterp mi = s.Movement.GetOrCreateMotionInterpreter();
        input.KeyDown(MovementKeys.TurnRight);
        Assert.Equal(MotionCommand.TurnRight, mi.RawState.TurnCommand);
        double now = 0;
        Run(s, ref now, 0.5);
        double h1 = s.Player.Position.Frame.Heading;
        Assert.InRange(h1, 1.0, 180.0);                          // turned clockwise
        input.KeyDown(MovementKeys.TurnLeft);
        Assert.Equal(MotionCommand.TurnLeft, mi.RawState.TurnCommand);
        Run(s, ref now, 0.5);
        Assert.Equal(0.0, s.Player.Position.Frame.Heading, 1);   // back to north at the same rate
        input.KeyUp(MovementKeys.TurnLeft);
        Assert.Equal(MotionCommand.TurnRight, mi.RawState.TurnCommand);
        input.KeyUp(MovementKeys.TurnRight);
        Assert.Equal(MotionCommand.None, mi.RawState.TurnCommand);
    }

    [Fact]
    public void RunByDefault_ForwardRuns_AndTheRunKeyWalks()
    {
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        var input = new PlayerInput(s.Player) { RunByDefault = true };
        MotionInterp mi = s.Movement.GetOrCreateMotionInterpreter();
        input.KeyDown(MovementKeys.Forward);
        Assert.Equal(MotionCommand.RunForward, mi.InterpretedState.ForwardCommand);
        input.KeyDown(MovementKeys.Run);
        Assert.Equal(MotionCommand.WalkForward, mi.InterpretedState.ForwardCommand);
        double now = 0;
        Run(s, ref now, 1.0);
        Assert.Equal(23.12f, s.Player.Position.Frame.Origin.Y, 3);
    }

    [Fact]
    public void RunByDefault_SetWhileTheRunKeyIsHeld_AppliesTheOptionAlone()
    {
        // Retail's option handler sends set_hold_run(option) alone (ACCmdInterp::RecvNotice_PlayerOptionChanged, 435916);
        // only the run key's own transitions send key XOR option (CommandInterpreter::SetHoldRun, 716977).
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        var input = new PlayerInput(s.Player);
        MotionInterp mi = s.Movement.GetOrCreateMotionInterpreter();
        input.KeyDown(MovementKeys.Forward);
        input.KeyDown(MovementKeys.Run);                         // 1 XOR 0: run
        Assert.Equal(MotionCommand.RunForward, mi.InterpretedState.ForwardCommand);
        input.RunByDefault = true;                               // set_hold_run(1): still running (key XOR option would walk)
        Assert.Equal(MotionCommand.RunForward, mi.InterpretedState.ForwardCommand);
        input.KeyUp(MovementKeys.Run);                           // 0 XOR 1: run
        Assert.Equal(MotionCommand.RunForward, mi.InterpretedState.ForwardCommand);
        input.KeyDown(MovementKeys.Run);                         // 1 XOR 1: walk
        Assert.Equal(MotionCommand.WalkForward, mi.InterpretedState.ForwardCommand);
        input.RunByDefault = false;                              // set_hold_run(0): walk, the key still held
        Assert.Equal(MotionCommand.WalkForward, mi.InterpretedState.ForwardCommand);
        input.KeyUp(MovementKeys.Run);                           // 0 XOR 0: walk
        Assert.Equal(MotionCommand.WalkForward, mi.InterpretedState.ForwardCommand);
        input.KeyDown(MovementKeys.Run);                         // 1 XOR 0: run
        Assert.Equal(MotionCommand.RunForward, mi.InterpretedState.ForwardCommand);
    }

    [Fact]
    public void Jump_HeldHalfASecond_JumpsWithExtentOneHalf()
    {
        // Jump down at t = 1 starts the power bar; up at t = 1.5: level (1.5 - 1) / 1 = 0.5, the extent. Jump skill 100 at
        // extent 0.5: h = (100 / 1400 · 22.2 + 0.05) · 0.5 = 0.8179 m (the quickstart's jump); the apex sampled every 0.05 s
        // is at most 9.8 · 0.025² / 2 = 0.0031 m short: top in [0.8148, 0.8180].
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        var input = new PlayerInput(s.Player);
        double now = 0;
        Run(s, ref now, 1.0);
        input.KeyDown(MovementKeys.Jump);
        Assert.Equal(MotionError.None, input.LastError);
        Run(s, ref now, 0.25);
        Assert.Equal(0.25, input.JumpCharge, 9);
        Run(s, ref now, 0.25);
        input.KeyUp(MovementKeys.Jump);
        Assert.Equal(MotionError.None, input.LastError);
        Assert.Equal(0.0, input.JumpCharge);
        Assert.Equal(4.0037f, s.Player.Velocity.Z, 3);         // launched at once: v_z = sqrt(19.6 h) = 4.0037 m/s
        float top = 0f;
        for (int i = 0; i < 30; i++)
        {
            now += 0.05;
            s.World.Tick(now);
            top = MathF.Max(top, s.Player.Position.Frame.Origin.Z);
        }

        Assert.InRange(top, 0.8148f, 0.8180f);
    }

    [Theory]
    [InlineData(0.0, 2.61916f)]  // pressed and released at once: level 0 < 0.001 gives MIN_JUMP_EXTENT, 0.0016 m: retail's floor 0.35 m
    [InlineData(0.3, 3.10129f)]  // extent 0.3: h = 0.490714 m
    [InlineData(2.0, 5.66216f)]  // a full bar: (2 - 0) / 1 clamps to 1: h = 1.635714 m
    public void Jump_Extent_IsThePowerBarLevel(double held, float vz)
    {
        // The extent is the bar's level; the launch speed shows it: jump skill 100 gives h = 1.635714 m · extent
        // (100 / 1400 · 22.2 + 0.05), at least MinJumpHeight 0.35 m (GetJumpHeight), and v_z = sqrt(19.6 h): the floor
        // sqrt(6.86) = 2.61916 m/s, extent 0.3 -> 3.10129, 1 -> 5.66216.
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        var input = new PlayerInput(s.Player);
        double now = 0;
        Run(s, ref now, 0.5);
        input.KeyDown(MovementKeys.Jump);
        s.World.SetCurrentTime(now + held);
        input.KeyUp(MovementKeys.Jump);
        Assert.Equal(MotionError.None, input.LastError);
        Assert.Equal(vz, s.Player.Velocity.Z, 3);
    }

    [Fact]
    public void SetHeldKeys_PerFrame_SendsTheSameAsEvents()
    {
        var a = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        var b = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        var ia = new PlayerInput(a.Player);
        var ib = new PlayerInput(b.Player);
        double now = 0;
        ia.KeyDown(MovementKeys.Forward);
        ia.KeyDown(MovementKeys.Run);
        ib.SetHeldKeys(MovementKeys.Forward | MovementKeys.Run);
        for (int i = 0; i < 20; i++)
        {
            now += 0.05;
            a.World.Tick(now);
            b.World.Tick(now);
        }

        ia.KeyUp(MovementKeys.Run);
        ia.KeyDown(MovementKeys.TurnLeft);
        ib.SetHeldKeys(MovementKeys.Forward | MovementKeys.TurnLeft);
        Assert.Equal(ia.HeldKeys, ib.HeldKeys);
        for (int i = 0; i < 20; i++)
        {
            now += 0.05;
            a.World.Tick(now);
            b.World.Tick(now);
        }

        Assert.Equal(a.Player.Position, b.Player.Position);
    }

    [Fact]
    public void ReleaseAll_Stands_StopsTurning_AndDropsTheRunKey()
    {
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        var input = new PlayerInput(s.Player);
        MotionInterp mi = s.Movement.GetOrCreateMotionInterpreter();
        input.SetHeldKeys(MovementKeys.Forward | MovementKeys.Run | MovementKeys.TurnRight | MovementKeys.StrafeLeft);
        input.ReleaseAll();
        Assert.Equal(MovementKeys.None, input.HeldKeys);
        Assert.Equal(MotionCommand.Ready, mi.RawState.ForwardCommand);
        Assert.Equal(MotionCommand.None, mi.RawState.TurnCommand);
        Assert.Equal(MotionCommand.None, mi.RawState.SidestepCommand);
        Assert.Equal(HoldKey.None, mi.RawState.CurrentHoldKey);
        input.KeyDown(MovementKeys.Forward);                     // the lists were cleared: a new press walks
        Assert.Equal(MotionCommand.WalkForward, mi.RawState.ForwardCommand);
    }

    [Fact]
    public void ReleaseAll_WhileChargingAJump_CancelsTheCharge()
    {
        // LoseKeyboardFocus (716868) calls the interpreter's vtable slot 20, the jump cancel (ACCmdInterp::FinishJump ->
        // ClientCombatSystem::FinishJump, 407624: jump_pending = 0, standing_longjump = 0), as Escape while charging does
        // (402170-402175): the jump key's later release finds no charge and jumps nothing.
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        var input = new PlayerInput(s.Player);
        MotionInterp mi = s.Movement.GetOrCreateMotionInterpreter();
        double now = 0;
        Run(s, ref now, 0.5);
        input.KeyDown(MovementKeys.Jump);
        Assert.True(mi.StandingLongJump);                         // charged standing still on the ground
        Run(s, ref now, 0.5);
        Assert.Equal(0.5, input.JumpCharge, 9);
        input.ReleaseAll();
        Assert.Equal(0.0, input.JumpCharge);
        Assert.False(mi.StandingLongJump);
        Assert.Equal(MovementKeys.None, input.HeldKeys);
        input.KeyUp(MovementKeys.Jump);                          // not held any more: nothing
        Run(s, ref now, 0.5);
        Assert.Equal(0f, s.Player.Position.Frame.Origin.Z);
        Assert.Equal(0f, s.Player.Velocity.Z);
        input.KeyDown(MovementKeys.Jump);                        // a new press charges from zero
        Run(s, ref now, 0.25);
        Assert.Equal(0.25, input.JumpCharge, 9);
    }

    [Theory]
    [InlineData(MovementKeys.None)]
    [InlineData(MovementKeys.Forward | MovementKeys.Run)]
    [InlineData((MovementKeys)0x100)]
    public void KeyDownOrUp_NotExactlyOneKey_Throws(MovementKeys key)
    {
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        var input = new PlayerInput(s.Player);
        Assert.Equal("key", Assert.Throws<ArgumentException>(() => input.KeyDown(key)).ParamName);
        Assert.Equal("key", Assert.Throws<ArgumentException>(() => input.KeyUp(key)).ParamName);
        Assert.Equal(MovementKeys.None, input.HeldKeys);
    }

    [Fact]
    public void Misuse_IsRefusedBeforeAnythingChanges()
    {
        Assert.Throws<ArgumentNullException>(() => new PlayerInput(null!));
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        var input = new PlayerInput(s.Player);
        Assert.Equal("keys", Assert.Throws<ArgumentException>(() => input.SetHeldKeys((MovementKeys)0x300)).ParamName);
        s.World.RemoveObject(s.Player);
        Assert.Throws<InvalidOperationException>(() => input.KeyDown(MovementKeys.Forward));
        Assert.Throws<InvalidOperationException>(() => input.SetHeldKeys(MovementKeys.Forward));
        Assert.Throws<InvalidOperationException>(() => new PlayerInput(s.Player));
        Assert.Equal(MovementKeys.None, input.HeldKeys);
    }
}
