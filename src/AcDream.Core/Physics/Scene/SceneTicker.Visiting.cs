using System;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Scene;

// The visiting list (the awake objects, in the world's order) and the wakes.
internal sealed partial class SceneTicker
{
    private readonly VisitOrderList _active = new();
    private VisitOrderList.Cursor _activeCursor;
    private PhysicsObj[] _pending = new PhysicsObj[16];
    private int _pendingCount;
    private int _pendingStale;
    private PhysicsObj? _current;
    private UInt128 _currentKey;

    /// <summary>Number of awake objects: in the visiting list or waiting to join it.</summary>
    internal int AwakeCount => _active.Count + _pendingCount - _pendingStale;

    /// <summary>True when, during a tick, the object's place in the visiting order has already passed (retail already visited it).</summary>
    internal bool IsVisitedThisTick(PhysicsObj obj) =>
        !_inTick || (_current is not null && VisitOrderList.KeyOf(obj) <= _currentKey);

    /// <summary>Puts an awake object that is not in the visiting list into the list (before the next visit in order).</summary>
    internal void EnqueueWake(PhysicsObj obj)
    {
        if (_inTick && !IsVisitedThisTick(obj))
        {
            InsertActive(obj);
            return;
        }

        if (_pendingCount == _pending.Length)
        {
            Array.Resize(ref _pending, _pending.Length * 2);
        }

        _pending[_pendingCount++] = obj;
        obj._scene.PendingWake = true;
    }

    /// <summary>Wakes a dormant object: materialises its bookkeeping and schedules its visits.</summary>
    internal void WakeDormant(PhysicsObj obj)
    {
        Materialize(obj, IsVisitedThisTick(obj));
        obj._scene.Dormancy = Dormancy.Awake;
        GateQueue.Forget(obj);
        EnqueueWake(obj);
    }

    /// <summary>Wakes every dormant object that depends on the player or on object maintenance (they changed).</summary>
    internal void WakeGatedDormant()
    {
        VisitOrderList objects = _world.Objects;
        VisitOrderList.Cursor cursor = objects.Start();
        while (objects.MoveNext(ref cursor, out PhysicsObj o))
        {
            if (o._scene.IsLazy)
            {
                WakeDormant(o);
            }
        }
    }

    /// <summary>Takes an object being removed from the world out of the visiting and pending lists and its gate queue.</summary>
    internal void RemoveFromVisiting(PhysicsObj obj)
    {
        ref SceneSlot s = ref obj._scene;
        GateQueue.Forget(obj);
        if (s.InActiveList)
        {
            _active.Remove(obj); // a walk in progress finds its place again by key
            s.InActiveList = false;
        }

        if (s.PendingWake)
        {
            // Left in the pending array as a stale entry (MergePending skips entries whose flag is clear); compacted once
            // stale entries are half the array, so a removal costs O(1) amortised.
            s.PendingWake = false;
            _pendingStale++;
            if (_pendingStale * 2 > _pendingCount + 16)
            {
                CompactPending();
            }
        }

        s.Dormancy = Dormancy.Awake;
    }

    private void InsertActive(PhysicsObj obj)
    {
        _active.Insert(obj);
        obj._scene.InActiveList = true;
    }

    /// <summary>Objects woken since the last tick join the visiting list.</summary>
    private void MergePending()
    {
        for (int i = 0; i < _pendingCount; i++)
        {
            PhysicsObj o = _pending[i];
            _pending[i] = null!;
            if (!o._scene.PendingWake)
            {
                continue; // removed while pending
            }

            o._scene.PendingWake = false;
            if (!o._scene.InActiveList && o._scene.Dormancy == Dormancy.Awake)
            {
                InsertActive(o);
            }
        }

        _pendingCount = 0;
        _pendingStale = 0;
    }

    // Drops the pending entries of objects removed from the world.
    private void CompactPending()
    {
        int w = 0;
        for (int i = 0; i < _pendingCount; i++)
        {
            PhysicsObj o = _pending[i];
            if (o._scene.PendingWake)
            {
                _pending[w++] = o;
            }
        }

        Array.Clear(_pending, w, _pendingCount - w);
        _pendingCount = w;
        _pendingStale = 0;
    }
}
