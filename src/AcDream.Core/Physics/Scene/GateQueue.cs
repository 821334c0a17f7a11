using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Scene;

/// <summary>
/// Dormant objects whose side of the 96 m player gate the player's movement could change, and the bands that find the ones
/// it may have changed. One queue per side of the player in the visiting order (objects before the player see its position
/// before its update).
/// </summary>
/// <remarks>
/// <para>Distance is 1-Lipschitz in the player's position: an object whose distance from a point C is more than ρ from 96 m keeps
/// its side while the player stays within ρ of C. So only the objects near C's 96 m circle need testing while the player stays
/// near C, and the queue keeps two bands of copies (<see cref="GateBand"/>): the <i>ring</i> (half-width
/// <see cref="RingHalfWidth"/>), tested at every tick the player moved, and the <i>band</i> (<see cref="BandHalfWidth"/>), about
/// its own centre, from which the ring is rebuilt around the player once it strays <see cref="RingHalfWidth"/> from the ring's
/// centre. When the band no longer covers the ring's needs, both are rebuilt from the cells of the grid that can hold
/// an object near the player's circle (<see cref="GateGrid"/>).
/// A still player costs nothing; one moving about a spot tests only the ring; a walking one rebuilds the ring every 2 m and the
/// band every ~10 m. The scans are conservative filters; the caller decides each flagged object (<see cref="Advance"/>).</para>
/// <para>Each slot and its grid entry keep what a test needs (position, side, flags), so testing reads no object. A crossing by an idle object is
/// recorded in the slot (<see cref="RecordFlip"/>), which keeps every copy's side current, and applied when the object is next
/// read; only objects that must move are woken.</para>
/// <para>Slots carry a generation: <see cref="Forget"/> bumps it, so band copies of the slot go stale; a stale copy is dropped
/// when the scan flags it, when its band is rebuilt, or by a compaction once the objects forgotten since the band was built
/// reach a quarter of it (or it has grown to twice its built size). Memory stays bounded and, once grown, never
/// allocates.</para>
/// </remarks>
internal sealed class GateQueue
{
    /// <summary>Half-width (metres) of the ring tested every tick the player moved, and how far the player may stray from its
    /// centre before it is rebuilt.</summary>
    public const double RingHalfWidth = 2.0;

    /// <summary>Half-width (metres) of the band the ring is rebuilt from.</summary>
    public const double BandHalfWidth = 12.0;

    /// <summary>Membership slack (metres): a band holds every entry within its half-width plus this of 96 m, so float rounding of
    /// the band's copies never leaves out one it must hold.</summary>
    public const double MemberSlack = 0.05;

    /// <summary>Scan tolerance on d² (m², about 1.3 mm of distance at 96 m): covers the float rounding of the band copies and the
    /// difference between the double estimate and retail's own arithmetic, which the caller resolves.</summary>
    public const float ScanTolerance = 0.25f;

    private const double Gate = PhysicsGlobals.PlayerActivityDistance;
    private const byte FromRing = 0, FromBand = 1, FromGrid = 2;
    private const long NoFlip = long.MinValue;

    // A slot's record, what a hit reads and writes in one cache line: its state (generation << 1 | 1 when beyond 96 m at its
    // last check), so that liveness and side are one read, its last two gate crossings since it was queued (tick, side), and
    // where its entry is in the grid. The grid entry says where the band holds a copy, so that a crossing updates the sides of
    // the entry and of that copy too: every copy's side stays current, and a ring rebuilt from the band starts current.
    private struct SlotRecord
    {
        public int State;
        public int Cell, CellIndex;
        public bool Far, PrevFar;
        public long Tick, PrevTick;
    }

    // Slots: the object, its record, its flags; the grid holds its position.
    private PhysicsObj?[] _obj = new PhysicsObj?[64];
    private SlotRecord[] _record = new SlotRecord[64];
    private byte[] _flags = new byte[64];
    private readonly GateGrid _grid = new();
    private int[] _free = new int[64];
    private int _freeCount;
    private int _slotCount;

    private readonly GateBand _ring = new(RingHalfWidth);
    private readonly GateBand _band = new(BandHalfWidth);

    // Objects forgotten since each band was built or compacted: a band is compacted once they reach a quarter of its entries
    // (whether or not they were in it), which bounds its stale copies at a quarter and costs O(1) amortised per forget.
    private int _forgottenSinceRing, _forgottenSinceBand;

    // The player position last tested against (the position the queue's objects saw).
    private bool _hasSeen;
    private uint _seenCell;
    private Vector3 _seenOrigin;
    private double _seenX, _seenY, _seenZ;

