using System;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Scene;

// The visiting list (the awake objects, in the world's order) and the wakes.
internal sealed partial class SceneTicker
{
    private PhysicsObj[] _active = new PhysicsObj[16];
    private int _activeCount;
    private int _activeCursor;
    private PhysicsObj[] _pending = new PhysicsObj[16];
    private int _pendingCount;
    private PhysicsObj? _current;

    /// <summary>Number of awake objects: in the visiting list or waiting to join it.</summary>
    internal int AwakeCount => _activeCount + _pendingCount;

    /// <summary>True when, during a tick, the object's place in the visiting order has already passed (retail already visited it).</summary>
    internal bool IsVisitedThisTick(PhysicsObj obj) => !_inTick || (_current is not null && obj.WorldIndex <= _current.WorldIndex);

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
        int count = _world.ObjectCount;
        for (int i = 0; i < count; i++)
        {
            PhysicsObj o = _world.ObjectAt(i);
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
            int at = Array.IndexOf(_active, obj, 0, _activeCount);
            Array.Copy(_active, at + 1, _active, at, _activeCount - at - 1);
            _activeCount--;
            _active[_activeCount] = null!;
            s.InActiveList = false;
            if (_inTick && at <= _activeCursor)
            {
                _activeCursor--;
            }
        }

        if (s.PendingWake)
        {
            int at = Array.IndexOf(_pending, obj, 0, _pendingCount);
            Array.Copy(_pending, at + 1, _pending, at, _pendingCount - at - 1);
            _pendingCount--;
            _pending[_pendingCount] = null!;
            s.PendingWake = false;
        }

        s.Dormancy = Dormancy.Awake;
    }

    private void InsertActive(PhysicsObj obj)
    {
        if (_activeCount == _active.Length)
        {
            Array.Resize(ref _active, _active.Length * 2);
        }

        int idx = obj.WorldIndex;
        int lo = 0, hi = _activeCount;
        while (lo < hi)
        {
            int mid = (lo + hi) >> 1;
            if (_active[mid].WorldIndex < idx)
            {
                lo = mid + 1;
            }
            else
            {
                hi = mid;
            }
        }

        Array.Copy(_active, lo, _active, lo + 1, _activeCount - lo);
        _active[lo] = obj;
        _activeCount++;
        obj._scene.InActiveList = true;
        if (_inTick && lo <= _activeCursor)
        {
            _activeCursor++;
        }
    }

    /// <summary>Objects woken since the last tick join the visiting list.</summary>
    private void MergePending()
    {
        for (int i = 0; i < _pendingCount; i++)
        {
            PhysicsObj o = _pending[i];
            _pending[i] = null!;
            o._scene.PendingWake = false;
            if (o.WorldIndex >= 0 && !o._scene.InActiveList && o._scene.Dormancy == Dormancy.Awake)
            {
                InsertActive(o);
            }
        }

        _pendingCount = 0;
    }
}
