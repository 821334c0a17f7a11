using System;
using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// Dormant objects whose side of the 96 m player gate the player's travel could change: each is re-measured only once the
/// player could have carried it across (its distance margin to 96 m; distance is 1-Lipschitz in the player's position).
/// One queue per side of the player in the visiting order (objects before the player see its position before its update).
/// </summary>
/// <remarks>
/// <para>Two clocks bound the player's displacement since an entry was measured. Small margins (&lt; <see cref="Split"/>) wait on
/// the <i>odometer</i> (path length). Large margins wait on an <i>anchor clock</i>: an anchor that follows the player in hops of
/// more than <see cref="AnchorRadius"/>; the clock is the hops' total plus that radius, and an entry measured at distance r from
/// the anchor is due once the clock passes (clock then) + margin − r. A player moving about one spot never re-measures far
/// objects; on a straight walk both clocks advance alike.</para>
/// <para>Entries carry what a re-measurement needs, so re-measuring reads no object. A crossing by an idle object is recorded in
/// the slot (<see cref="RecordFlip"/>) and applied when the object is next read; only objects that must move are woken.</para>
/// <para>Slots carry a generation: <see cref="Forget"/> bumps it and the entry, now stale, is dropped when the caller would act on
/// its object (<see cref="Keep"/>), when the far level cascades, or by a compaction once stale entries outnumber live ones; a
/// stale entry that never crosses just goes round until then (cheaper than reading a slot for every pop). Memory stays bounded
/// by about twice the live count and, once grown, never allocates.</para>
/// </remarks>
internal sealed class GateQueue
{
    /// <summary>Margins below this (metres) wait on the odometer; larger ones on the anchor clock.</summary>
    public const double Split = 8.0;

    /// <summary>How far (metres) the player may stray from the anchor before it hops.</summary>
    public const double AnchorRadius = 4.0;

    private const long NoFlip = long.MinValue;

    private readonly GateWheel _odometerWheel;
    private readonly GateWheel _anchorWheel;

    // The last two gate crossings of a slot's object since it was queued (tick and side): one cache line per record.
    private struct Flips
    {
        public long Tick, PrevTick;
        public bool Far, PrevFar;
    }

    // Slots: the object, its generation, its crossings.
    private PhysicsObj?[] _obj = new PhysicsObj?[64];
    private int[] _generation = new int[64];
    private Flips[] _flips = new Flips[64];
    private int[] _free = new int[64];
    private int _freeCount;
    private int _slotCount;
    private int _stale;

    // The clocks as of this tick's Advance.
    private double _odometer;
    private double _anchorTotal;
    private double _anchorX, _anchorY, _anchorZ;
    private bool _hasAnchor;
    private double _fromAnchor;
    private double _seenX, _seenY, _seenZ;

    public GateQueue()
    {
        _odometerWheel = new GateWheel(this);
        _anchorWheel = new GateWheel(this);
    }

    /// <summary>Entries held, stale ones included (at most about twice the queued objects plus a constant).</summary>
    public int EntryCount => _odometerWheel.Count + _anchorWheel.Count;

    /// <summary>The seen player position of this tick (global), as passed to <see cref="Advance"/>.</summary>
    public void Seen(out double x, out double y, out double z)
    {
        x = _seenX;
        y = _seenY;
        z = _seenZ;
    }

    /// <summary>The object of a popped entry.</summary>
    public PhysicsObj Object(in GateEntry e) => _obj[e.Slot]!;

    internal bool IsLive(in GateEntry e) => _generation[e.Slot] == e.Generation;

    internal void StaleDropped() => _stale--;

    /// <summary>True when a popped entry still belongs to its slot's object; a stale one is counted as dropped (the caller
    /// discards it).</summary>
    public bool Keep(in GateEntry e)
    {
        if (_generation[e.Slot] == e.Generation)
        {
            return true;
        }

        _stale--;
        return false;
    }

