using System;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.Scene;

namespace AcDream.Core.Physics.World;

/// <summary>
/// A physics scene: the objects it owns and the state that retail kept in globals — the client clock
/// (<c>Timer::cur_time</c>), the physics clock (<c>PhysicsTimer::curr_time</c>), the last world update (<c>CPhysics</c>'
/// <c>last_update</c>), the player (<c>CPhysicsObj::player_object</c>) and object maintenance
/// (<c>CObjectMaint::is_active</c>). Two worlds share nothing and can tick side by side.
/// </summary>
/// <remarks>Not thread-safe: one world is ticked by one thread at a time.</remarks>
public sealed partial class PhysicsWorld
{
    // The object table, in ascending id order (equal ids: creation order), the order a tick visits objects in.
    private readonly VisitOrderList _objects = new();
    private ulong _created;
    private PhysicsObj? _player;
    private readonly System.Collections.Generic.Dictionary<uint, PhysicsObj> _byId = new();
    private bool _inUseTime;

    /// <summary>Creates a world whose clocks start at <paramref name="startTime"/> seconds.</summary>
    /// <param name="startTime">Initial client time, seconds.</param>
    /// <param name="profile">Time-slicing profile; <see cref="PhysicsProfile.Retail"/> when null.</param>
    /// <param name="hookPoolCapacity">Number of <see cref="FPHook"/>s preallocated so that fades do not allocate.</param>
    /// <exception cref="ArgumentException"><paramref name="startTime"/> is NaN, infinite or not within
    /// ±<see cref="InputLimits.MaxClockTime"/> (2^40 s).</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="hookPoolCapacity"/> is negative.</exception>
    /// <remarks>Valid clock times: |t| &lt; 2^40 s = 1,099,511,627,776 s, where a double's spacing (≤ 2^-13 s) still
    /// resolves EPSILON and the 1/30 s gate (<see cref="InputLimits.MaxClockTime"/>).</remarks>
    // retail: CPhysics::CPhysics (acclient.c:311398) sets PhysicsTimer::curr_time = Timer::cur_time
    public PhysicsWorld(double startTime = 0.0, PhysicsProfile? profile = null, int hookPoolCapacity = 64)
    {
        ThrowIfClockOutside(startTime, nameof(startTime));

        ArgumentOutOfRangeException.ThrowIfNegative(hookPoolCapacity);
        Profile = profile ?? PhysicsProfile.Retail;
        CurrentTime = startTime;
        PhysicsTime = startTime;
        LastUpdate = startTime;
        Scene = new SceneTicker(this, startTime);
        for (int i = 0; i < hookPoolCapacity; i++)
        {
            ReturnFPHook(new FPHook());
        }
    }

    /// <summary>The time-slicing profile.</summary>
    public PhysicsProfile Profile { get; }

    /// <summary>The client clock, seconds (retail <c>Timer::cur_time</c>).</summary>
    public double CurrentTime { get; private set; }

    /// <summary>The physics clock, seconds (retail <c>PhysicsTimer::curr_time</c>): during an object's update it is that object's
    /// consumed time; hooks are timed against it.</summary>
    public double PhysicsTime { get; internal set; }

    /// <summary>Client time of the last world update, seconds (retail <c>last_update</c> in <c>CPhysics::UseTime</c>).</summary>
    public double LastUpdate { get; private set; }

    /// <summary>True while object maintenance is active (retail <c>obj_maint-&gt;is_active</c>): only then are objects farther than
    /// 96 m from the player made inactive. True by default, as in shipped play.</summary>
    public bool ObjectMaintenanceActive
    {
        get => _objectMaintenanceActive;
        set
        {
            if (value != _objectMaintenanceActive)
            {
                Scene.WakeGatedDormant();
                _objectMaintenanceActive = value;
            }
        }
    }

    private bool _objectMaintenanceActive = true;

