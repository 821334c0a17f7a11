using System;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Core.Physics.Input;

// The player under server control (retail CommandInterpreter: LoseControlToServer, TakeControlFromServer, SetAutonomyLevel,
// UsePositionFromServer, UseTime's hand-back): what the server's messages tell the input (IPlayerControl).
public sealed partial class PlayerInput : IPlayerControl
{
    private bool _controlledByServer;
    private uint _autonomyLevel = 2;

    /// <summary>The server moves the player (a MoveTo of a MovementEvent, a non-autonomous motion): key releases only
    /// update the held-key lists and the server's move goes on; the next key press (or, keys held, the end of the
    /// server's move) takes control back (retail <c>controlled_by_server</c>).</summary>
    public bool ControlledByServer => _controlledByServer;

    /// <summary>The player's autonomy level (retail <c>autonomy_level</c>, 0..2, default 2): at 2 the client moves the player
    /// itself and ignores the server's echoes of its position and vectors (<see cref="UsePositionFromServer"/> false); at 0
    /// the server never hands control to the keys.</summary>
    public uint AutonomyLevel => _autonomyLevel;

    /// <summary>Sets <see cref="AutonomyLevel"/>.</summary>
    /// <returns>False (nothing changed) for a level above 2.</returns>
    // retail: CommandInterpreter::SetAutonomyLevel (acclient.c:717568)
    public bool SetAutonomyLevel(uint level)
    {
        if (level > 2)
        {
            return false;
        }

        _autonomyLevel = level;
        return true;
    }

    /// <inheritdoc />
    // retail: CommandInterpreter::UsePositionFromServer (acclient.c:717528)
    public bool UsePositionFromServer => _autonomyLevel != 2;

    /// <summary>The server moved the player: the keys lose control (with an autonomy level above 0) and auto-run stops.</summary>
    // retail: CommandInterpreter::LoseControlToServer (acclient.c:716831)
    public void LoseControlToServer()
    {
        if (_autonomyLevel != 0)
        {
            _controlledByServer = true;
        }
    }

    /// <inheritdoc />
    public void PositionForcedByServer() => PositionDue = true;

    /// <summary>The player was teleported: auto-run stops and the motion is sent again.</summary>
    // retail: CommandInterpreter::PlayerTeleported (acclient.c:716923)
    public void PlayerTeleported() => SendMovementEvent();

    /// <summary>The server forced the position: the outbound side sends it at once.</summary>
    internal bool PositionDue { get; set; }

    /// <summary>Once per frame, before the world's tick: while the server controls the player and its move is over (no
    /// motion pending, no move-to), a held movement key takes control back.</summary>
    /// <exception cref="InvalidOperationException">The player was removed from its world.</exception>
    // retail: CommandInterpreter::UseTime (acclient.c:717594), the hand-back
    public void UseTime()
    {
        ThrowIfRemoved();
        if (_controlledByServer && !_movement.MotionsPending() && !_player.IsMovingTo()
            && (_substateList.Head != MotionCommand.None || _turnList.Head != MotionCommand.None
                || _sidestepList.Head != MotionCommand.None))
        {
            TakeControlFromServer();
        }
    }

    // retail: CommandInterpreter::TakeControlFromServer (acclient.c:716933; ACCmdInterp::TakeControlFromServer 435802 also
    // aborts the automatic attack, the client's): the player stops completely, stops interpolating, and the held keys apply.
    private void TakeControlFromServer()
    {
        if (!_controlledByServer || _autonomyLevel == 0)
        {
            return;
        }

        _controlledByServer = false;
        _player.LastMoveWasAutonomous = true;
        _player.StopCompletely();
        _player.StopInterpolating();
        SetHoldRun(_holdRun);
        ApplyHeldMovement();
    }

    // retail: CommandInterpreter::ApplyCurrentMovement (acclient.c:717026): the heads of the three lists, or stand.
    private void ApplyHeldMovement()
    {
        MotionCommand substate = _substateList.Head;
        MovePlayer(substate != MotionCommand.None ? substate : MotionCommand.Ready, start: true);
        MotionCommand turn = _turnList.Head;
        if (turn != MotionCommand.None)
        {
            MovePlayer(turn, start: true);
        }
        else
        {
            MovePlayer(MotionCommand.SideStepRight, start: false);
            MovePlayer(MotionCommand.TurnRight, start: false);
        }

        MotionCommand side = _sidestepList.Head;
        if (side != MotionCommand.None)
        {
            MovePlayer(side, start: true);
        }
        else
        {
            MovePlayer(MotionCommand.SideStepRight, start: false);
        }
    }
}
