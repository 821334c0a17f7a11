using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Scene;

// The 96 m player gate of the dormant objects, and putting idle objects to sleep.
internal sealed partial class SceneTicker
{
    // Objects ordered before the player see its position before its update; those after, after it: one queue each, so each
    // is tested against the position it sees.
    private readonly GateQueue _gateBefore = new();
    private readonly GateQueue _gateAfter = new();
    private GateHit[] _gateHits = new GateHit[16];

    /// <summary>Gate statistics since the world was created: dormant objects' copies re-measured against the 96 m gate, crossings
    /// handled without a visit, and crossings that woke the object.</summary>
    internal long GateRemeasures, GateFlips, GateWakes;

    /// <summary>Entries the gate queues hold, stale ones included (bounded by about twice the queued objects plus a constant).</summary>
    internal int GateEntryCount => _gateBefore.EntryCount + _gateAfter.EntryCount;

    /// <summary>An object whose player_distance (a float) is within this of 96 m stays awake: the float may have rounded across
    /// 96 from the double update_object compared, so its side is not known from it (an ulp at 96 is 7.6e-6).</summary>
    internal static float GateSafetyMargin => 1e-4f;

    /// <summary>How far retail's distance (float offsets, spilled sums) and the queue's estimate (double arithmetic on float
    /// copies of the positions, within ~3e-5 m) may differ: far below this. Within twice this of 96 m, retail's own arithmetic
    /// decides.</summary>
    private static double GateKeySlack(double distance) => 2e-4 + distance * 2e-6;

    /// <summary>Tests the dormant gated objects whose side of 96 m the player's movement may have changed (the queue's bands,
    /// from the positions the queue holds, touching no object). An idle object that crossed the gate has the crossing recorded,
    /// and takes the state this tick's visit leaves when next read (<see cref="Materialize"/>); an object that must move once
    /// near and one whose crossing leaves a state no dormancy kind describes are woken and visited later in this same tick, in
    /// order. Near the boundary the side is decided with retail's own arithmetic.</summary>
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
                double d = Math.Sqrt(dx * dx + dy * dy + dz * dz);
                if (!(Math.Abs(d - PhysicsGlobals.PlayerActivityDistance) > 2.0 * GateKeySlack(d)))
                {
                    // Near the boundary: decide with retail's own arithmetic (update_object's get_offset and double sqrt).
                    Vector3 pv = seen.GetOffset(queue.Object(h.Slot)._position);
                    d = VectorMath.Magnitude(pv);
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
        PhysicsObj? player = _world.Player;
        bool gateReady = player == _playerSeenNow;
        var filter = new SleepFilter(this, player, gateReady);
        _active.RemoveWhere(ref filter);
    }

    // PutIdleToSleep's pass over the visiting list: puts each object whose next visits would change nothing to sleep (and
    // into its gate queue) and takes it out of the list.
    private struct SleepFilter : VisitOrderList.IRemovalFilter
    {
        private readonly SceneTicker _ticker;
        private readonly PhysicsObj? _player;
        private readonly bool _gateReady;

        internal SleepFilter(SceneTicker ticker, PhysicsObj? player, bool gateReady)
        {
            _ticker = ticker;
            _player = player;
            _gateReady = gateReady;
        }

        public bool ShouldRemove(PhysicsObj o) => _ticker.TryPutToSleep(o, _player, _gateReady);
    }

    // Puts o to sleep when its next visits would change nothing but bookkeeping; false when it stays awake.
    private bool TryPutToSleep(PhysicsObj o, PhysicsObj? player, bool gateReady)
    {
        Dormancy d = ClassifyForSleep(o, out float margin);
        if (d == Dormancy.Awake || (!gateReady && !float.IsNaN(margin)))
        {
            return false;
        }

        ref SceneSlot s = ref o._scene;
        s.InActiveList = false;
        s.Dormancy = d;
        s.SleepTick = _tick;
        s.SleepPhaseActive = (o._transientState & TransientState.Active) != 0;
        GateQueue.Forget(o);
        if (!float.IsNaN(margin) && d != Dormancy.Bailed)
        {
            // Idle: it never moves on either side of the gate, so a crossing only changes its bookkeeping (no visit).
            bool idle = IsIdle(o);
            if (_world.GateTracking == GateTracking.Exact || !idle)
            {
                bool before = player is not null && VisitOrderList.Precedes(o, player);
                float pd = s.PlayerDistance;
                (before ? _gateBefore : _gateAfter).Add(o, pd > PhysicsGlobals.PlayerActivityDistance, idle,
                    (o._transientState & TransientState.OnWalkable) != 0);
            }
        }

        return true;
    }
}
