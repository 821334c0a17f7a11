namespace AcDream.Core.Physics.Motion;

/// <summary>One started motion waiting for its animation to finish (retail <c>CMotionInterp::MotionNode</c>).</summary>
/// <param name="ContextId">The context id it was started with.</param>
/// <param name="Motion">The motion (Ready for a stop).</param>
/// <param name="JumpErrorCode">Not <see cref="MotionError.None"/> when a jump is not allowed until it finishes (the error a
/// jump then returns).</param>
public readonly record struct MotionNode(uint ContextId, MotionCommand Motion, MotionError JumpErrorCode)
{
    // The command prints by name (an unnamed one as its hex id).
    private bool PrintMembers(System.Text.StringBuilder builder)
    {
        builder.Append("ContextId = ").Append(ContextId)
               .Append(", Motion = ").Append(MotionCommandText.Format(Motion))
               .Append(", JumpErrorCode = ").Append(JumpErrorCode);
        return true;
    }
}

/// <summary>
/// The interpreter's list of started motions not yet finished (retail <c>CMotionInterp::pending_motions</c>), first in
/// first out, in a fixed array.
/// </summary>
/// <remarks>Retail's list is unbounded; this one holds <see cref="Capacity"/> and, when full, drops the oldest node (a
/// motion table that reports its completions never lets it fill).</remarks>
public sealed class PendingMotions
{
    /// <summary>Most nodes held. Non-retail: retail's list grows without bound.</summary>
    public const int Capacity = 64;

    private readonly MotionNode[] _nodes = new MotionNode[Capacity];
    private int _head;

    /// <summary>Number of pending motions.</summary>
    public int Count { get; private set; }

    /// <summary>The oldest pending motion.</summary>
    /// <exception cref="System.InvalidOperationException">The list is empty.</exception>
    public MotionNode Head => Count > 0 ? _nodes[_head] : throw new System.InvalidOperationException("No pending motion.");

    /// <summary>The pending motion at position <paramref name="i"/> (0 = oldest).</summary>
    /// <exception cref="System.ArgumentOutOfRangeException"><paramref name="i"/> is not below <see cref="Count"/>.</exception>
    public MotionNode this[int i]
    {
        get
        {
            System.ArgumentOutOfRangeException.ThrowIfNegative(i);
            System.ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(i, Count);
            return _nodes[(_head + i) % Capacity];
        }
    }

    internal void Add(in MotionNode node)
    {
        // non-retail: a bounded list
        if (Count == Capacity)
        {
            RemoveHead();
        }

        _nodes[(_head + Count) % Capacity] = node;
        Count++;
    }

    internal void RemoveHead()
    {
        if (Count == 0)
        {
            return;
        }

        _head = (_head + 1) % Capacity;
        Count--;
    }

    internal void Clear()
    {
        _head = 0;
        Count = 0;
    }
}
