using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Animation;

/// <summary>
/// An object's motion-table manager (retail <c>MotionTableManager</c>, PORTAL/cphysobj/CMTableManager.c): the table, the
/// state it plays from, and the motions started but not finished, each with the number of animations that must end
/// before it is done. <c>AnimationDone</c> counts the animations the sequence finishes; a motion whose count is reached is
/// reported done (retail <c>CPhysicsObj::MotionDone</c>; here queued for <see cref="TryTakeCompletedMotion"/>, which the
/// object drains at once).
/// </summary>
internal sealed class MotionTableManager
{
    // The completed-motion ring: 32 entries at first, doubled in Append (where the pending list grows) whenever the pending
    // and completed motions together could outnumber it. Each MotionDone moves one motion from the pending list to the ring,
    // so the ring never fills and the per-tick path (AnimationDone, CheckForCompletedMotions) never grows it.
    private const int InitialCompletedCapacity = 32;
    private MotionCommand[] _completedMotion = new MotionCommand[InitialCompletedCapacity];
    private bool[] _completedSuccess = new bool[InitialCompletedCapacity];
    private int _completedHead;
    private int _completedCount;

    // pending_animations (a DLList of AnimNode); nodes are recycled through _free.
    private AnimNode? _head;
    private AnimNode? _tail;
    private AnimNode? _free;
    private int _pendingCount;

    /// <summary>Creates a manager for <paramref name="table"/> (null: every movement fails with
    /// <see cref="MotionError.NoMotionTable"/>, as retail's manager without a table).</summary>
    // retail: MotionTableManager::Create (acclient.c:329813)
    public MotionTableManager(MotionTable? table)
    {
        Table = table;
        State = new MotionState();
        AnimationCounter = 0;
    }

    /// <summary>The motion table (retail <c>table</c>).</summary>
    public MotionTable? Table { get; private set; }

    /// <summary>The state the table plays from (retail <c>state</c>).</summary>
    public MotionState State { get; }

    /// <summary>Animations finished since the head motion started (retail <c>animation_counter</c>).</summary>
    public int AnimationCounter { get; private set; }

    /// <summary>Number of motions not yet done.</summary>
    public int PendingCount => _pendingCount;

    /// <summary>Capacity of the completed-motion ring (for tests: it grows with the pending list, never in a tick).</summary>
    internal int CompletedCapacity => _completedMotion.Length;

    /// <summary>Replaces the table (retail reads it by id from the data files).</summary>
    // retail: MotionTableManager::SetMotionTableID (acclient.c:329772)
    public bool SetMotionTable(MotionTable? table)
    {
        Table = table;
        return table is not null;
    }

    /// <summary>The table's data id, 0 without one.</summary>
    // retail: MotionTableManager::GetMotionTableID (acclient.c:329791)
    public uint GetMotionTableId() => Table?.Id ?? 0u;

    /// <summary>Takes the oldest motion reported done.</summary>
    public bool TryTakeCompletedMotion(out MotionCommand motion, out bool success)
    {
        if (_completedCount == 0)
        {
            motion = 0;
            success = false;
            return false;
        }

        motion = _completedMotion[_completedHead];
        success = _completedSuccess[_completedHead];
        _completedHead = (_completedHead + 1) % _completedMotion.Length;
        _completedCount--;
        return true;
    }

    // CPhysicsObj::MotionDone, queued.
    private void MotionDone(uint motion, bool success)
    {
        // non-retail: a queue (retail calls the object at once) that the object drains in the same call
        // (PhysicsObj.ReportCompletedMotions). It loses nothing: Append keeps its capacity at least the pending motions plus
        // the completed ones not yet taken, and each MotionDone moves one pending motion here.
        int at = (_completedHead + _completedCount) % _completedMotion.Length;
        _completedMotion[at] = (MotionCommand)motion;
        _completedSuccess[at] = success;
        _completedCount++;
    }

    // Doubles the completed-motion ring until it holds `needed`, keeping its order (called from Append only).
    private void EnsureCompletedCapacity(int needed)
    {
        int capacity = _completedMotion.Length;
        if (needed <= capacity)
        {
            return;
        }

        while (capacity < needed)
        {
            capacity *= 2;
        }

        var motions = new MotionCommand[capacity];
        var successes = new bool[capacity];
        for (int i = 0; i < _completedCount; i++)
        {
            int from = (_completedHead + i) % _completedMotion.Length;
            motions[i] = _completedMotion[from];
            successes[i] = _completedSuccess[from];
        }

        _completedMotion = motions;
        _completedSuccess = successes;
        _completedHead = 0;
    }

