namespace AcDream.Core.Physics.Motion.MoveTo;

/// <summary>One pending step of a move-to (retail <c>MoveToManager::MovementNode</c>, acclient.h:57702): move to the
/// position (<see cref="MovementType.MoveToPosition"/>) or turn to <see cref="Heading"/>
/// (<see cref="MovementType.TurnToHeading"/>).</summary>
internal struct MoveToNode
{
    /// <summary>The step: <see cref="MovementType.MoveToPosition"/> or <see cref="MovementType.TurnToHeading"/>.</summary>
    public MovementType Type;

    /// <summary>The heading of a turn, degrees.</summary>
    public float Heading;
}

/// <summary>
/// The move-to manager's pending steps (retail <c>pending_actions</c>, a <c>DLList</c> it appends to and takes from the head
/// of). Non-retail storage: a ring of nodes that grows by doubling and is never shrunk, so that after the first move-tos no
/// step allocates (retail news and deletes a 16-byte node per step).
/// </summary>
internal sealed class MoveToNodeList
{
    private MoveToNode[] _nodes = new MoveToNode[4];
    private int _head;

    /// <summary>Number of pending steps.</summary>
    public int Count { get; private set; }

    /// <summary>The first pending step (Count must be positive).</summary>
    public ref MoveToNode Head => ref _nodes[_head];

    /// <summary>The step at <paramref name="index"/> from the head.</summary>
    public MoveToNode this[int index] => _nodes[(_head + index) % _nodes.Length];

    /// <summary>Appends a step after the tail (retail <c>DLListBase::InsertAfter(node, tail)</c>).</summary>
    public void Append(MovementType type, float heading)
    {
        if (Count == _nodes.Length)
        {
            var grown = new MoveToNode[_nodes.Length * 2];
            for (int i = 0; i < Count; i++)
            {
                grown[i] = _nodes[(_head + i) % _nodes.Length];
            }

            _nodes = grown;
            _head = 0;
        }

        ref MoveToNode n = ref _nodes[(_head + Count) % _nodes.Length];
        n.Type = type;
        n.Heading = heading;
        Count++;
    }

    /// <summary>Drops the head step, if any.</summary>
    public void RemoveHead()
    {
        if (Count == 0)
        {
            return;
        }

        _head = (_head + 1) % _nodes.Length;
        Count--;
        if (Count == 0)
        {
            _head = 0;
        }
    }

    /// <summary>Drops every step.</summary>
    public void Clear()
    {
        Count = 0;
        _head = 0;
    }

    /// <summary>Capacity held (tests of the pooling).</summary>
    public int Capacity => _nodes.Length;
}
