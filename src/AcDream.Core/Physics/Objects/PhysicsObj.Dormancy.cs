using System;
using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Math;
using AcDream.Core.Physics.Scene;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Objects;

/// <summary>How a dormant object's retail bookkeeping evolves while the scene does not visit it.</summary>
internal enum Dormancy : byte
{
    /// <summary>Visited every world tick.</summary>
    Awake = 0,

    /// <summary>update_object bails out at once (parented, no cell, frozen): nothing changes.</summary>
    Bailed,

    /// <summary>Each tick only update_time advances, by retail's consumed-time arithmetic (the world's consumed clock), and the
    /// player vector is re-measured. ACTIVE stays as it is (clear: static, far, or no player; set: idle but never on walkable).</summary>
    ConsumedClock,

    /// <summary>Near the player, idle on walkable ground: retail re-activates it every other tick (set_active restarts its
    /// clock) and it deactivates itself on the next step. ACTIVE and update_time alternate.</summary>
    PingPong,
}

public sealed partial class PhysicsObj
{
    internal Dormancy _dormancy;
    internal long _sleepTick;
    internal bool _sleepPhaseActive;
    internal bool _inActiveList;
    internal bool _pendingWake;
    internal GateQueue? _gateQueue;
    internal int _gateSlot = -1;
    private double _updateTime;
    private Vector3 _playerVector;
    internal float _playerDistance;

    /// <summary>The scene queued the object to join its active list at the next merge.</summary>
    internal void MarkPendingWake() => _pendingWake = true;

    /// <summary>The scene merged the object's pending wake, or dropped it with the object.</summary>
    internal void ClearPendingWake() => _pendingWake = false;

    /// <summary>The scene counts the object awake again.</summary>
    internal void MarkAwake() => _dormancy = Dormancy.Awake;

    /// <summary>The scene put the object in (<paramref name="value"/> true) or took it out of its active list.</summary>
    internal void SetInActiveList(bool value) => _inActiveList = value;

    /// <summary>
    /// The scene put the object to sleep in scene tick <paramref name="tick"/>: it leaves the active list with
    /// <paramref name="dormancy"/> and remembers the ACTIVE bit it slept with.
    /// </summary>
    internal void EnterDormancy(Dormancy dormancy, long tick)
    {
        _inActiveList = false;
        _dormancy = dormancy;
        _sleepTick = tick;
        _sleepPhaseActive = (_transientState & TransientState.Active) != 0;
    }

    /// <summary>The object now waits in slot <paramref name="slot"/> of the gate queue <paramref name="queue"/>.</summary>
    internal void EnterGateQueue(GateQueue queue, int slot)
    {
        _gateQueue = queue;
        _gateSlot = slot;
    }

    /// <summary>The object left its gate queue.</summary>
    internal void LeaveGateQueue()
    {
        _gateQueue = null;
        _gateSlot = -1;
    }

    /// <summary>True while the scene skips this object because its retail update would change nothing but bookkeeping.</summary>
    public bool IsDormant => _dormancy != Dormancy.Awake;

    /// <summary>
    /// Wakes the object if it is dormant: its bookkeeping (ACTIVE bit, update time, player vector) is brought to the values retail
    /// would hold now, and the scene visits it again from the next point in the tick order. Called by every mutating member.
    /// </summary>
    internal void Touch()
    {
        if (_dormancy != Dormancy.Awake)
        {
            World.WakeDormant(this);
        }
        else if (!_inActiveList && !_pendingWake && WorldIndex >= 0)
        {
            World.EnqueueWake(this);
        }
    }

