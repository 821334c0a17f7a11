using System;
using System.Numerics;
using AcDream.Core.Physics.Math;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Scene;

namespace AcDream.Core.Physics.World;

/// <summary>
/// The scene side of the world: which objects a tick visits.
/// </summary>
/// <remarks>
/// <para>Retail walks every object every tick. Most objects of a client scene — trees, rocks, items on the ground, anything far
/// from the player — gain nothing from the visit: their retail update changes only bookkeeping (the ACTIVE bit, update_time, the
/// player vector). The world keeps those objects <i>dormant</i> and never visits them; that bookkeeping is evaluated lazily, from
/// a few clocks the world keeps per tick, to exactly the values retail would hold. Everything simulated (frames, velocities, cell
/// ids, contact state, hooks) is bit-identical to visiting every object (<see cref="VisitEveryObject"/>), which the tests check.</para>
/// <para>Objects wake on events, not by scanning: any mutating member (velocity, omega, hooks, interpolation, placement, state,
/// components…) wakes its object. A dormant object whose distance to the player may cross the 96 m gate is tested only when the
/// player has moved, and only while it lies near the 96 m circle about the player (<see cref="GateQueue"/>: a ring of copies of
/// the objects within 2 m of it, rebuilt as the player moves on), from a copy of its position, so a still player costs nothing
/// and a test reads no object. An idle object that crosses is not visited either: the crossing is recorded and its
/// bookkeeping follows retail's from that tick on. Only objects that would move once near are woken by a crossing.</para>
/// <para>Objects are visited in ascending id order (then creation order), whatever the order in which they were created or woken.</para>
/// </remarks>
public sealed partial class PhysicsWorld
{
    private PhysicsObj[] _active = new PhysicsObj[16];
    private int _activeCount;
    private PhysicsObj[] _pending = new PhysicsObj[16];
    private int _pendingCount;
    private bool _inTick;
    private long _tick;
    private long _lastHugeTick = long.MinValue;
    private double _tickTimePrev, _tickTimeNow;
    private double _consumedPrev, _consumedNow;
    private double _pingPongPrev, _pingPongNow;
    private PhysicsObj? _playerSeenPrev, _playerSeenNow;
    private Position _playerBeforePrev, _playerAfterPrev, _playerBeforeNow, _playerAfterNow;
    private PhysicsObj? _current;
    // Objects ordered before the player see its position before its update; those after, after it: one queue each, so each
    // is tested against the position it sees.
    private readonly GateQueue _gateBefore = new();
    private readonly GateQueue _gateAfter = new();
    private GateHit[] _gateHits = new GateHit[16];

    /// <summary>
    /// The effects this scene simulates; <see cref="SceneEffects.All"/> (retail) by default. Declare fewer to pay for fewer.
    /// </summary>
    public SceneEffects Effects { get; init; } = SceneEffects.All;

    /// <summary>
    /// When true, every object is visited every tick, as retail walks its object table (for comparison and diagnostics).
    /// False by default: dormant objects are skipped, with identical simulated results.
    /// </summary>
    public bool VisitEveryObject { get; init; }

    /// <summary>
    /// How dormant objects follow the player's 96 m gate. <see cref="GateTracking.Exact"/> (the default) keeps their bookkeeping
    /// exactly retail's; <see cref="GateTracking.MovingObjectsOnly"/> re-measures only dormant objects that would move once near.
    /// </summary>
    public GateTracking GateTracking { get; init; } = GateTracking.Exact;

    /// <summary>Gate statistics since the world was created: dormant objects' copies re-measured against the 96 m gate, crossings
    /// handled without a visit, and crossings that woke the object.</summary>
    internal long GateRemeasures, GateFlips, GateWakes;

    /// <summary>What the 96 m gate tracking has done since the world was created (re-measurements, crossings applied without a
    /// visit, crossings that woke their object).</summary>
    public GateStatistics GateStatistics => new(GateRemeasures, GateFlips, GateWakes);

    /// <summary>Number of objects visited by the last tick (awake objects).</summary>
    public int LastTickVisitCount { get; private set; }

