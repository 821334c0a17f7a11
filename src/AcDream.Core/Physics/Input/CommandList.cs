using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Input;

/// <summary>
/// One of the command interpreter's lists of held movement keys (retail <c>CommandList</c>: the substate, turn and side-step
/// lists), newest first: the head is the command in force, and releasing it hands over to the key held before it. Keyboard
/// entries only (no mouse command); at most two commands share a list, so it is two fixed slots.
/// </summary>
internal struct CommandList
{
    private MotionCommand _head;
    private MotionCommand _next;

    /// <summary>The command in force (the newest held), or <see cref="MotionCommand.None"/>.</summary>
    public readonly MotionCommand Head => _head;

    /// <summary>Puts <paramref name="command"/> at the head.</summary>
    // retail: CommandList::AddCommand (acclient.c:718507)
    public void AddCommand(MotionCommand command)
    {
        _next = _head;
        _head = command;
    }

    /// <summary>Removes <paramref name="command"/>; true when it was the head.</summary>
    // retail: CommandList::RemoveCommand (acclient.c:718294), keyboard branch
    public bool RemoveCommand(MotionCommand command)
    {
        if (_head == command)
        {
            _head = _next;
            _next = MotionCommand.None;
            return true;
        }

        if (_next == command)
        {
            _next = MotionCommand.None;
        }

        return false;
    }

    /// <summary>Forgets every command.</summary>
    // retail: CommandList::ClearKeyboardCommands (acclient.c:718434)
    public void ClearKeyboardCommands()
    {
        _head = MotionCommand.None;
        _next = MotionCommand.None;
    }
}