    /// <summary>The collision sweep. <see cref="FreeSpaceSweep.Instance"/> by default.</summary>
    /// <remarks>Replacing a <see cref="RetailSweep"/> takes the objects' shadows out of its cells and releases them (its
    /// <see cref="Terrain.TerrainWorld"/> or <see cref="Cells.WorldCells"/>) for another world, unless the new sweep uses the same cells.</remarks>
    /// <exception cref="ArgumentNullException">The value is null.</exception>
    /// <exception cref="ArgumentException">The seam's cells already serve another world (see <see cref="RetailSweep"/>);
    /// nothing changes.</exception>
    /// <exception cref="InvalidOperationException">Set from a callback inside this world's tick; nothing changes.</exception>
    public CollisionSweep Sweep
    {
        get => _sweep;
        set
        {
            ArgumentNullException.ThrowIfNull(value);
            ThrowIfInTick();
            if (ReferenceEquals(value, _sweep))
            {
                return;
            }

            value.AttachTo(this);
            _sweep.DetachFrom(this, value);
            // The old seam may have released cells the new one shares (a WorldCells' terrain): claim them again.
            value.AttachTo(this);
            _sweep = value;
            // The objects' cells (their object lists) are now the new seam's cells of the same ids.
            VisitOrderList.Cursor cursor = _objects.Start();
            while (_objects.MoveNext(ref cursor, out PhysicsObj o))
            {
                o.RelistInCell();
            }
        }
    }

    private CollisionSweep _sweep = FreeSpaceSweep.Instance;

    /// <summary>Optional step observer (tests, diagnostics); null costs nothing.</summary>
    public IStepObserver? StepObserver { get; set; }

    /// <summary>Optional listener told after the player's update.</summary>
    public IPlayerPhysicsListener? PlayerListener { get; set; }

    /// <summary>Optional factory for movement managers created on demand (<c>get_minterp</c>); when null
    /// the retail <see cref="Motion.MovementManager"/> is created.</summary>
    public IMovementManagerFactory? MovementManagerFactory { get; set; }

    /// <summary>Optional client callback that plays physics scripts (CallPES hooks).</summary>
    public IScriptPlayer? ScriptPlayer { get; set; }

    /// <summary>Number of objects the world owns.</summary>
    public int ObjectCount => _objects.Count;

    /// <summary>
    /// The player object (retail <c>CPhysicsObj::player_object</c>): objects measure their distance to it. Null for none.
    /// Setting an object that has no movement manager gives it one through <see cref="PhysicsObj.GetOrCreateMotionInterpreter"/> (so through
    /// <see cref="MovementManagerFactory"/> when set): retail's player always has one, and without it an object resting on
    /// walkable ground deactivates itself every other step and walks at half speed.
    /// </summary>
    /// <exception cref="ArgumentException">The object belongs to another world or was removed.</exception>
    public PhysicsObj? Player
    {
        get => _player;
        set
        {
            if (value is not null && (value.World != this || !value.InWorld))
            {
                throw new ArgumentException("The player must be an object of this world.", nameof(value));
            }

            if (value != _player)
            {
                Scene.WakeGatedDormant();
                value?.Touch();
            }

            // non-retail: the player is given its movement manager here (retail's client creates it when the command
            // interpreter first moves the player); see docs/divergences.md
            if (value is not null && value.Movement is null)
            {
                value.GetOrCreateMotionInterpreter();
            }

            _player = value;
        }
    }

    /// <summary>Object <paramref name="index"/> (0 &lt;= index &lt; <see cref="ObjectCount"/>), in ascending id order (objects
    /// with equal ids in creation order): the order in which a tick visits them. Consecutive indexes cost O(1) each.</summary>
    /// <exception cref="ArgumentOutOfRangeException">Index out of range.</exception>
    public PhysicsObj GetObject(int index)
    {
        if ((uint)index >= (uint)_objects.Count)
        {
            throw new ArgumentOutOfRangeException(nameof(index));
        }

        return _objects.At(index);
    }

    /// <summary>The object table, in visiting order.</summary>
    internal VisitOrderList Objects => _objects;

    /// <summary>The object with id <paramref name="id"/>, or null when no object of this world has it (id 0 is no id: always
    /// null) (retail <c>CPhysicsObj::GetObjectA</c> through the object maintainer's table, acclient.c:316437).</summary>
    public PhysicsObj? GetObjectById(uint id) => id != 0 && _byId.TryGetValue(id, out PhysicsObj? o) ? o : null;