    /// <summary>Number of objects currently dormant (never visited until an event wakes them).</summary>
    public int DormantCount => _count - _activeCount - _pendingCount;

    internal double ConsumedClockNow => _consumedNow;

    /// <summary>Entries the gate queues hold, stale ones included (bounded by about twice the queued objects plus a constant).</summary>
    internal int GateEntryCount => _gateBefore.EntryCount + _gateAfter.EntryCount;

    /// <summary>Number of scene ticks so far (the tick in progress during a tick).</summary>
    internal long SceneTick => _tick;

    // Whether this tick's retail visit of an idle object that crosses the gate leaves a state a dormancy kind describes: beyond
    // 96 m its update_time must come out as the world's consumed clock from any update_time an idle object can hold (the tick
    // time, the ping-pong time or the consumed clock of the tick before); within, one off walkable ground keeps ACTIVE and
    // update_time = now, which must be the consumed clock. Both hold except after stalls that leave time unconsumed.
    private bool _flipToFarOk, _flipToNearOk;

    internal double ConsumedClockPrev => _consumedPrev;

    internal double TickTime(bool visitedThisTick) => visitedThisTick ? _tickTimeNow : _tickTimePrev;

    internal double PingPongTime(bool visitedThisTick) => visitedThisTick ? _pingPongNow : _pingPongPrev;

    /// <summary>An object whose player_distance (a float) is within this of 96 m stays awake: the float may have rounded across
    /// 96 from the double update_object compared, so its side is not known from it (an ulp at 96 is 7.6e-6).</summary>
    internal static float GateSafetyMargin => 1e-4f;

    /// <summary>How far retail's distance (float offsets, spilled sums) and the queue's estimate (double arithmetic on float
    /// copies of the positions, within ~3e-5 m) may differ: far below this. Within twice this of 96 m, retail's own arithmetic
    /// decides.</summary>
    private static double GateKeySlack(double distance) => 2e-4 + distance * 2e-6;

    /// <summary>True when, during a tick, the object's place in the visiting order has already passed (retail already visited it).</summary>
    internal bool IsVisitedThisTick(PhysicsObj obj) => !_inTick || (_current is not null && obj.WorldIndex <= _current.WorldIndex);

    /// <summary>ACTIVE after the last (or the previous) tick for a ping-pong object put to sleep after tick <paramref name="sleepTick"/>.</summary>
    internal bool PingPongActive(long sleepTick, bool sleepActive, bool visitedThisTick)
    {
        long n = visitedThisTick ? _tick : _tick - 1;
        long huge = _lastHugeTick <= n ? _lastHugeTick : long.MinValue;
        if (huge > sleepTick)
        {
            // A stall longer than HugeQuantum leaves every ping-pong object ACTIVE; then they alternate again.
            return ((n - huge) & 1) == 0;
        }

        return sleepActive ^ (((n - sleepTick) & 1) == 1);
    }