    /// <summary>Drops the link animations queued after <paramref name="node"/>: the counts of the motions after it are
    /// zeroed and their sum of link animations removed from the sequence.</summary>
    // retail: MotionTableManager::truncate_animation_list (acclient.c:329841)
    internal void TruncateAnimationList(AnimNode? node, AnimSequence seq)
    {
        if (node is null)
        {
            return;
        }

        AnimNode? a = _tail;
        uint n = 0;
        if (a == node)
        {
            seq.RemoveLinkAnimations(n);
            return;
        }

        while (a is not null)
        {
            uint c = a.NumAnims;
            a.NumAnims = 0;
            a = a.Prev;
            n += c;
            if (a == node)
            {
                seq.RemoveLinkAnimations(n);
                return;
            }
        }
    }

    /// <summary>One animation of the sequence ended: the counter goes up, and every motion at the head whose count it
    /// reaches is done (an action's entry leaves the state's action list).</summary>
    // retail: MotionTableManager::AnimationDone (acclient.c:329872)
    public void AnimationDone(bool success)
    {
        AnimNode? a = _head;
        if (a is null)
        {
            return;
        }

        AnimationCounter++;
        do
        {
            // Retail compares the count and the counter as unsigned (pointer-width) values.
            if (a.NumAnims > (uint)AnimationCounter)
            {
                break;
            }

            if ((a.Motion & 0x10000000) != 0)
            {
                State.RemoveActionHead();
            }

            MotionDone(a.Motion, success);
            AnimationCounter -= (int)a.NumAnims;
            RemoveHead();
            a = _head;
        }
        while (a is not null);

        if (AnimationCounter != 0 && a is null)
        {
            AnimationCounter = 0;
        }
    }

    /// <summary>The object left the world: every pending motion is done, unsuccessfully.</summary>
    // retail: MotionTableManager::HandleExitWorld (acclient.c:329939)
    public void HandleExitWorld(AnimSequence seq)
    {
        while (_head is not null)
        {
            DrainOne();
        }
    }

    /// <summary>The object entered the world (or its links are dropped): the sequence's link animations go and every
    /// pending motion is done, unsuccessfully.</summary>
    // retail: MotionTableManager::HandleEnterWorld (acclient.c:329948)
    public void HandleEnterWorld(AnimSequence seq)
    {
        seq.RemoveAllLinkAnimations();
        while (_head is not null)
        {
            DrainOne();
        }
    }

    // One turn of the drain loops above: retail's AnimationDone(false). A call whose count the head does not reach only
    // increments the counter (AnimationDone breaks before anything else), so the counter is first moved to one below the
    // head's count: the same calls' result without them.
    private void DrainOne()
    {
        // non-retail: a motion with no animations (a cycle without animations: num_anims = 0 - 1 = 0xFFFFFFFF) kept retail's
        // loop calling AnimationDone about 2^32 times, until the counter reached the count (a stall of tens of seconds);
        // skipping the calls that only count leaves the same state (docs/divergences.md)
        uint needed = _head!.NumAnims;
        if (needed > (uint)AnimationCounter + 1u)
        {
            AnimationCounter = (int)(needed - 1u);
        }

        AnimationDone(false);
    }

    /// <summary>Reports done, in order, the motions at the head that wait for no animation.</summary>
    // retail: MotionTableManager::CheckForCompletedMotions (acclient.c:329959)
    public void CheckForCompletedMotions()
    {
        for (AnimNode? a = _head; a is not null; a = _head)
        {
            if (a.NumAnims != 0)
            {
                break;
            }

            if ((a.Motion & 0x10000000) != 0)
            {
                State.RemoveActionHead();
            }

            MotionDone(a.Motion, true);
            RemoveHead();
        }
    }

    /// <summary>Per-step bookkeeping: retail's <c>UseTime</c> is its own 5-byte thunk (0x0051BFD0 in the PDB), a tail jump to
    /// <c>CheckForCompletedMotions</c> (acclient.c:329959); the decompilation shows it no body.</summary>
    // retail: MotionTableManager::UseTime (a 5-byte tail-jump thunk to MotionTableManager::CheckForCompletedMotions, acclient.c:329959)
    public void UseTime() => CheckForCompletedMotions();