    /// <summary>Creates an object owned by this world (retail: <c>CPhysicsObj</c> constructor plus registration in the object
    /// table). It is not in a cell until placed (<see cref="PhysicsObj.EnterWorld"/> or <see cref="PhysicsObj.SetPositionSimple"/>).</summary>
    /// <param name="id">The object's id; 0 for none (any number of objects may have no id). A non-zero id is unique in the world
    /// while its object is in it: the id of a removed object is free again.</param>
    /// <returns>The new object.</returns>
    /// <exception cref="ArgumentException"><paramref name="id"/> is not 0 and an object of this world already has it (a server
    /// re-sending an object's creation: look it up with <see cref="GetObjectById"/>, or remove the old one first); nothing
    /// changes.</exception>
    public PhysicsObj CreateObject(uint id = 0)
    {
        // non-retail: a second object with an id in use is refused (retail's object table would hold two and answer either)
        if (id != 0 && _byId.ContainsKey(id))
        {
            throw new ArgumentException(
                string.Create(System.Globalization.CultureInfo.InvariantCulture,
                    $"An object with id 0x{id:X8} is already in this world: look it up with GetObjectById, or remove it first."),
                nameof(id));
        }

        // Kept in ascending id order (equal ids: creation order) so that a tick visits objects in the same order whatever the
        // order of creation. Retail walks its hash table; any fixed order is as retail-like as another. O(log n) in any order.
        var obj = new PhysicsObj(this, id, _created++);
        _objects.Insert(obj);
        obj.InWorld = true;
        obj.Touch();
        if (id != 0)
        {
            _byId.Add(id, obj);
        }

        return obj;
    }

    /// <summary>Removes <paramref name="obj"/> from the world (it is no longer ticked). Order of the others is kept.</summary>
    /// <remarks>Safe from any callback inside a tick (hooks, the step observer, collision and player listeners), the removed
    /// object's own included: its step ends at the callback, its shadows leave the cells and never return, its hooks are
    /// dropped (pooled fades go back to the pool once), and every other object is still visited exactly once this tick. The
    /// removed object keeps its last <see cref="PhysicsObj.Position"/> for the caller to read, but is in no cell
    /// (<see cref="PhysicsObj.CellId"/> 0) and has no transient state (no contact, walkable or active bit); its id is free for a
    /// new object. It cannot be added back: every public mutator of a removed object (placement, velocity, parent, state,
    /// hooks, managers...) throws <see cref="InvalidOperationException"/>; its reads stay allowed.</remarks>
    /// <exception cref="ArgumentException">The object is not in this world (or was already removed).</exception>
    public void RemoveObject(PhysicsObj obj)
    {
        ArgumentNullException.ThrowIfNull(obj);
        if (obj.World != this || !obj.InWorld)
        {
            throw new ArgumentException("The object is not in this world.", nameof(obj));
        }

        // retail: exit_world's target lines (acclient.c line 322204): the object stops tracking and its voyeurs are told
        obj.NotifyTargetExitWorld();
        obj.NotifyDetectionExitWorld();
        if (obj == _player)
        {
            Scene.WakeGatedDormant();
        }

        Scene.RemoveFromVisiting(obj);
        if ((obj.State & (PhysicsState.HasDefaultAnim | PhysicsState.HasDefaultScript)) != 0)
        {
            RemoveStaticAnimatingObject(obj);
        }

        _objects.Remove(obj);
        obj.InWorld = false;
        obj.RemovedFromWorld = true;
        if (obj.Id != 0 && _byId.TryGetValue(obj.Id, out PhysicsObj? found) && found == obj)
        {
            _byId.Remove(obj.Id);
        }

        obj.RemoveShadowsFromCells();
        // retail: CPhysicsObj::leave_world (acclient.c:322653) -> CObjectMaint::RemoveFromLostCell
        RemoveFromLostCell(obj);
        obj.LeaveCellOnRemove();
        obj.ClearOnRemove();
        obj.ClearHooksOnRemove();
        if (_player == obj)
        {
            _player = null;
        }
    }

    /// <summary>Sets the client clock without ticking (retail: the client loop advancing <c>Timer::cur_time</c>).</summary>
    /// <param name="now">Client time, seconds: finite, |now| &lt; <see cref="InputLimits.MaxClockTime"/> (2^40 s).</param>
    /// <exception cref="ArgumentException"><paramref name="now"/> is NaN, infinite or not within ±2^40 s (state unchanged).
    /// The clock may go backwards (retail resyncs).</exception>
    /// <exception cref="InvalidOperationException">Called from a callback inside this world's tick (the clock the tick is
    /// slicing would change under it); nothing changes.</exception>
    public void SetCurrentTime(double now)
    {
        ThrowIfInTick();
        ThrowIfClockOutside(now, nameof(now));
        CurrentTime = now;
    }