    /// <summary>
    /// Starts this tick for the queue: the odometer reading and the player position the queue's objects see, then pops the live
    /// entries now due into <paramref name="due"/> (grown as needed) and returns their number. Each popped object stays queued:
    /// the caller re-queues it (<see cref="Requeue"/>) or forgets it.
    /// </summary>
    public int Advance(double odometer, in Position seen, ref GateEntry[] due)
    {
        _odometer = odometer;
        GateEntry.Global(seen, out _seenX, out _seenY, out _seenZ);
        if (!_hasAnchor)
        {
            SetAnchor();
            _hasAnchor = true;
        }

        double dx = _seenX - _anchorX, dy = _seenY - _anchorY, dz = _seenZ - _anchorZ;
        _fromAnchor = Math.Sqrt(dx * dx + dy * dy + dz * dz);
        if (_fromAnchor > AnchorRadius)
        {
            _anchorTotal += _fromAnchor;
            SetAnchor();
            _fromAnchor = 0.0;
        }

        if (_stale > 1024 && _stale > EntryCount - _stale)
        {
            _odometerWheel.Compact();
            _anchorWheel.Compact();
            _stale = 0; // (the count may run high: an object woken after its entry was popped leaves nothing behind)
        }

        int n = _odometerWheel.PopDue(_odometer, ref due, 0);
        return _anchorWheel.PopDue(_anchorTotal + AnchorRadius, ref due, n);
    }

    private void SetAnchor()
    {
        _anchorX = _seenX;
        _anchorY = _seenY;
        _anchorZ = _seenZ;
    }

    /// <summary>Queues <paramref name="o"/> (queued nowhere), measured against this tick's seen position with the given side and
    /// safe margin (metres the player may travel before it could cross).</summary>
    public void Add(PhysicsObj o, bool far, bool idle, bool onWalkable, double margin)
    {
        int slot;
        if (_freeCount != 0)
        {
            slot = _free[--_freeCount];
        }
        else
        {
            if (_slotCount == _obj.Length)
            {
                GrowSlots();
            }

            slot = _slotCount++;
        }

        _obj[slot] = o;
        _flips[slot] = new Flips { Tick = NoFlip, PrevTick = NoFlip };
        o._gateQueue = this;
        o._gateSlot = slot;
        uint cell = o._position.ObjCellId;
        Vector3 origin = o._position.Frame.Origin;
        var e = new GateEntry
        {
            X = origin.X,
            Y = origin.Y,
            Z = origin.Z,
            Slot = slot,
            Generation = _generation[slot],
            BlockX = (byte)(cell >> 24),
            BlockY = (byte)(cell >> 16),
            Flags = (byte)((far ? GateFlags.Far : 0) | (idle ? GateFlags.Idle : 0) | (onWalkable ? GateFlags.OnWalkable : 0)),
        };
        Requeue(e, margin);
    }

    /// <summary>Puts a popped entry back, re-measured with <paramref name="margin"/> against this tick's seen position.</summary>
    public void Requeue(in GateEntry e, double margin)
    {
        if (margin < Split)
        {
            _odometerWheel.Push(e, _odometer + margin);
        }
        else
        {
            // Displacement since now <= (anchor total then - now) + the player's distance from the anchor then + now.
            _anchorWheel.Push(e, _anchorTotal + margin - _fromAnchor);
        }
    }

    /// <summary>Records that the slot's idle object crossed the gate in tick <paramref name="tick"/> (to the far side when
    /// <paramref name="far"/>); the last two crossings are kept, enough to answer for this tick and the one before.</summary>
    public void RecordFlip(int slot, long tick, bool far)
    {
        ref Flips f = ref _flips[slot];
        f.PrevTick = f.Tick;
        f.PrevFar = f.Far;
        f.Tick = tick;
        f.Far = far;
    }

    /// <summary>The last crossing of the slot's object in or before tick <paramref name="tick"/>, if any since it was queued.</summary>
    public bool LastFlip(int slot, long tick, out long flipTick, out bool far)
    {
        ref Flips f = ref _flips[slot];
        if (f.Tick != NoFlip && f.Tick <= tick)
        {
            flipTick = f.Tick;
            far = f.Far;
            return true;
        }

        if (f.PrevTick != NoFlip && f.PrevTick <= tick)
        {
            flipTick = f.PrevTick;
            far = f.PrevFar;
            return true;
        }

        flipTick = 0;
        far = false;
        return false;
    }

    /// <summary>Takes <paramref name="o"/> out of whichever queue holds it (no effect when none does); its entry becomes stale.</summary>
    public static void Forget(PhysicsObj o)
    {
        GateQueue? q = o._gateQueue;
        if (q is null)
        {
            return;
        }

        int slot = o._gateSlot;
        q._generation[slot]++;
        q._obj[slot] = null;
        if (q._freeCount == q._free.Length)
        {
            Array.Resize(ref q._free, q._free.Length * 2);
        }

        q._free[q._freeCount++] = slot;
        q._stale++;
        o._gateQueue = null;
        o._gateSlot = -1;
    }

    private void GrowSlots()
    {
        int size = _obj.Length * 2;
        Array.Resize(ref _obj, size);
        Array.Resize(ref _generation, size);
        Array.Resize(ref _flips, size);
    }
}
