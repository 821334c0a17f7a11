namespace AcDream.Core.Physics.Motion;

/// <summary>
/// A motion command (retail's <c>uint32</c> command ids; the high byte is the command's class, see
/// <see cref="MotionCommandClass"/>: 0x80 style, 0x40 substate, 0x20 modifier, 0x10 action). The named members are the
/// commands the interpreter tests by value, named as in the server protocol's command list; every other command is
/// <c>(MotionCommand)id</c> (e.g. from <see cref="MotionCommandIds.TryGet"/>) and prints as its hex id.
/// </summary>
public enum MotionCommand : uint
{
    /// <summary>No command: an empty side-step or turn slot of a motion state (0).</summary>
    None = 0,

    /// <summary>Standing still, the default substate (0x41000003).</summary>
    Ready = 0x41000003u,

    /// <summary>Walking forward (0x45000005).</summary>
    WalkForward = 0x45000005u,

    /// <summary>Walking backwards (0x45000006); the interpreter turns it into <see cref="WalkForward"/> at -0.65 speed.</summary>
    WalkBackwards = 0x45000006u,

    /// <summary>Running forward (0x44000007); <see cref="WalkForward"/> with the run key held becomes this.</summary>
    RunForward = 0x44000007u,

    /// <summary>Fallen over (0x40000008): no jump charge from it.</summary>
    Fallen = 0x40000008u,

    /// <summary>Dead (0x40000011): starting it drops the link animations.</summary>
    Dead = 0x40000011u,

    /// <summary>Falling (0x40000015): the substate an airborne creature is put in.</summary>
    Falling = 0x40000015u,

    /// <summary>Crouching (0x41000012), the first of the three low postures that forbid a jump.</summary>
    Crouch = 0x41000012u,

    /// <summary>Sitting (0x41000013).</summary>
    Sitting = 0x41000013u,

    /// <summary>Sleeping (0x41000014), the last low posture.</summary>
    Sleeping = 0x41000014u,

    /// <summary>Turning right (0x6500000D); positive speed turns clockwise seen from above.</summary>
    TurnRight = 0x6500000Du,

    /// <summary>Turning left (0x6500000E); the interpreter turns it into <see cref="TurnRight"/> at negative speed.</summary>
    TurnLeft = 0x6500000Eu,

    /// <summary>Side-stepping right (0x6500000F).</summary>
    SideStepRight = 0x6500000Fu,

    /// <summary>Side-stepping left (0x65000010); the interpreter turns it into <see cref="SideStepRight"/> at negative speed.</summary>
    SideStepLeft = 0x65000010u,

    /// <summary>The non-combat style, every object's default style (0x8000003D).</summary>
    NonCombat = 0x8000003Du,
}