    // non-retail: clock times are refused from 2^40 s on, where the double clock no longer resolves EPSILON (retail's clock
    // would silently stop ticking near 1e15 s)
    private static void ThrowIfClockOutside(double time, string paramName)
    {
        if (!InputLimits.IsClockTimeInDomain(time))
        {
            throw new ArgumentException("Clock time must be finite and within ±2^40 s (1,099,511,627,776 s).", paramName);
        }
    }

    /// <summary>Sets the client clock to <paramref name="now"/> and runs <see cref="UseTime"/>.</summary>
    /// <param name="now">Client time, seconds: finite, |now| &lt; <see cref="InputLimits.MaxClockTime"/> = 2^40 s
    /// (1,099,511,627,776 s, about 34,800 years); beyond it the double clock's spacing (2^-12 s and more) no longer resolves
    /// EPSILON, and from about 1e15 s not even the 1/30 s gate.</param>
    /// <returns>True when the objects were visited (at least MinQuantum had passed). A frame longer than
    /// <see cref="PhysicsProfile.HugeQuantum"/> (2 s) is visited but discarded: no object moves. Such frames, and a clock
    /// going back, are counted in <see cref="DiscardedFrames"/> — a count growing every frame means the clock is not in
    /// seconds (is it in milliseconds?).</returns>
    /// <exception cref="ArgumentException"><paramref name="now"/> is NaN, infinite or not within ±2^40 s (state unchanged).</exception>
    /// <exception cref="InvalidOperationException">Called from a callback inside this world's tick (re-entrant tick); nothing
    /// changes and the tick in progress goes on. Or, with <see cref="MaxConsecutiveDiscardedFrames"/> set, this tick made
    /// that many consecutive discarded frames (thrown after the tick finished as retail's).</exception>
    /// <remarks>An exception thrown by a client callback (collision or player listener, step observer, hooks, seams) propagates
    /// out of the tick uncaught. The world stays usable: the next tick runs, the pools are full again, and the objects the
    /// throwing tick did not reach are updated by the next one over the whole elapsed time (docs/stability.md, "After a
    /// callback threw").</remarks>
    public bool Tick(double now)
    {
        SetCurrentTime(now);
        return UseTime();
    }

    /// <summary>
    /// The world tick: when the client clock went backwards, resynchronises; when at least MinQuantum has passed since the
    /// last update, runs <see cref="PhysicsObj.UpdateObject"/> on every object in order and records the time.
    /// </summary>
    /// <returns>True when the objects were visited (at least MinQuantum had passed; a frame longer than
    /// <see cref="PhysicsProfile.HugeQuantum"/> is visited but discarded, see <see cref="DiscardedFrames"/>).</returns>
    /// <exception cref="InvalidOperationException">Called from a callback inside this world's tick; nothing changes. Or the
    /// <see cref="MaxConsecutiveDiscardedFrames"/> limit was reached (after the tick finished).</exception>
    /// <remarks>A client callback's exception propagates; the world stays usable (see <see cref="Tick"/>).</remarks>
    // retail: CPhysics::UseTime (acclient.c:311334)
    public bool UseTime()
    {
        ThrowIfInTick();
        double quantum = CurrentTime - LastUpdate;
        if (quantum < 0.0)
        {
            // non-retail: the discarded frame is counted for the client (retail resyncs silently)
            CountDiscardedFrame(quantum);
            LastUpdate = CurrentTime;
            ThrowIfDiscardLimitReached();
            return false;
        }

        if (!(quantum >= Profile.MinQuantum))
        {
            return false;
        }

        if (quantum > Profile.HugeQuantum)
        {
            // non-retail: the frame every object's update_object will discard (acclient.c:323080) is counted for the client
            CountDiscardedFrame(quantum);
        }

        // non-retail: the re-entrancy guard (retail's tick is never called from inside itself)
        _inUseTime = true;
        try
        {
            if (VisitEveryObject)
            {
                PhysicsObj? player = _player;
                int visits = 0;
                // The cursor finds its place again by key after a removal or creation from a callback, so each object in the
                // list when the walk reaches it is visited once.
                VisitOrderList.Cursor cursor = _objects.Start();
                while (_objects.MoveNext(ref cursor, out PhysicsObj obj))
                {
                    obj.UpdateObject();
                    visits++;
                    if (obj == player)
                    {
                        PlayerListener?.PlayerPhysicsUpdated(obj);
                    }
                }

                LastTickVisitCount = visits;
            }
            else
            {
                LastTickVisitCount = Scene.Tick();
            }
        }
        finally
        {
            _inUseTime = false;
        }

        LastUpdate = CurrentTime;
        if (quantum > Profile.HugeQuantum)
        {
            ThrowIfDiscardLimitReached();
        }
        else
        {
            _consecutiveDiscardedFrames = 0;
        }

        return true;
    }

