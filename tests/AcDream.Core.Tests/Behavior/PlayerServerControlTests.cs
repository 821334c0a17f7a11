using System;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Input;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Motion.Wire;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Tests.Retail;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// The player under server control (retail CommandInterpreter::LoseControlToServer, TakeControlFromServer, UseTime's
/// hand-back, HandleKeyboardCommand's release branch): a server MoveTo given to the player through
/// <see cref="ServerMessageHandler"/> takes control from the keys; a release then only updates the held-key lists; the next
/// press stops completely and takes control back; keys still held when the server's move ends take it back too.
/// </summary>
public sealed class PlayerServerControlTests
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

    // A MoveToPosition (type 7) for the player to (100, y) in landblock 0xA9B4, retail's default move-to parameters, run
    // rate 1, not autonomous (the server's own move).
    private static byte[] MoveTo(uint id, ushort stamp, ushort serverControl, float y) =>
        MovementEventBytes.Body(stamp, serverControl, false, new RetailDataWriter().Byte(7).Byte(0).UInt16(0x3D)
            .UInt32(LandDefs.OutdoorCellId(0xA9B4FFFF, 100f, y)).Single(100f).Single(y).Single(0f)
            .UInt32(0x1EE0Fu).Single(0.6f).Single(0f).Single(float.MaxValue).Single(1f).Single(15f).Single(0f)
            .Single(1f).ToArray(), id);

    private static (WalkingPlayerScene S, PlayerInput Input, ServerMessageHandler Handler) Scene()
    {
        var s = new WalkingPlayerScene(new Vector3(100f, 20f, 0f));
        var input = new PlayerInput(s.Player);
        var h = new ServerMessageHandler(s.World) { PlayerId = s.Player.Id, PlayerControl = input };
        return (s, input, h);
    }

    [Fact]
    public void KeyRelease_UnderServerControl_OnlyUpdatesTheLists_TheServersMoveGoesOn_ThePressTakesControlBack()
    {
        var (s, input, h) = Scene();
        double now = 0;
        input.KeyDown(MovementKeys.Forward);
        Run(s, ref now, 0.5);
        Assert.Equal(ServerMessageResult.Applied, h.HandleMessage(0xF74C, MoveTo(s.Player.Id, 1, 1, 60f)));
        Assert.True(input.ControlledByServer);
        Assert.True(s.Player.IsMovingTo());
        // W up: the list loses it, nothing is sent, the move-to goes on.
        input.KeyUp(MovementKeys.Forward);
        Assert.Equal(MovementKeys.None, input.HeldKeys);
        Assert.True(s.Player.IsMovingTo());
        float y0 = s.Player.Position.Frame.Origin.Y;
        Run(s, ref now, 1.0);
        Assert.True(s.Player.IsMovingTo());
        Assert.True(s.Player.Position.Frame.Origin.Y > y0 + 1f);
        // A press: stop completely (the move-to is cancelled), control back, the key's command applies.
        input.KeyDown(MovementKeys.TurnLeft);
        Assert.False(input.ControlledByServer);
        Assert.False(s.Player.IsMovingTo());
        MotionInterp mi = s.Movement.GetOrCreateMotionInterpreter();
        Assert.Equal(MotionCommand.TurnLeft, mi.RawState.TurnCommand);
        Assert.Equal(MotionCommand.Ready, mi.InterpretedState.ForwardCommand);
        Assert.True(s.Player.LastMoveWasAutonomous);
    }

    [Fact]
    public void WithoutServerControl_TheSameReleaseStopsTheWalkAndEndsTheMoveTo()
    {
        // The behaviour before the port (and of a client that does not tell the input): the release sends
        // StopMotion(WalkForward), which cancels the server's move.
        var (s, input, h) = Scene();
        h.PlayerControl = null;
        double now = 0;
        input.KeyDown(MovementKeys.Forward);
        Run(s, ref now, 0.5);
        Assert.Equal(ServerMessageResult.Applied, h.HandleMessage(0xF74C, MoveTo(s.Player.Id, 1, 1, 60f)));
        Assert.False(input.ControlledByServer);
        Assert.True(s.Player.IsMovingTo());
        input.KeyUp(MovementKeys.Forward);
        Assert.False(s.Player.IsMovingTo());
    }

    [Fact]
    public void KeysHeldWhenTheServersMoveEnds_TakeControlBack_AtUseTime()
    {
        var (s, input, h) = Scene();
        double now = 0;
        input.KeyDown(MovementKeys.Forward);
        // A MoveTo 2 m ahead while W is held: the server's move runs, W stays in the list.
        float target = s.Player.Position.Frame.Origin.Y + 2f;
        Assert.Equal(ServerMessageResult.Applied, h.HandleMessage(0xF74C, MoveTo(s.Player.Id, 1, 1, target)));
        input.UseTime();
        Assert.True(input.ControlledByServer); // still moving to
        for (int i = 0; i < 100 && s.Player.IsMovingTo(); i++)
        {
            Run(s, ref now, 0.05);
        }

        Assert.False(s.Player.IsMovingTo());
        Run(s, ref now, 0.5); // the move-to's last motions settle
        input.UseTime();
        Assert.False(input.ControlledByServer);
        Assert.Equal(MotionCommand.WalkForward, s.Movement.GetOrCreateMotionInterpreter().InterpretedState.ForwardCommand);
        float y = s.Player.Position.Frame.Origin.Y;
        Run(s, ref now, 1.0);
        Assert.Equal(y + WalkingPlayerScene.WalkSpeed, s.Player.Position.Frame.Origin.Y, 1);
    }

    [Fact]
    public void AutonomyLevel_DecidesWhetherTheServersPositionsAreUsed_AndWhetherControlIsLost()
    {
        var (s, input, _) = Scene();
        Assert.Equal(2u, input.AutonomyLevel);
        Assert.False(input.UsePositionFromServer);
        Assert.False(input.SetAutonomyLevel(3));
        Assert.Equal(2u, input.AutonomyLevel);
        Assert.True(input.SetAutonomyLevel(1));
        Assert.True(input.UsePositionFromServer);
        Assert.True(input.SetAutonomyLevel(0));
        input.LoseControlToServer();
        Assert.False(input.ControlledByServer); // level 0: retail never sets controlled_by_server
        Assert.True(input.SetAutonomyLevel(2));
        input.LoseControlToServer();
        Assert.True(input.ControlledByServer);
        Assert.NotNull(s);
    }
}