    /// <summary>When the newest motion with animations repeats an earlier one still queued (a substate, or a style), the
    /// links queued between them are dropped (<see cref="TruncateAnimationList"/>).</summary>
    // retail: MotionTableManager::remove_redundant_links (acclient.c:330078)
    internal void RemoveRedundantLinks(AnimSequence seq)
    {
        AnimNode? last = _tail;
        if (last is null)
        {
            return;
        }

        while (last.NumAnims == 0)
        {
            last = last.Prev;
            if (last is null)
            {
                return;
            }
        }

        uint motion = last.Motion;
        if ((motion & 0x40000000) != 0 && (motion & 0x20000000) == 0)
        {
            AnimNode? a = last.Prev;
            while (a is not null)
            {
                uint m = a.Motion;
                if (m == motion && a.NumAnims != 0)
                {
                    TruncateAnimationList(a, seq);
                    return;
                }

                if (a.NumAnims != 0 && (m & 0xB0000000) != 0)
                {
                    return;
                }

                a = a.Prev;
            }

            return;
        }

        if ((int)motion < 0)
        {
            AnimNode? a = last.Prev;
            while (a is not null)
            {
                uint m = a.Motion;
                if (m == motion)
                {
                    TruncateAnimationList(a, seq);
                    return;
                }

                if (a.NumAnims != 0 && (m & 0x70000000) != 0)
                {
                    return;
                }

                a = a.Prev;
            }
        }
    }

    /// <summary>Queues <paramref name="motion"/> as waiting for <paramref name="numAnims"/> animations.</summary>
    // retail: MotionTableManager::add_to_queue (acclient.c:330148)
    internal void AddToQueue(uint motion, uint numAnims, AnimSequence seq)
    {
        Append(motion, numAnims);
        RemoveRedundantLinks(seq);
    }

    /// <summary>Puts the table's default state on the sequence and queues it (as a Ready) for its animations.</summary>
    // retail: MotionTableManager::initialize_state (acclient.c:330171)
    public void InitializeState(AnimSequence seq)
    {
        uint numAnims = 0;
        if (Table is not null)
        {
            Table.SetDefaultState(State, seq, out numAnims);
        }

        Append(0x41000003u, numAnims);
        RemoveRedundantLinks(seq);
    }

    /// <summary>Plays (<paramref name="type"/> <see cref="MovementType.InterpretedCommand"/>, 2), stops
    /// (<see cref="MovementType.StopInterpretedCommand"/>, 4) or stops everything (<see cref="MovementType.StopCompletely"/>, 5)
    /// through the table and queues the result.</summary>
    /// <returns><see cref="MotionError.NoMotionTable"/> (7) without a table; <see cref="MotionError.NoMotionTableData"/>
    /// (0x43) when the table has nothing for the motion; else <see cref="MotionError.None"/>.</returns>
    // retail: MotionTableManager::PerformMovement (acclient.c:330205)
    public MotionError PerformMovement(MovementType type, uint motion, float speed, AnimSequence seq)
    {
        MotionTable? table = Table;
        if (table is null)
        {
            return MotionError.NoMotionTable;
        }

        uint numAnims;
        switch (type)
        {
            case MovementType.InterpretedCommand:
                if (table.DoObjectMotion(motion, State, seq, speed, out numAnims))
                {
                    AddToQueue(motion, numAnims, seq);
                    return MotionError.None;
                }

                return MotionError.NoMotionTableData;
            case MovementType.StopInterpretedCommand:
                if (table.StopObjectMotion(motion, speed, State, seq, out numAnims))
                {
                    AddToQueue(0x41000003u, numAnims, seq);
                    return MotionError.None;
                }

                return MotionError.NoMotionTableData;
            case MovementType.StopCompletely:
                table.StopObjectCompletely(State, seq, out numAnims);
                AddToQueue(0x41000003u, numAnims, seq);
                return MotionError.None;
            default:
                // Retail returns whatever is in its register (the sequence pointer) for another type; no caller passes one.
                return MotionError.GeneralMovementFailure;
        }
    }

    private void Append(uint motion, uint numAnims)
    {
        EnsureCompletedCapacity(_pendingCount + 1 + _completedCount);
        AnimNode? n = _free;
        if (n is null)
        {
            n = new AnimNode();
        }
        else
        {
            _free = n.Next;
        }

        n.Motion = motion;
        n.NumAnims = numAnims;
        n.Next = null;
        n.Prev = _tail;
        if (_tail is null)
        {
            _head = n;
        }
        else
        {
            _tail.Next = n;
        }

        _tail = n;
        _pendingCount++;
    }

    private void RemoveHead()
    {
        AnimNode? h = _head;
        if (h is null)
        {
            return;
        }

        _head = h.Next;
        if (_head is null)
        {
            _tail = null;
        }
        else
        {
            _head.Prev = null;
        }

        h.Prev = null;
        h.Next = _free;
        _free = h;
        _pendingCount--;
    }

    /// <summary>A started motion and the animations it waits for (retail <c>MotionTableManager::AnimNode</c>).</summary>
    internal sealed class AnimNode
    {
        public uint Motion;
        public uint NumAnims;
        public AnimNode? Next;
        public AnimNode? Prev;
    }
}
