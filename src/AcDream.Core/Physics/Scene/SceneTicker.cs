using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Scene;

/// <summary>
/// The scene's world tick: which objects a tick visits. Not retail; <see cref="PhysicsWorld"/> owns one and runs it instead of
/// visiting every object (<see cref="PhysicsWorld.VisitEveryObject"/>).
/// </summary>
/// <remarks>
/// <para>Retail walks every object every tick. Most objects of a client scene — trees, rocks, items on the ground, anything far
/// from the player — gain nothing from the visit: their retail update changes only bookkeeping (the ACTIVE bit, update_time, the
/// player vector). The scene keeps those objects <i>dormant</i> and never visits them; that bookkeeping is evaluated lazily, from
/// a few clocks the scene keeps per tick, to exactly the values retail would hold. Everything simulated (frames, velocities, cell
/// ids, contact state, hooks) is bit-identical to visiting every object (<see cref="PhysicsWorld.VisitEveryObject"/>), which the
/// tests check.</para>
/// <para>Objects wake on events, not by scanning: any mutating member (velocity, omega, hooks, interpolation, placement, state,
/// components…) wakes its object (the wake rule is written at <see cref="PhysicsObj.Touch"/>). A dormant object whose distance
/// to the player may cross the 96 m gate is tested only when the player has moved, and only while it lies near the 96 m circle
/// about the player (<see cref="GateQueue"/>: a ring of copies of the objects within 2 m of it, rebuilt as the player moves on),
/// from a copy of its position, so a still player costs nothing and a test reads no object. An idle object that crosses is not
/// visited either: the crossing is recorded and its bookkeeping follows retail's from that tick on. Only objects that would move
/// once near are woken by a crossing.</para>
/// <para>Objects are visited in ascending id order (then creation order), whatever the order in which they were created or woken.</para>
/// <para>The class is split by concern: the tick and its clocks (this file), the visiting list and the wakes
/// (<c>SceneTicker.Visiting.cs</c>), the 96 m gate and putting objects to sleep (<c>SceneTicker.Gate.cs</c>), and the dormant
/// bookkeeping (<c>SceneTicker.Dormancy.cs</c>).</para>
/// </remarks>
internal sealed partial class SceneTicker
{
    private readonly PhysicsWorld _world;

    // Reading ahead (VisitAwakeObjects): while an object is visited, the object 2 x LookAhead places on has its own fields
    // read and the one LookAhead places on its part array's, so that their memory is on its way by the time they are visited.
    // Objects are visited by id but lie in memory in creation order; created in random id order, each visit would otherwise
    // wait for its memory (100,000 movers: 3.2 times the cost per object of the same movers created in id order, about 2
    // with reading ahead; CreationOrderTickBenchmarks, docs/performance.md). The reads change nothing; their sum goes to _lookAheadSink only so
    // that they are not dropped.
    private const int LookAhead = 6;
    private int _lookAheadSink;
    private bool _inTick;
    private long _tick;
    private long _lastHugeTick = long.MinValue;
    private double _tickTimePrev, _tickTimeNow;
    private double _consumedPrev, _consumedNow;
    private double _pingPongPrev, _pingPongNow;
    private PhysicsObj? _playerSeenPrev, _playerSeenNow;
    private Position _playerBeforePrev, _playerAfterPrev, _playerBeforeNow, _playerAfterNow;

    // Whether this tick's retail visit of an idle object that crosses the gate leaves a state a dormancy kind describes: beyond
    // 96 m its update_time must come out as the world's consumed clock from any update_time an idle object can hold (the tick
    // time, the ping-pong time or the consumed clock of the tick before); within, one off walkable ground keeps ACTIVE and
    // update_time = now, which must be the consumed clock. Both hold except after stalls that leave time unconsumed.
    private bool _flipToFarOk, _flipToNearOk;

    /// <summary>Creates the scene of <paramref name="world"/>, whose clocks start at <paramref name="startTime"/>.</summary>
    internal SceneTicker(PhysicsWorld world, double startTime)
    {
        _world = world;
        _tickTimeNow = _tickTimePrev = startTime;
        _consumedNow = _consumedPrev = startTime;
        _pingPongNow = _pingPongPrev = startTime;
    }

    /// <summary>Number of scene ticks so far (the tick in progress during a tick).</summary>
    internal long SceneTick => _tick;