    /// <summary>Writes the lazily evaluated bookkeeping into the fields (as of the world's last completed visit of this object).</summary>
    /// <remarks>An idle object the player's travel carried across the 96 m gate while dormant takes the state retail's visit in
    /// that tick left (<see cref="GateQueue.RecordFlip"/>): update_object (acclient.c:323080) clears ACTIVE beyond 96 m, and the
    /// idle steps leave update_time at the consumed time (the scene records a crossing only when that is the world's consumed
    /// clock); within 96 m, set_active(1) sets ACTIVE and restarts update_time at now, so the slicing sees dt = 0. From there
    /// an object on walkable ground deactivates itself on its next step and is re-activated on the one after (ping-pong).</remarks>
    internal void Materialize(bool visitedThisTick)
    {
        PhysicsWorld w = World;
        Dormancy kind = _dormancy;
        long sleepTick = _sleepTick;
        bool phaseActive = _sleepPhaseActive;
        if (_gateQueue is not null
            && _gateQueue.LastFlip(_gateSlot, visitedThisTick ? w.SceneTick : w.SceneTick - 1, out long flipTick, out bool far))
        {
            if (far)
            {
                kind = Dormancy.ConsumedClock;
                phaseActive = false;
            }
            else if ((_transientState & TransientState.OnWalkable) != 0)
            {
                kind = Dormancy.PingPong;
                sleepTick = flipTick;
                phaseActive = true;
            }
            else
            {
                kind = Dormancy.ConsumedClock;
                phaseActive = true;
            }
        }

        if (!Evaluate(kind, sleepTick, phaseActive, visitedThisTick, out bool active, out double updateTime))
        {
            return;
        }

        SetBookkeeping(active, updateTime);
        if (w.PlayerSeenPosition(this, visitedThisTick, out Position seen))
        {
            Vector3 pv = seen.GetOffset(_position);
            _playerVector = pv;
            _playerDistance = (float)System.Math.Sqrt((double)pv.X * pv.X + (double)pv.Y * pv.Y + (double)pv.Z * pv.Z);
        }
    }

    private void SetBookkeeping(bool active, double updateTime)
    {
        _transientState = active ? _transientState | TransientState.Active : _transientState & ~TransientState.Active;
        _updateTime = updateTime;
    }

    /// <summary>The ACTIVE bit and update_time a dormancy kind gives after the last (or the previous) tick; false for kinds with
    /// no lazy bookkeeping. <paramref name="phaseActive"/> is the ACTIVE bit at <paramref name="sleepTick"/> (constant for
    /// <see cref="Dormancy.ConsumedClock"/>).</summary>
    private bool Evaluate(Dormancy kind, long sleepTick, bool phaseActive, bool visitedThisTick, out bool active, out double updateTime)
    {
        PhysicsWorld w = World;
        switch (kind)
        {
            case Dormancy.ConsumedClock:
                active = phaseActive;
                updateTime = visitedThisTick ? w.ConsumedClockNow : w.ConsumedClockPrev;
                return true;
            case Dormancy.PingPong:
                active = w.PingPongActive(sleepTick, phaseActive, visitedThisTick);
                updateTime = active ? w.TickTime(visitedThisTick) : w.PingPongTime(visitedThisTick);
                return true;
            default:
                active = false;
                updateTime = 0.0;
                return false;
        }
    }

    private double LazyUpdateTime()
    {
        if (_dormancy is Dormancy.ConsumedClock or Dormancy.PingPong)
        {
            Materialize(World.IsVisitedThisTick(this));
        }

        return _updateTime;
    }

    private TransientState LazyTransientState()
    {
        if (_dormancy is Dormancy.ConsumedClock or Dormancy.PingPong)
        {
            Materialize(World.IsVisitedThisTick(this));
        }

        return _transientState;
    }

    private Vector3 LazyPlayerVector()
    {
        if (_dormancy is Dormancy.ConsumedClock or Dormancy.PingPong)
        {
            Materialize(World.IsVisitedThisTick(this));
        }

        return _playerVector;
    }

    private float LazyPlayerDistance()
    {
        if (_dormancy is Dormancy.ConsumedClock or Dormancy.PingPong)
        {
            Materialize(World.IsVisitedThisTick(this));
        }

        return _playerDistance;
    }

