using System;

namespace AcDream.Core.Physics.Input;

/// <summary>
/// The movement keys of a player's keyboard (retail's movement input actions, <c>ACCmdInterp::OnAction</c>, acclient.c:435950).
/// One bit per key: <see cref="PlayerInput.SetHeldKeys"/> takes any combination, <see cref="PlayerInput.KeyDown"/> and
/// <see cref="PlayerInput.KeyUp"/> exactly one.
/// </summary>
[Flags]
public enum MovementKeys
{
    /// <summary>No key.</summary>
    None = 0,

    /// <summary>Walk forward (input action 0x29: <c>WalkForward</c>, 0x45000005).</summary>
    Forward = 1 << 0,

    /// <summary>Walk backwards (input action 0x2A: <c>WalkBackwards</c>, 0x45000006).</summary>
    Backward = 1 << 1,

    /// <summary>Turn right (input action 0x2E: <c>TurnRight</c>, 0x6500000D).</summary>
    TurnRight = 1 << 2,

    /// <summary>Turn left (input action 0x2F: <c>TurnLeft</c>, 0x6500000E).</summary>
    TurnLeft = 1 << 3,

    /// <summary>Side-step (strafe) right (input action 0x2C: <c>SideStepRight</c>, 0x6500000F).</summary>
    StrafeRight = 1 << 4,

    /// <summary>Side-step (strafe) left (input action 0x2D: <c>SideStepLeft</c>, 0x65000010).</summary>
    StrafeLeft = 1 << 5,

    /// <summary>The run key, held (input action 0x32: <c>CommandInterpreter::SetHoldRun</c>): walking becomes running; with
    /// <see cref="PlayerInput.RunByDefault"/> it is the walk key instead.</summary>
    Run = 1 << 6,

    /// <summary>Jump (input action 0x31): down starts the charge (<c>ClientCombatSystem::CommenceJump</c>), up jumps with the
    /// charge reached (<c>ClientCombatSystem::DoJump</c>).</summary>
    Jump = 1 << 7,
}