    // A rebuild decided by Advance and done by Finish (after the caller has resolved the hits, so copies take the new sides).
    private byte _rebuild; // 0 none; FromBand: the ring from the band's selection; FromGrid: both from the grid's places below
    private long[] _hitPlaces = new long[64];
    private long[] _ringPlaces = new long[64];
    private int _ringPlaceCount;
    private long[] _bandPlaces = new long[64];
    private int _bandPlaceCount;

    /// <summary>Grid entries and band copies, dead and stale ones included (bounded by a small multiple of the queued objects).</summary>
    public int EntryCount => _grid.Held + _ring.Count + _band.Count;

    /// <summary>The player position of this tick's <see cref="Advance"/> (global).</summary>
    public void Seen(out double x, out double y, out double z)
    {
        x = _seenX;
        y = _seenY;
        z = _seenZ;
    }

    /// <summary>The object in a slot.</summary>
    public PhysicsObj Object(int slot) => _obj[slot]!;

    /// <summary>True when the slot still holds the object it held at generation <paramref name="generation"/>.</summary>
    public bool IsCurrent(int slot, int generation) => _record[slot].State >> 1 == generation;

    /// <summary>True when the hit's object is still in the queue (it was not woken or removed since the scan).</summary>
    public bool IsLive(in GateHit h) => IsCurrent(h.Slot, h.Generation);

    /// <summary>True when the slot's object was beyond 96 m at its last check.</summary>
    public bool IsFar(int slot) => (_record[slot].State & 1) != 0;

    /// <summary>A hit's global position: from the band copy it came from (float offsets, within ~3e-5 m), or from its slot.</summary>
    public void Position(in GateHit h, out double x, out double y, out double z)
    {
        GateBand? b = BandOf(h);
        if (b is not null)
        {
            b.Position(h.Index, out x, out y, out z);
            return;
        }

        _grid.Global(h.Cell, h.Index, out x, out y, out z);
    }

    /// <summary>A position's global x, y, z: block offsets are whole multiples of 192 m (as <c>LandDefs::get_block_offset</c>), so
    /// differences of these agree with <c>Position::get_offset</c> to float rounding.</summary>
    public static void Global(in Position p, out double x, out double y, out double z)
    {
        uint cell = p.ObjCellId;
        x = ((cell >> 24) & 0xFF) * (double)LandDefs.BlockLength + p.Frame.Origin.X;
        y = ((cell >> 16) & 0xFF) * (double)LandDefs.BlockLength + p.Frame.Origin.Y;
        z = p.Frame.Origin.Z;
    }

    /// <summary>
    /// Tests the queue against this tick's player position <paramref name="seen"/>: writes into <paramref name="hits"/> (grown as
    /// needed) every live entry that may have crossed 96 m since it was last tested (and some near 96 m that did not), and returns
    /// their number; <paramref name="tested"/> is the number of entries tested. Nothing is tested when the player has not moved.
    /// The caller resolves each hit (<see cref="IsFar"/>, <see cref="RecordFlip"/>, or a wake), then calls <see cref="Finish"/>.
    /// </summary>
    public int Advance(in Position seen, ref GateHit[] hits, out long tested)
    {
        tested = 0;
        if (_hasSeen && seen.ObjCellId == _seenCell && seen.Frame.Origin == _seenOrigin)
        {
            return 0;
        }

        _hasSeen = true;
        _seenCell = seen.ObjCellId;
        _seenOrigin = seen.Frame.Origin;
        Global(seen, out _seenX, out _seenY, out _seenZ);
        double px = _seenX, py = _seenY, pz = _seenZ;
        float r2 = (float)(Gate * Gate);
        double fromRing = _ring.Valid ? _ring.DistanceTo(px, py, pz) : double.PositiveInfinity;
        if (fromRing < RingHalfWidth)
        {
            tested = _ring.Count;
            return _ring.Scan(px, py, pz, r2, ScanTolerance, FromRing, ref hits, 0);
        }

        // The player left the ring. Entries that may have crossed since their last test lie within fromRing of 96 m about the
        // ring's centre; the new ring about the player holds those within RingHalfWidth (+ slack) of 96 m about the player. If
        // the band holds both sets, the ring is rebuilt from it; otherwise both are rebuilt from the grid.
        double fromBand = _band.Valid ? _band.DistanceTo(px, py, pz) : double.PositiveInfinity;
        double centres = _ring.Valid && _band.Valid
            ? _band.DistanceTo(_ring.CentreX, _ring.CentreY, _ring.CentreZ)
            : double.PositiveInfinity;
        if (fromRing + centres + MemberSlack <= BandHalfWidth && RingHalfWidth + MemberSlack + fromBand <= BandHalfWidth)
        {
            // (The ring's entries are all in the band: its region lay inside the band's when it was built, and additions go to
            // both; so the band's scan finds every crossing.)
            tested = _band.Count;
            double lo = Math.Max(0.0, Gate - RingHalfWidth - MemberSlack), hi = Gate + RingHalfWidth + MemberSlack;
            _rebuild = FromBand;
            return _band.Scan(px, py, pz, r2, ScanTolerance, FromBand, ref hits, 0, true, (float)(lo * lo), (float)(hi * hi));
        }

        // Entries that may have crossed lie within fromRing of 96 m about the ring's centre (all, before the first build).
        _rebuild = FromGrid;
        int n = _grid.Select(px, py, pz, _ring.CentreX, _ring.CentreY, _ring.CentreZ,
            _ring.Valid ? fromRing + MemberSlack : double.PositiveInfinity, BandHalfWidth + MemberSlack, RingHalfWidth + MemberSlack,
            ScanTolerance, ref _hitPlaces, ref _bandPlaces, out _bandPlaceCount, ref _ringPlaces, out _ringPlaceCount, out tested);
        if (n > hits.Length)
        {
            Array.Resize(ref hits, Math.Max(n, hits.Length * 2));
        }

        for (int i = 0; i < n; i++)
        {
            int cell = GateGrid.CellOf(_hitPlaces[i]), index = GateGrid.IndexOf(_hitPlaces[i]);
            ref GateGrid.Entry e = ref _grid.At(cell, index);
            hits[i] = new GateHit(e.Slot, e.Generation, e.Flags, FromGrid, index, cell);
        }

        return n;
    }

