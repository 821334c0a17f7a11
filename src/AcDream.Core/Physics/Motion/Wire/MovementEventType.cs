namespace AcDream.Core.Physics.Motion.Wire;

/// <summary>The kind of movement a MovementEvent carries: the first byte of its movement data, on which retail's
/// <c>MovementManager::unpack_movement</c> switches. Types 6-9 are <see cref="MovementType"/>'s values; the wire's 0 is an
/// interpreted motion state (where <see cref="MovementType"/>'s 0 is <see cref="MovementType.Invalid"/>).</summary>
public enum MovementEventType : byte
{
    /// <summary>0: an interpreted motion state (walk, run, side-step, turn, actions).</summary>
    InterpretedMotion = 0,

    /// <summary>6: move to an object (retail <c>MoveToObject</c>).</summary>
    MoveToObject = 6,

    /// <summary>7: move to a position (retail <c>MoveToPosition</c>).</summary>
    MoveToPosition = 7,

    /// <summary>8: turn to face an object (retail <c>TurnToObject</c>).</summary>
    TurnToObject = 8,

    /// <summary>9: turn to a heading (retail <c>TurnToHeading</c>).</summary>
    TurnToHeading = 9,
}