    /// <summary>
    /// After a visit: decides whether the next visits would change nothing but the bookkeeping that <see cref="Materialize"/>
    /// reproduces, and if so which kind of dormancy applies. <paramref name="farMargin"/> receives |distance - 96| for objects
    /// whose kind depends on the player gate (NaN when it does not).
    /// </summary>
    internal Dormancy ClassifyForSleep(out float farMargin)
    {
        farMargin = float.NaN;
        PhysicsWorld w = World;
        if (w.Player == this)
        {
            return Dormancy.Awake;
        }

        if (Parent is not null || CellId == 0 || (_state & PhysicsState.Frozen) != 0)
        {
            return Dormancy.Bailed;
        }

        // The particle and script seams run on every visit, active or not.
        if ((ParticleManager is not null || ScriptManager is not null) && (w.Effects & SceneEffects.ParticlesAndScripts) != 0)
        {
            return Dormancy.Awake;
        }

        PhysicsObj? player = w.Player;
        bool gated = player is not null && w.ObjectMaintenanceActive && (_state & PhysicsState.Static) == 0;
        if (gated)
        {
            farMargin = MathF.Abs(_playerDistance - PhysicsGlobals.PlayerActivityDistance);
            if (!(farMargin > PhysicsWorld.GateSafetyMargin))
            {
                return Dormancy.Awake; // its float distance may have rounded across 96 m: visit
            }
        }

        bool far = gated && _playerDistance > PhysicsGlobals.PlayerActivityDistance;
        if (far || (_state & PhysicsState.Static) != 0)
        {
            // Inactive branch only (far) or never active (static): only update_time advances.
            // (A static object never runs the active branch, so its hooks and motion never act either.)
            if ((_transientState & TransientState.Active) != 0 || _updateTime != w.ConsumedClockNow)
            {
                return Dormancy.Awake;
            }

            return Dormancy.ConsumedClock;
        }

        if (!IsIdleForScene())
        {
            return Dormancy.Awake;
        }

        bool active = (_transientState & TransientState.Active) != 0;
        if (player is null)
        {
            // No player: nobody re-activates it.
            if (active && (_transientState & TransientState.OnWalkable) != 0)
            {
                return Dormancy.Awake; // it deactivates on its next step
            }

            return _updateTime == w.ConsumedClockNow ? Dormancy.ConsumedClock : Dormancy.Awake;
        }

        // Near the player (or object maintenance off): set_active(1) every tick.
        if ((_transientState & TransientState.OnWalkable) != 0)
        {
            double expected = active ? w.TickTime(true) : w.PingPongTime(true);
            return _updateTime == expected ? Dormancy.PingPong : Dormancy.Awake;
        }

        return active && _updateTime == w.ConsumedClockNow ? Dormancy.ConsumedClock : Dormancy.Awake;
    }

    /// <summary>
    /// True when a visit to this (non-far, non-bailed) object changes nothing but the bookkeeping: no motion, no components that
    /// act on their own, and a frame that <c>combine</c> with the identity offset reproduces bit for bit.
    /// </summary>
    internal bool IsIdleForScene()
    {
        if (MovementManager is not null || DetectionManager is not null || TargetManager is not null
            || Hooks is not null || _animHookCount != 0 || (Children is not null && Children.Count != 0)
            || (_state & PhysicsState.Hidden) != 0 || JumpedThisFrame
            || (_transientState & TransientState.CheckEthereal) != 0)
        {
            return false;
        }

        if (PositionManager is not null && !PositionManager.IsIdle)
        {
            return false;
        }

        if (PartArray is not null && !PartArray.IsIdle)
        {
            return false;
        }

        if (!IsPositiveZero(_velocity) || !IsPositiveZero(CachedVelocity) || _acceleration != Vector3.Zero || _omega != Vector3.Zero)
        {
            return false;
        }

        Frame f = _position.Frame;
        Frame again = f;
        again.Combine(f, Frame.Identity);
        return BitwiseEqual(again, f);
    }

    // Frame.Equals compares with float.Equals, which treats -0 and +0 as equal; a frame holding a -0 component comes back from
    // combine with +0 (retail's sums), so a visit does change it and the object must not be skipped yet.
    private static bool BitwiseEqual(in Frame a, in Frame b) =>
        IsSameBits(a.Origin, b.Origin)
        && Bits(a.Qw) == Bits(b.Qw) && Bits(a.Qx) == Bits(b.Qx) && Bits(a.Qy) == Bits(b.Qy) && Bits(a.Qz) == Bits(b.Qz)
        && Bits(a.M0) == Bits(b.M0) && Bits(a.M1) == Bits(b.M1) && Bits(a.M2) == Bits(b.M2)
        && Bits(a.M3) == Bits(b.M3) && Bits(a.M4) == Bits(b.M4) && Bits(a.M5) == Bits(b.M5)
        && Bits(a.M6) == Bits(b.M6) && Bits(a.M7) == Bits(b.M7) && Bits(a.M8) == Bits(b.M8);

    private static int Bits(float f) => BitConverter.SingleToInt32Bits(f);

    private static bool IsSameBits(Vector3 a, Vector3 b) => Bits(a.X) == Bits(b.X) && Bits(a.Y) == Bits(b.Y) && Bits(a.Z) == Bits(b.Z);

    private static bool IsPositiveZero(Vector3 v) =>
        BitConverter.SingleToInt32Bits(v.X) == 0 && BitConverter.SingleToInt32Bits(v.Y) == 0 && BitConverter.SingleToInt32Bits(v.Z) == 0;
}