    /// <summary>Ends this tick's <see cref="Advance"/> once its hits are resolved: band copies of the hits take their slots' sides
    /// (stale ones die), then any rebuild Advance decided is done about the player's position, and bands grown stale are
    /// compacted.</summary>
    public void Finish(GateHit[] hits, int n)
    {
        for (int i = 0; i < n; i++)
        {
            GateHit h = hits[i];
            GateBand? b = BandOf(h);
            if (b is null)
            {
                continue;
            }

            if (IsLive(h))
            {
                b.SetSide(h.Index, IsFar(h.Slot));
            }
            else
            {
                b.Kill(h.Index);
            }
        }

        if (_rebuild == FromBand)
        {
            // The ring inherits the band's stale copies in its selection: no more than the band's compaction rule allows.
            _ring.Reset(_seenX, _seenY, _seenZ);
            _band.CopyMembersTo(_ring);
            _ring.MarkBuilt();
            _forgottenSinceRing = 0;
        }
        else if (_rebuild == FromGrid)
        {
            _ring.Reset(_seenX, _seenY, _seenZ);
            _band.Reset(_seenX, _seenY, _seenZ);
            AppendPlaces(_ring, _ringPlaces, _ringPlaceCount);
            AppendPlaces(_band, _bandPlaces, _bandPlaceCount);
            _ring.MarkBuilt();
            _band.MarkBuilt();
            _forgottenSinceRing = _forgottenSinceBand = 0;
        }

        _rebuild = 0;
        _grid.Sweep(this); // only here: the places a rebuild selected stay valid until now, whatever was forgotten meanwhile
        if (_forgottenSinceRing * 4 > _ring.CountAtBuild + 64 || _ring.Count > 2 * _ring.CountAtBuild + 64)
        {
            _ring.Compact(this);
            _forgottenSinceRing = 0;
        }

        if (_forgottenSinceBand * 4 > _band.CountAtBuild + 64 || _band.Count > 2 * _band.CountAtBuild + 64)
        {
            _band.Compact(this);
            _forgottenSinceBand = 0;
        }
    }

