namespace AcDream.Core.Physics.Motion;

/// <summary>
/// The motion command ids the interpreter tests by value (retail's command list; the high byte is the command class:
/// 0x80 style, 0x40 substate, 0x20 modifier, 0x10 action). Names are those of the server protocol's command list.
/// </summary>
public static class MotionCommand
{
    /// <summary>Standing still, the default substate (0x41000003).</summary>
    public const uint Ready = 0x41000003u;

    /// <summary>Walking forward (0x45000005).</summary>
    public const uint WalkForward = 0x45000005u;

    /// <summary>Walking backwards (0x45000006); the interpreter turns it into <see cref="WalkForward"/> at -0.65 speed.</summary>
    public const uint WalkBackwards = 0x45000006u;

    /// <summary>Running forward (0x44000007); <see cref="WalkForward"/> with the run key held becomes this.</summary>
    public const uint RunForward = 0x44000007u;

    /// <summary>Fallen over (0x40000008): no jump charge from it.</summary>
    public const uint Fallen = 0x40000008u;

    /// <summary>Dead (0x40000011): starting it drops the link animations.</summary>
    public const uint Dead = 0x40000011u;

    /// <summary>Falling (0x40000015): the substate an airborne creature is put in.</summary>
    public const uint Falling = 0x40000015u;

    /// <summary>Crouching (0x41000012), the first of the three low postures that forbid a jump.</summary>
    public const uint Crouch = 0x41000012u;

    /// <summary>Sitting (0x41000013).</summary>
    public const uint Sitting = 0x41000013u;

    /// <summary>Sleeping (0x41000014), the last low posture.</summary>
    public const uint Sleeping = 0x41000014u;

    /// <summary>Turning right (0x6500000D); positive speed turns clockwise seen from above.</summary>
    public const uint TurnRight = 0x6500000Du;

    /// <summary>Turning left (0x6500000E); the interpreter turns it into <see cref="TurnRight"/> at negative speed.</summary>
    public const uint TurnLeft = 0x6500000Eu;

    /// <summary>Side-stepping right (0x6500000F).</summary>
    public const uint SideStepRight = 0x6500000Fu;

    /// <summary>Side-stepping left (0x65000010); the interpreter turns it into <see cref="SideStepRight"/> at negative speed.</summary>
    public const uint SideStepLeft = 0x65000010u;

    /// <summary>The non-combat style, every object's default style (0x8000003D).</summary>
    public const uint NonCombat = 0x8000003Du;

    /// <summary>The style class bit: a command with it set is a stance (0x80000000).</summary>
    public const uint StyleMask = 0x80000000u;

    /// <summary>The substate class bit (0x40000000).</summary>
    public const uint SubstateMask = 0x40000000u;

    /// <summary>The modifier class bit (0x20000000).</summary>
    public const uint ModifierMask = 0x20000000u;

    /// <summary>The action class bit (0x10000000): one-shot motions queued in the states' action lists.</summary>
    public const uint ActionMask = 0x10000000u;

    /// <summary>The chat-emote class bit (0x02000000): refused outside the non-combat style.</summary>
    public const uint ChatEmoteMask = 0x02000000u;
}

/// <summary>
/// The error numbers the motion interpreter returns (retail's weenie error codes; 0 is success). Names are those of the
/// server protocol's error list.
/// </summary>
public static class MotionError
{
    /// <summary>Success.</summary>
    public const int None = 0;

    /// <summary>The object has no movement manager or its part array has no motion table (7).</summary>
    public const int NoMotionTable = 7;

    /// <summary>The interpreter has no physics object (8).</summary>
    public const int NoPhysicsObject = 8;

    /// <summary>The object is in the air and may not move or jump (0x24).</summary>
    public const int YouCantJumpWhileInTheAir = 0x24;

    /// <summary>Crouching is refused outside the non-combat style (0x3F).</summary>
    public const int CantCrouchInCombat = 0x3F;

    /// <summary>Sitting is refused outside the non-combat style (0x40).</summary>
    public const int CantSitInCombat = 0x40;

    /// <summary>Lying down is refused outside the non-combat style (0x41).</summary>
    public const int CantLieDownInCombat = 0x41;

    /// <summary>Chat emotes are refused outside the non-combat style (0x42).</summary>
    public const int CantChatEmoteInCombat = 0x42;

    /// <summary>Six actions are already queued (0x45).</summary>
    public const int TooManyActions = 0x45;

    /// <summary>General failure: no part array, fully constrained, or the jump stamina cost was refused (0x47).</summary>
    public const int GeneralMovementFailure = 0x47;

    /// <summary>The current motion does not allow a jump (0x48).</summary>
    public const int YouCantJumpFromThisPosition = 0x48;

    /// <summary>The character is too loaded down to jump (0x49).</summary>
    public const int CantJumpLoadedDown = 0x49;
}
