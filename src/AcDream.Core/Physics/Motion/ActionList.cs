namespace AcDream.Core.Physics.Motion;

/// <summary>One queued action of a motion state (retail <c>ActionNode</c>).</summary>
/// <param name="Action">The action command.</param>
/// <param name="Speed">Its speed.</param>
/// <param name="Stamp">Its server action stamp (15 bits used).</param>
/// <param name="Autonomous">True when this client started it.</param>
public readonly record struct ActionNode(MotionCommand Action, float Speed, uint Stamp, bool Autonomous)
{
    // The command prints by name (an unnamed one as its hex id).
    private bool PrintMembers(System.Text.StringBuilder builder)
    {
        builder.Append("Action = ").Append(MotionCommandText.Format(Action))
               .Append(", Speed = ").Append(Speed.ToString(System.Globalization.CultureInfo.InvariantCulture))
               .Append(", Stamp = ").Append(Stamp)
               .Append(", Autonomous = ").Append(Autonomous);
        return true;
    }
}

/// <summary>
/// A motion state's queue of actions (retail <c>LList&lt;ActionNode&gt;</c>), first in first out, in a fixed array so the
/// tick never allocates.
/// </summary>
/// <remarks>
/// Retail's list is unbounded. <c>DoMotion</c> refuses a seventh action, so a list seldom holds more than six; this one holds
/// <see cref="Capacity"/> and ignores an action added to a full list.
/// </remarks>
public sealed class ActionList
{
    /// <summary>Most actions held. Non-retail: retail's list grows without bound.</summary>
    public const int Capacity = 16;

    private readonly ActionNode[] _nodes = new ActionNode[Capacity];
    private int _head;

    /// <summary>Number of queued actions (retail <c>InterpretedMotionState::GetNumActions</c>, the count of the list).</summary>
    // retail: InterpretedMotionState::GetNumActions (acclient.c:332814)
    public int Count { get; private set; }

    /// <summary>The action at queue position <paramref name="i"/> (0 = oldest).</summary>
    /// <exception cref="System.ArgumentOutOfRangeException"><paramref name="i"/> is not below <see cref="Count"/>.</exception>
    public ActionNode this[int i]
    {
        get
        {
            System.ArgumentOutOfRangeException.ThrowIfNegative(i);
            System.ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(i, Count);
            return _nodes[(_head + i) % Capacity];
        }
    }

    /// <summary>Appends an action at the tail (ignored when the list is full).</summary>
    /// <exception cref="System.ArgumentException">The action's speed is NaN, infinite or beyond
    /// ±<see cref="Spatial.InputLimits.MaxMotionSpeed"/> (the list unchanged): an action is played at its speed when the
    /// state is applied, after the state's movement, so a bad speed must be refused here, where it enters.</exception>
    public void Add(in ActionNode node)
    {
        // non-retail: the action speed's domain (see InputLimits.MaxMotionSpeed)
        if (!MotionChecks.IsSpeedInDomain(node.Speed))
        {
            throw new System.ArgumentException(
                $"An action's speed must be finite and within ±{Spatial.InputLimits.MaxMotionSpeed} (got {node.Speed}).", nameof(node));
        }

        // non-retail: a bounded list (retail allocates a node per action)
        if (Count == Capacity)
        {
            return;
        }

        _nodes[(_head + Count) % Capacity] = node;
        Count++;
    }

    /// <summary>Removes the oldest action and returns its command, or <see cref="MotionCommand.None"/> when empty (retail
    /// <c>RemoveAction</c>).</summary>
    public MotionCommand RemoveFirst()
    {
        if (Count == 0)
        {
            return MotionCommand.None;
        }

        MotionCommand action = _nodes[_head].Action;
        _head = (_head + 1) % Capacity;
        Count--;
        return action;
    }

    /// <summary>Empties the list (retail <c>Destroy</c>).</summary>
    public void Clear()
    {
        _head = 0;
        Count = 0;
    }

    /// <summary>Replaces the contents with a copy of <paramref name="other"/>'s.</summary>
    /// <exception cref="System.ArgumentNullException"><paramref name="other"/> is null.</exception>
    public void CopyFrom(ActionList other)
    {
        System.ArgumentNullException.ThrowIfNull(other);
        if (ReferenceEquals(this, other))
        {
            return;
        }

        Clear();
        for (int i = 0; i < other.Count; i++)
        {
            Add(other[i]);
        }
    }
}
