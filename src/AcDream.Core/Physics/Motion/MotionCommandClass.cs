namespace AcDream.Core.Physics.Motion;

/// <summary>
/// The class bits of a <see cref="MotionCommand"/> id (retail tests them with masks: <c>motion &amp; 0x10000000</c> is an
/// action, and so on). Not commands themselves: test a command with <c>((uint)motion &amp; (uint)MotionCommandClass.Action)
/// != 0</c>, as the interpreter does.
/// </summary>
[System.Flags]
public enum MotionCommandClass : uint
{
    /// <summary>No class bit.</summary>
    None = 0,

    /// <summary>A style (stance), e.g. <see cref="MotionCommand.NonCombat"/> (0x80000000).</summary>
    Style = 0x80000000u,

    /// <summary>A substate: the forward motion, e.g. <see cref="MotionCommand.Ready"/>, <see cref="MotionCommand.WalkForward"/>
    /// (0x40000000).</summary>
    Substate = 0x40000000u,

    /// <summary>A modifier played over the substate: turns and side-steps (0x20000000).</summary>
    Modifier = 0x20000000u,

    /// <summary>An action: a one-shot motion queued in the states' action lists (0x10000000).</summary>
    Action = 0x10000000u,

    /// <summary>A chat emote: refused outside the non-combat style (0x02000000).</summary>
    ChatEmote = 0x02000000u,
}
