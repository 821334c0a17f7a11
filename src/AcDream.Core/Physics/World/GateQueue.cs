using System;
using System.Collections.Generic;

namespace AcDream.Core.Physics;

/// <summary>
/// Dormant objects whose side of the 96 m player gate the player's travel could change, keyed by the player odometer reading
/// at which that first becomes possible. Entries of objects woken since they were queued are stale and skipped; they are dropped
/// before the queue would grow, so sleep/wake cycles never allocate.
/// </summary>
internal sealed class GateQueue
{
    private readonly PriorityQueue<(PhysicsObj Obj, int Stamp), double> _queue = new(64);
    private int _capacity = 64;
    private int _live;
    private (PhysicsObj Obj, int Stamp)[] _scratch = new (PhysicsObj, int)[16];
    private double[] _scratchKeys = new double[16];

    public void Enqueue(PhysicsObj o, double key)
    {
        if (o._gateQueue != this)
        {
            Forget(o);
            o._gateQueue = this;
            _live++;
        }

        if (_queue.Count >= _capacity)
        {
            Compact();
            if (_queue.Count >= _capacity / 2)
            {
                _capacity = _queue.EnsureCapacity(_capacity * 2);
            }
        }

        _queue.Enqueue((o, o._queueStamp), key);
    }

    /// <summary>Invalidates <paramref name="o"/>'s entry, in whichever queue holds it.</summary>
    public static void Forget(PhysicsObj o)
    {
        o._queueStamp++;
        GateQueue? q = o._gateQueue;
        if (q is not null)
        {
            q._live--;
            o._gateQueue = null;
        }
    }

    /// <summary>Removes the live entries due at <paramref name="odometer"/> into <paramref name="due"/> (grown as needed) and
    /// returns their number; each is forgotten (re-enqueue it to keep it).</summary>
    public int PopDue(double odometer, ref PhysicsObj[] due)
    {
        int n = 0;
        while (_queue.TryPeek(out (PhysicsObj Obj, int Stamp) e, out double key) && key <= odometer)
        {
            _queue.Dequeue();
            if (e.Obj._queueStamp != e.Stamp || e.Obj._gateQueue != this || e.Obj._dormancy == Dormancy.Awake || e.Obj.WorldIndex < 0)
            {
                continue;
            }

            Forget(e.Obj);
            if (n == due.Length)
            {
                Array.Resize(ref due, n * 2);
            }

            due[n++] = e.Obj;
        }

        return n;
    }

    private void Compact()
    {
        int n = 0;
        while (_queue.TryDequeue(out (PhysicsObj Obj, int Stamp) e, out double key))
        {
            if (e.Obj._queueStamp != e.Stamp || e.Obj._gateQueue != this)
            {
                continue;
            }

            if (n == _scratch.Length)
            {
                Array.Resize(ref _scratch, n * 2);
                Array.Resize(ref _scratchKeys, n * 2);
            }

            _scratch[n] = e;
            _scratchKeys[n] = key;
            n++;
        }

        for (int i = 0; i < n; i++)
        {
            _queue.Enqueue(_scratch[i], _scratchKeys[i]);
            _scratch[i] = default;
        }
    }
}