    internal double ConsumedClockNow => _consumedNow;

    internal double ConsumedClockPrev => _consumedPrev;

    internal double TickTime(bool visitedThisTick) => visitedThisTick ? _tickTimeNow : _tickTimePrev;

    internal double PingPongTime(bool visitedThisTick) => visitedThisTick ? _pingPongNow : _pingPongPrev;

    /// <summary>The scene's world tick: visits the awake objects in order, wakes those the player's travel may have carried across
    /// the 96 m gate, and puts to sleep those whose next visits would change nothing.</summary>
    /// <returns>The number of objects visited.</returns>
    internal int Tick()
    {
        AdvanceClocks();
        PhysicsObj? player = _playerSeenNow;
        MergePending();
        _inTick = true;
        if (player is not null)
        {
            // Objects ordered before the player see its position before its update.
            CheckGate(_gateBefore, _playerBeforeNow);
        }

        int visits = VisitAwakeObjects(player, out bool playerVisited);
        if (player is not null && !playerVisited)
        {
            // The player is dormant-proof, so it is always in the list; this covers a player with no cell (bails) too.
            CheckGate(_gateAfter, _playerAfterNow);
        }

        _inTick = false;
        _current = null;
        PutIdleToSleep();
        return visits;
    }

    /// <summary>The clock bookkeeping of a tick: the tick count, the clocks dormant objects' bookkeeping is evaluated from (tick
    /// time, consumed clock, ping-pong time, the last stall), whether a gate crossing can be recorded without a visit, and the
    /// player and its position as this tick begins (each kept with the tick before's).</summary>
    private void AdvanceClocks()
    {
        double now = _world.CurrentTime;
        double lastUpdate = _world.LastUpdate;
        _tick++;
        _tickTimePrev = _tickTimeNow;
        _tickTimeNow = now;
        if (now - lastUpdate > _world.Profile.HugeQuantum)
        {
            _lastHugeTick = _tick;
        }

        _consumedPrev = _consumedNow;
        _consumedNow = Consume(_consumedNow, now);
        _pingPongPrev = _pingPongNow;
        _pingPongNow = Consume(lastUpdate, now);
        _flipToFarOk = Consume(_tickTimePrev, now) == _consumedNow && Consume(_pingPongPrev, now) == _consumedNow;
        _flipToNearOk = _tickTimeNow == _consumedNow;
        _playerSeenPrev = _playerSeenNow;
        _playerBeforePrev = _playerBeforeNow;
        _playerAfterPrev = _playerAfterNow;

        PhysicsObj? player = _world.Player;
        _playerSeenNow = player;
        if (player is not null)
        {
            _playerBeforeNow = player._position;
            _playerAfterNow = _playerBeforeNow;
        }
    }

    /// <summary>Runs update_object on every object in the visiting list, in order; after the player's own update, tells the
    /// listener and tests the gate of the objects ordered after it.</summary>
    private int VisitAwakeObjects(PhysicsObj? player, out bool playerVisited)
    {
        playerVisited = false;
        int visits = 0;
        _activeCursor = _active.Start();
        while (_active.MoveNext(ref _activeCursor, out PhysicsObj obj))
        {
            _current = obj;
            _currentKey = _activeCursor.LastKey;
            PhysicsObj? far = _active.Ahead(_activeCursor, LookAhead * 2);
            if (far is not null)
            {
                _lookAheadSink += far.TouchForVisit();
            }

            PhysicsObj? near = _active.Ahead(_activeCursor, LookAhead);
            if (near is not null)
            {
                _lookAheadSink += near.TouchComponentsForVisit();
            }

            obj.UpdateObject();
            visits++;
            if (obj == player)
            {
                _world.PlayerListener?.PlayerPhysicsUpdated(obj);
                _playerAfterNow = player._position;
                CheckGate(_gateAfter, _playerAfterNow);
                playerVisited = true;
            }
        }

        return visits;
    }

    /// <summary>update_object's consumed-time arithmetic without the steps: the update_time an idle object ends with.</summary>
    private double Consume(double updateTime, double now)
    {
        var slicer = new QuantumSlicer(_world.Profile, updateTime, now);
        while (slicer.Next(out _))
        {
        }

        return slicer.EndTime(updateTime);
    }
}
