namespace AcDream.Core.Physics.Motion;

/// <summary>The kind of a movement request (retail <c>MovementTypes::Type</c>, acclient.h:2856): the motion interpreter's
/// commands (1–5) and the move-to manager's moves and turns (6–9). Also the movement type byte of a MovementEvent (0xF74C),
/// where 0 is an interpreted motion state.</summary>
public enum MovementType : uint
{
    /// <summary>No movement (0); the move-to manager's idle state.</summary>
    Invalid = 0,

    /// <summary>A command as the player gives it (1).</summary>
    RawCommand = 1,

    /// <summary>An interpreted command (2).</summary>
    InterpretedCommand = 2,

    /// <summary>Stop a command as the player gives it (3).</summary>
    StopRawCommand = 3,

    /// <summary>Stop an interpreted command (4).</summary>
    StopInterpretedCommand = 4,

    /// <summary>Stop everything (5).</summary>
    StopCompletely = 5,

    /// <summary>Walk or run to an object, following it (6).</summary>
    MoveToObject = 6,

    /// <summary>Walk or run to a position (7).</summary>
    MoveToPosition = 7,

    /// <summary>Turn to face an object (8).</summary>
    TurnToObject = 8,

    /// <summary>Turn to a heading (9).</summary>
    TurnToHeading = 9,
}
