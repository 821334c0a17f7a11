namespace AcDream.Core.Physics.Motion.Wire;

/// <summary>
/// What the server's messages tell the player's command interpreter (retail's <c>CommandInterpreter</c>, which the
/// SmartBox calls): <see cref="Input.PlayerInput"/> implements it; a client with its own input implements it itself.
/// Set it as <see cref="ServerMessageHandler.PlayerControl"/>.
/// </summary>
public interface IPlayerControl
{
    /// <summary>Whether the player follows the server's positions and vectors (retail
    /// <c>CommandInterpreter::UsePositionFromServer</c>, acclient.c:717528: the autonomy level is not 2). False: the
    /// client moves the player itself and the server's echoes of it are ignored.</summary>
    bool UsePositionFromServer { get; }

    /// <summary>The server moved the player by a MovementEvent (a MoveTo, a non-autonomous motion): the interpreter gives
    /// control to the server (retail <c>CommandInterpreter::LoseControlToServer</c>, acclient.c:716831, called by
    /// <c>ACSmartBox</c> when <c>CPhysics::SetObjectMovement</c> answers 1).</summary>
    void LoseControlToServer();

    /// <summary>The server forced the player's position (a blip): retail's SmartBox then has the interpreter report the
    /// player's position at once.</summary>
    void PositionForcedByServer();

    /// <summary>The player was teleported (retail <c>CommandInterpreter::PlayerTeleported</c>, acclient.c:716923, from
    /// <c>SmartBox::PlayerPositionUpdated</c>).</summary>
    void PlayerTeleported();
}
