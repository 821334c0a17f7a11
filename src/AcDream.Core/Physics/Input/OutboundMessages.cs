using System;

namespace AcDream.Core.Physics.Input;

/// <summary>Which of the player's messages the client should send now (<see cref="PlayerInput.TakeOutbound"/>): each is a
/// game action (0xF7B1) whose body <see cref="PlayerInput"/> holds.</summary>
[Flags]
public enum OutboundMessages
{
    /// <summary>Nothing to send.</summary>
    None = 0,

    /// <summary>0xF61C MoveToState: the raw motion state and the pose (<see cref="PlayerInput.MoveToStateBody"/>).</summary>
    MoveToState = 1,

    /// <summary>0xF753 AutonomousPosition: the pose (<see cref="PlayerInput.AutonomousPositionBody"/>).</summary>
    AutonomousPosition = 2,

    /// <summary>0xF61B Jump: extent, velocity and the pose (<see cref="PlayerInput.JumpBody"/>).</summary>
    Jump = 4,
}