    /// <summary>
    /// Number of frames this world discarded since its creation: ticks (<see cref="Tick"/>, <see cref="UseTime"/>) whose
    /// elapsed time since <see cref="LastUpdate"/> was negative (the client clock went back: retail's <c>CPhysics::UseTime</c>
    /// resyncs <see cref="LastUpdate"/> and runs no update) or above <see cref="PhysicsProfile.HugeQuantum"/> (2 s: the objects
    /// are visited, but retail's <c>update_object</c> discards a gap that large, sets each object's update time to now and
    /// runs no step, so nothing moves). A tick shorter than MinQuantum is not discarded (its time accumulates).
    /// </summary>
    /// <remarks>A count that grows with every frame means the clock passed to <see cref="Tick"/> is not in seconds (a clock in
    /// milliseconds makes every 60 fps frame 16.7 "seconds" long) or runs backwards. Counted once per tick in the world's
    /// update, not per object (an object whose own gap is over 2 s because it was frozen or parented is retail's resync and
    /// not counted).</remarks>
    public long DiscardedFrames { get; private set; }

    /// <summary>Length of the last discarded frame (see <see cref="DiscardedFrames"/>), seconds: negative when the clock
    /// went back, above <see cref="PhysicsProfile.HugeQuantum"/> otherwise; 0 until a frame is discarded.</summary>
    public double LastDiscardedFrameSeconds { get; private set; }

    /// <summary>
    /// Opt-in strict clock check (non-retail; 0, the default, is retail's behaviour: discarded frames are only counted):
    /// when positive, the tick that makes this many consecutive discarded frames (see <see cref="DiscardedFrames"/>; a tick
    /// that runs the objects normally resets the run) throws an <see cref="InvalidOperationException"/> after finishing as
    /// retail does, so a clock in milliseconds (every 60 fps frame 16.7 "seconds" long) is reported instead of freezing the
    /// world. The world stays usable; a later discarded frame throws again.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">Set to a negative value (state unchanged).</exception>
    public int MaxConsecutiveDiscardedFrames
    {
        get => _maxConsecutiveDiscardedFrames;
        set
        {
            ArgumentOutOfRangeException.ThrowIfNegative(value);
            _maxConsecutiveDiscardedFrames = value;
        }
    }

    private int _maxConsecutiveDiscardedFrames;
    private int _consecutiveDiscardedFrames;

    private void CountDiscardedFrame(double quantum)
    {
        DiscardedFrames++;
        LastDiscardedFrameSeconds = quantum;
        if (_consecutiveDiscardedFrames < int.MaxValue)
        {
            _consecutiveDiscardedFrames++;
        }
    }

    private void ThrowIfDiscardLimitReached()
    {
        if (_maxConsecutiveDiscardedFrames > 0 && _consecutiveDiscardedFrames >= _maxConsecutiveDiscardedFrames)
        {
            throw new InvalidOperationException(
                $"{_consecutiveDiscardedFrames} consecutive frames were discarded (the last {LastDiscardedFrameSeconds} s long; "
                + "retail discards a frame longer than 2 s or a clock going back): Tick takes the client clock in seconds "
                + "(is it in milliseconds?).");
        }
    }

    private void ThrowIfInTick()
    {
        if (_inUseTime)
        {
            throw new InvalidOperationException("The world is ticking: Tick, UseTime, SetCurrentTime and Sweep cannot be called or set from a callback inside its tick.");
        }
    }
}