    /// <summary>Queues <paramref name="o"/> (queued nowhere), tested against this tick's player position: on the far side of 96 m
    /// when <paramref name="far"/>.</summary>
    public void Add(PhysicsObj o, bool far, bool idle, bool onWalkable)
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
        ref SlotRecord r = ref _record[slot];
        r.State = (r.State & ~1) | (far ? 1 : 0);
        r.Tick = NoFlip;
        r.PrevTick = NoFlip;
        _flags[slot] = (byte)((idle ? GateFlags.Idle : 0) | (onWalkable ? GateFlags.OnWalkable : 0));
        Global(o._position, out double x, out double y, out _);
        _grid.Add(slot, r.State >> 1, _flags[slot], x, y, o._position.Frame.Origin.Z, far, out r.Cell, out r.CellIndex);
        o._scene.GateQueue = this;
        o._scene.GateSlot = slot;
        AppendIfNear(_ring, slot);
        AppendIfNear(_band, slot);
    }

    /// <summary>Records that the slot's idle object crossed the gate in tick <paramref name="tick"/> (to the far side when
    /// <paramref name="far"/>), which is now its side; the last two crossings are kept, enough to answer for this tick and the
    /// one before.</summary>
    public void RecordFlip(int slot, long tick, bool far)
    {
        ref SlotRecord f = ref _record[slot];
        f.State = (f.State & ~1) | (far ? 1 : 0);
        ref GateGrid.Entry e = ref _grid.At(f.Cell, f.CellIndex);
        e.Side = far ? 1f : -1f;
        if (e.BandEpoch == _band.Epoch)
        {
            _band.SetSide(e.BandIndex, far);
        }
        f.PrevTick = f.Tick;
        f.PrevFar = f.Far;
        f.Tick = tick;
        f.Far = far;
    }

    /// <summary>The last crossing of the slot's object in or before tick <paramref name="tick"/>, if any since it was queued.</summary>
    public bool LastFlip(int slot, long tick, out long flipTick, out bool far)
    {
        ref SlotRecord f = ref _record[slot];
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

    /// <summary>Takes <paramref name="o"/> out of whichever queue holds it (no effect when none does); its band copies go stale.</summary>
    public static void Forget(PhysicsObj o)
    {
        GateQueue? q = o._scene.GateQueue;
        if (q is null)
        {
            return;
        }

        int slot = o._scene.GateSlot;
        q._record[slot].State = ((q._record[slot].State >> 1) + 1) << 1; // next generation: its copies are stale
        q._obj[slot] = null;
        q._grid.Remove(q._record[slot].Cell, q._record[slot].CellIndex);

        if (q._freeCount == q._free.Length)
        {
            Array.Resize(ref q._free, q._free.Length * 2);
        }

        q._free[q._freeCount++] = slot;
        q._forgottenSinceRing++;
        q._forgottenSinceBand++;
        o._scene.GateQueue = null;
        o._scene.GateSlot = -1;
    }

    private GateBand? BandOf(in GateHit h) => h.Band == FromRing ? _ring : h.Band == FromBand ? _band : null;

    private void AppendPlaces(GateBand band, long[] places, int count)
    {
        for (int i = 0; i < count; i++)
        {
            AppendPlace(band, GateGrid.CellOf(places[i]), GateGrid.IndexOf(places[i]));
        }
    }

    private void AppendPlace(GateBand band, int cell, int index)
    {
        ref GateGrid.Entry e = ref _grid.At(cell, index);
        if (e.Slot < 0)
        {
            return; // forgotten since it was selected
        }

        _grid.Global(cell, index, out double x, out double y, out double z);
        int at = band.Append(e.Slot, e.Generation, e.Flags, x, y, z, e.Side > 0f);
        if (band == _band)
        {
            e.BandIndex = at;
            e.BandEpoch = band.Epoch;
        }
    }

    /// <summary>A slot's grid entry has moved to <paramref name="index"/> in its cell (the grid is sweeping).</summary>
    internal void EntryMoved(int slot, int index) => _record[slot].CellIndex = index;

    /// <summary>A band's entry for a slot's object has moved to <paramref name="index"/> (the band is compacting).</summary>
    internal void Moved(GateBand band, int slot, int index)
    {
        if (band == _band)
        {
            ref SlotRecord r = ref _record[slot];
            ref GateGrid.Entry e = ref _grid.At(r.Cell, r.CellIndex);
            e.BandIndex = index;
            e.BandEpoch = band.Epoch;
        }
    }

    private void AppendIfNear(GateBand band, int slot)
    {
        ref SlotRecord r = ref _record[slot];
        if (band.Valid)
        {
            _grid.Global(r.Cell, r.CellIndex, out double x, out double y, out double z);
            if (Math.Abs(band.DistanceTo(x, y, z) - Gate) < band.HalfWidth + MemberSlack)
            {
                AppendPlace(band, r.Cell, r.CellIndex);
            }
        }
    }

    private void GrowSlots()
    {
        int size = _obj.Length * 2;
        Array.Resize(ref _obj, size);
        Array.Resize(ref _record, size);
        Array.Resize(ref _flags, size);
    }
}

/// <summary>Bits of a gate slot's flags.</summary>
internal static class GateFlags
{
    /// <summary>Idle: a visit on either side of the gate changes nothing but bookkeeping, so a crossing needs no visit.</summary>
    public const byte Idle = 2;

    /// <summary>On walkable ground (within 96 m it then re-activates every other tick).</summary>
    public const byte OnWalkable = 4;
}
