using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Scene;

// The dormant objects' bookkeeping: which kind of dormancy an object can take, and the values retail would hold.
internal sealed partial class SceneTicker
{
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

        // The visiting order is fixed by id and creation number, so the keys decide before/after.
        bool afterPlayer = VisitOrderList.Precedes(p, obj);
        seen = visitedThisTick
            ? (afterPlayer ? _playerAfterNow : _playerBeforeNow)
            : (afterPlayer ? _playerAfterPrev : _playerBeforePrev);
        return true;
    }

    /// <summary>Writes the lazily evaluated bookkeeping of <paramref name="obj"/> into its fields (as of the world's last
    /// completed visit of the object).</summary>
    /// <remarks>An idle object the player's travel carried across the 96 m gate while dormant takes the state retail's visit in
    /// that tick left (<see cref="GateQueue.RecordFlip"/>): update_object (acclient.c:323080) clears ACTIVE beyond 96 m, and the
    /// idle steps leave update_time at the consumed time (the scene records a crossing only when that is the world's consumed
    /// clock); within 96 m, set_active(1) sets ACTIVE and restarts update_time at now, so the slicing sees dt = 0. From there
    /// an object on walkable ground deactivates itself on its next step and is re-activated on the one after (ping-pong).</remarks>
    internal void Materialize(PhysicsObj obj, bool visitedThisTick)
    {
        ref SceneSlot s = ref obj._scene;
        Dormancy kind = s.Dormancy;
        long sleepTick = s.SleepTick;
        bool phaseActive = s.SleepPhaseActive;
        if (s.GateQueue is not null
            && s.GateQueue.LastFlip(s.GateSlot, visitedThisTick ? _tick : _tick - 1, out long flipTick, out bool far))
        {
            if (far)
            {
                kind = Dormancy.ConsumedClock;
                phaseActive = false;
            }
            else if ((obj._transientState & TransientState.OnWalkable) != 0)
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

        obj.SetLazyActive(active);
        s.UpdateTime = updateTime;
        if (PlayerSeenPosition(obj, visitedThisTick, out Position seen))
        {
            Vector3 pv = seen.GetOffset(obj._position);
            s.PlayerVector = pv;
            s.PlayerDistance = (float)VectorMath.Magnitude(pv);
        }
    }

    /// <summary>The ACTIVE bit and update_time a dormancy kind gives after the last (or the previous) tick; false for kinds with
    /// no lazy bookkeeping. <paramref name="phaseActive"/> is the ACTIVE bit at <paramref name="sleepTick"/> (constant for
    /// <see cref="Dormancy.ConsumedClock"/>).</summary>
    private bool Evaluate(Dormancy kind, long sleepTick, bool phaseActive, bool visitedThisTick, out bool active, out double updateTime)
    {
        switch (kind)
        {
            case Dormancy.ConsumedClock:
                active = phaseActive;
                updateTime = visitedThisTick ? _consumedNow : _consumedPrev;
                return true;
            case Dormancy.PingPong:
                active = PingPongActive(sleepTick, phaseActive, visitedThisTick);
                updateTime = active ? TickTime(visitedThisTick) : PingPongTime(visitedThisTick);
                return true;
            default:
                active = false;
                updateTime = 0.0;
                return false;
        }
    }

    /// <summary>
    /// After a visit: decides whether the next visits of <paramref name="o"/> would change nothing but the bookkeeping that
    /// <see cref="Materialize"/> reproduces, and if so which kind of dormancy applies. <paramref name="farMargin"/> receives
    /// |distance - 96| for objects whose kind depends on the player gate (NaN when it does not).
    /// </summary>
    internal Dormancy ClassifyForSleep(PhysicsObj o, out float farMargin)
    {
        farMargin = float.NaN;
        PhysicsWorld w = _world;
        if (w.Player == o)
        {
            return Dormancy.Awake;
        }

        PhysicsState state = o._state;
        if (o.Parent is not null || o.CellId == 0 || (state & PhysicsState.Frozen) != 0)
        {
            return Dormancy.Bailed;
        }

        // The particle and script seams run on every visit, active or not.
        if ((o.ParticleManager is not null || o.ScriptManager is not null) && (w.Effects & SceneEffects.ParticlesAndScripts) != 0)
        {
            return Dormancy.Awake;
        }

        PhysicsObj? player = w.Player;
        float distance = o._scene.PlayerDistance;
        bool gated = player is not null && w.ObjectMaintenanceActive && (state & PhysicsState.Static) == 0;
        if (gated)
        {
            farMargin = MathF.Abs(distance - PhysicsGlobals.PlayerActivityDistance);
            if (!(farMargin > GateSafetyMargin))
            {
                return Dormancy.Awake; // its float distance may have rounded across 96 m: visit
            }
        }

        TransientState transient = o._transientState;
        double updateTime = o._scene.UpdateTime;
        bool far = gated && distance > PhysicsGlobals.PlayerActivityDistance;
        if (far || (state & PhysicsState.Static) != 0)
        {
            // Inactive branch only (far) or never active (static): only update_time advances.
            // (A static object never runs the active branch, so its hooks and motion never act either.)
            if ((transient & TransientState.Active) != 0 || updateTime != _consumedNow)
            {
                return Dormancy.Awake;
            }

            return Dormancy.ConsumedClock;
        }

        if (!IsIdle(o))
        {
            return Dormancy.Awake;
        }

        bool active = (transient & TransientState.Active) != 0;
        if (player is null)
        {
            // No player: nobody re-activates it.
            if (active && (transient & TransientState.OnWalkable) != 0)
            {
                return Dormancy.Awake; // it deactivates on its next step
            }

            return updateTime == _consumedNow ? Dormancy.ConsumedClock : Dormancy.Awake;
        }

        // Near the player (or object maintenance off): set_active(1) every tick.
        if ((transient & TransientState.OnWalkable) != 0)
        {
            double expected = active ? TickTime(true) : PingPongTime(true);
            return updateTime == expected ? Dormancy.PingPong : Dormancy.Awake;
        }

        return active && updateTime == _consumedNow ? Dormancy.ConsumedClock : Dormancy.Awake;
    }

    /// <summary>
    /// True when a visit to <paramref name="o"/> (non-far, non-bailed) changes nothing but the bookkeeping: no motion, no
    /// components that act on their own, and a frame that <c>combine</c> with the identity offset reproduces bit for bit.
    /// </summary>
    internal static bool IsIdle(PhysicsObj o)
    {
        // The motion first: it is what keeps most awake objects awake (every visited object is classified each tick), and
        // it reads only the object's own fields. The tests are pure, so their order does not change the answer.
        if (!IsPositiveZero(o._velocity) || o._omega != Vector3.Zero || !IsPositiveZero(o.CachedVelocity)
            || o._acceleration != Vector3.Zero)
        {
            return false;
        }

        if (o.Movement is not null || o.DetectionManager is not null || o.TargetManager is not null
            || o.Hooks is not null || o.PendingAnimHookCount != 0 || (o.Children is not null && o.Children.Count != 0)
            || (o._state & PhysicsState.Hidden) != 0 || o.JumpedThisFrame
            || (o._transientState & TransientState.CheckEthereal) != 0)
        {
            return false;
        }

        if (o.PositionManager is not null && !o.PositionManager.IsIdle)
        {
            return false;
        }

        if (o.PartArray is not null && !o.PartArray.IsIdle)
        {
            return false;
        }

        Frame f = o._position.Frame;
        Frame again = f;
        again.Combine(f, Frame.Identity);
        return BitwiseEqual(again, f);
    }

    // Frame.Equals compares with float.Equals, which treats -0 and +0 as equal; a frame holding a -0 component comes back from
    // combine with +0 (retail's sums), so a visit does change it and the object must not be skipped yet.
    private static bool BitwiseEqual(in Frame a, in Frame b) =>
        IsSameBits(a.Origin, b.Origin)
        && Bits(a.Qw) == Bits(b.Qw) && Bits(a.Qx) == Bits(b.Qx) && Bits(a.Qy) == Bits(b.Qy) && Bits(a.Qz) == Bits(b.Qz)
        && Bits(a.M11) == Bits(b.M11) && Bits(a.M12) == Bits(b.M12) && Bits(a.M13) == Bits(b.M13)
        && Bits(a.M21) == Bits(b.M21) && Bits(a.M22) == Bits(b.M22) && Bits(a.M23) == Bits(b.M23)
        && Bits(a.M31) == Bits(b.M31) && Bits(a.M32) == Bits(b.M32) && Bits(a.M33) == Bits(b.M33);

    private static int Bits(float f) => BitConverter.SingleToInt32Bits(f);

    private static bool IsSameBits(Vector3 a, Vector3 b) => Bits(a.X) == Bits(b.X) && Bits(a.Y) == Bits(b.Y) && Bits(a.Z) == Bits(b.Z);

    private static bool IsPositiveZero(Vector3 v) =>
        BitConverter.SingleToInt32Bits(v.X) == 0 && BitConverter.SingleToInt32Bits(v.Y) == 0 && BitConverter.SingleToInt32Bits(v.Z) == 0;
}