    /// <summary>The player's position as this object saw it in its last visit (before or after the player's own update).</summary>
    internal bool PlayerSeenPosition(PhysicsObj obj, bool visitedThisTick, out Position seen)
    {
        PhysicsObj? p = visitedThisTick ? _playerSeenNow : _playerSeenPrev;
        if (p is null)
        {
            seen = default;
            return false;
        }

        // Relative order never changes (creation and removal keep it), so the live indexes decide before/after.
        bool afterPlayer = obj.WorldIndex > p.WorldIndex;
        seen = visitedThisTick
            ? (afterPlayer ? _playerAfterNow : _playerBeforeNow)
            : (afterPlayer ? _playerAfterPrev : _playerBeforePrev);
        return true;
    }

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
        obj.MarkPendingWake();
    }

    /// <summary>Wakes a dormant object: materialises its bookkeeping and schedules its visits.</summary>
    internal void WakeDormant(PhysicsObj obj)
    {
        obj.Materialize(IsVisitedThisTick(obj));
        obj.MarkAwake();
        GateForget(obj);
        EnqueueWake(obj);
    }

    /// <summary>Wakes every dormant object that depends on the player or on object maintenance (they changed).</summary>
    private void WakeGatedDormant()
    {
        for (int i = 0; i < _count; i++)
        {
            PhysicsObj o = _objects[i];
            if (o._dormancy is Dormancy.ConsumedClock or Dormancy.PingPong)
            {
                WakeDormant(o);
            }
        }
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
        obj.SetInActiveList(true);
        if (_inTick && lo <= _activeCursor)
        {
            _activeCursor++;
        }
    }

    private int _activeCursor;

    private static void GateForget(PhysicsObj o) => GateQueue.Forget(o);

    private void RemoveFromVisiting(PhysicsObj obj)
    {
        GateForget(obj);
        if (obj._inActiveList)
        {
            int at = Array.IndexOf(_active, obj, 0, _activeCount);
            Array.Copy(_active, at + 1, _active, at, _activeCount - at - 1);
            _activeCount--;
            _active[_activeCount] = null!;
            obj.SetInActiveList(false);
            if (_inTick && at <= _activeCursor)
            {
                _activeCursor--;
            }
        }

        if (obj._pendingWake)
        {
            int at = Array.IndexOf(_pending, obj, 0, _pendingCount);
            Array.Copy(_pending, at + 1, _pending, at, _pendingCount - at - 1);
            _pendingCount--;
            _pending[_pendingCount] = null!;
            obj.ClearPendingWake();
        }

        obj.MarkAwake();
    }

    private void MergePending()
    {
        for (int i = 0; i < _pendingCount; i++)
        {
            PhysicsObj o = _pending[i];
            _pending[i] = null!;
            o.ClearPendingWake();
            if (o.WorldIndex >= 0 && !o._inActiveList && o._dormancy == Dormancy.Awake)
            {
                InsertActive(o);
            }
        }

        _pendingCount = 0;
    }

    /// <summary>update_object's consumed-time arithmetic without the steps: the update_time an idle object ends with.</summary>
    private double Consume(double updateTime, double now)
    {
        var slicer = new QuantumSlicer(Profile, updateTime, now);
        while (slicer.Next(out _))
        {
        }

        return slicer.EndTime(updateTime);
    }

    /// <summary>The scene's world tick: visits the awake objects in order, wakes those the player's travel may have carried across
    /// the 96 m gate, and puts to sleep those whose next visits would change nothing.</summary>
    private void UseTimeScene()
    {
        _tick++;
        _tickTimePrev = _tickTimeNow;
        _tickTimeNow = CurrentTime;
        if (CurrentTime - LastUpdate > Profile.HugeQuantum)
        {
            _lastHugeTick = _tick;
        }

        _consumedPrev = _consumedNow;
        _consumedNow = Consume(_consumedNow, CurrentTime);
        _pingPongPrev = _pingPongNow;
        _pingPongNow = Consume(LastUpdate, CurrentTime);
        _flipToFarOk = Consume(_tickTimePrev, CurrentTime) == _consumedNow && Consume(_pingPongPrev, CurrentTime) == _consumedNow;
        _flipToNearOk = _tickTimeNow == _consumedNow;
        _playerSeenPrev = _playerSeenNow;
        _playerBeforePrev = _playerBeforeNow;
        _playerAfterPrev = _playerAfterNow;

        PhysicsObj? player = _player;
        _playerSeenNow = player;
        if (player is not null)
        {
            _playerBeforeNow = player._position;
            _playerAfterNow = _playerBeforeNow;
        }

        MergePending();
        _inTick = true;
        bool checkedAfterPlayer = player is null;
        if (player is not null)
        {
            // Objects ordered before the player see its position before its update.
            CheckGate(_gateBefore, _playerBeforeNow);
        }

        int visits = 0;
        for (_activeCursor = 0; _activeCursor < _activeCount; _activeCursor++)
        {
            PhysicsObj obj = _active[_activeCursor];
            _current = obj;
            obj.UpdateObject();
            visits++;
            if (obj == player)
            {
                PlayerListener?.PlayerPhysicsUpdated(obj);
                _playerAfterNow = player._position;
                CheckGate(_gateAfter, _playerAfterNow);
                checkedAfterPlayer = true;
            }
        }

        if (!checkedAfterPlayer && player is not null)
        {
            // The player is dormant-proof, so it is always in the list; this covers a player with no cell (bails) too.
            CheckGate(_gateAfter, _playerAfterNow);
        }

        _inTick = false;
        _current = null;
        LastTickVisitCount = visits;
        PutIdleToSleep();
    }

    /// <summary>Tests the dormant gated objects whose side of 96 m the player's movement may have changed (the queue's bands,
    /// from the positions the queue holds, touching no object). An idle object that crossed the gate has the crossing recorded,
    /// and takes the state this tick's visit leaves when next read (<see cref="PhysicsObj.Materialize"/>); an object that must
    /// move once near and one whose crossing leaves a state no dormancy kind describes are woken and visited later in this same
    /// tick, in order. Near the boundary the side is decided with retail's own arithmetic.</summary>
    private void CheckGate(GateQueue queue, in Position seen)
    {
        int n = queue.Advance(seen, ref _gateHits, out long tested);
        GateRemeasures += tested;
        if (n != 0)
        {
            queue.Seen(out double sx, out double sy, out double sz);
            for (int i = 0; i < n; i++)
            {
                GateHit h = _gateHits[i];
                if (!queue.IsLive(h))
                {
                    continue; // the object was woken or removed since (or an earlier hit of this tick woke it)
                }

                queue.Position(h, out double gx, out double gy, out double gz);
                double dx = gx - sx, dy = gy - sy, dz = gz - sz;
                double d = System.Math.Sqrt(dx * dx + dy * dy + dz * dz);
                if (!(System.Math.Abs(d - PhysicsGlobals.PlayerActivityDistance) > 2.0 * GateKeySlack(d)))
                {
                    // Near the boundary: decide with retail's own arithmetic (update_object's get_offset and double sqrt).
                    Vector3 pv = seen.GetOffset(queue.Object(h.Slot)._position);
                    d = System.Math.Sqrt((double)pv.X * pv.X + (double)pv.Y * pv.Y + (double)pv.Z * pv.Z);
                }

                bool isFar = d > PhysicsGlobals.PlayerActivityDistance;
                if (isFar == queue.IsFar(h.Slot))
                {
                    continue;
                }

                bool describable = (h.Flags & GateFlags.Idle) != 0
                    && (isFar ? _flipToFarOk : (h.Flags & GateFlags.OnWalkable) != 0 || _flipToNearOk);
                if (!describable)
                {
                    GateWakes++;
                    WakeDormant(queue.Object(h.Slot));
                    continue;
                }

                queue.RecordFlip(h.Slot, _tick, isFar);
                GateFlips++;
            }
        }

        queue.Finish(_gateHits, n);
    }

    /// <summary>After the visits: objects whose next visits would change nothing but bookkeeping leave the visiting list.</summary>
    private void PutIdleToSleep()
    {
        // The gate queues measure against the player this tick began with; after a change of player mid-tick, gated objects
        // wait a tick before they sleep.
        bool gateReady = _player == _playerSeenNow;
        int w = 0;
        for (int i = 0; i < _activeCount; i++)
        {
            PhysicsObj o = _active[i];
            Dormancy d = o.ClassifyForSleep(out float margin);
            if (d == Dormancy.Awake || (!gateReady && !float.IsNaN(margin)))
            {
                _active[w++] = o;
                continue;
            }

            o.EnterDormancy(d, _tick);
            GateForget(o);
            if (!float.IsNaN(margin) && d != Dormancy.Bailed)
            {
                // Idle: it never moves on either side of the gate, so a crossing only changes its bookkeeping (no visit).
                bool idle = o.IsIdleForScene();
                if (GateTracking == GateTracking.Exact || !idle)
                {
                    bool before = _player is not null && o.WorldIndex < _player.WorldIndex;
                    float pd = o._playerDistance;
                    (before ? _gateBefore : _gateAfter).Add(o, pd > PhysicsGlobals.PlayerActivityDistance, idle,
                        (o._transientState & TransientState.OnWalkable) != 0);
                }
            }
        }

        for (int i = w; i < _activeCount; i++)
        {
            _active[i] = null!;
        }

        _activeCount = w;
    }
}
