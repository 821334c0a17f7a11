using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Core.Tests.Replay.Harness;

/// <summary>What a melee replay does with the MovementEvents.</summary>
public enum MeleeMode
{
    /// <summary>Every event goes through <see cref="PhysicsObj.HandleMovementEvent"/> (move-to and turn-to included).</summary>
    MoveToApplied,

    /// <summary>Events of types 6-9 are dropped; type 0 goes through <see cref="PhysicsObj.HandleMovementEvent"/>.</summary>
    MoveToIgnored,

    /// <summary>No MovementEvent is applied: the monsters follow their UpdatePositions only.</summary>
    InterpolationOnly,
}

/// <summary>One truth pose of the player compared with its body.</summary>
public readonly record struct MeleePlayerSample(double T, double Error, Vector3 Body, Vector3 Truth);

/// <summary>One monster UpdatePosition: how far the body was from it just before it arrived.</summary>
/// <param name="Moving">The report is more than <see cref="MeleeReplay.MovingStep"/> from the monster's previous one.</param>
public readonly record struct MeleeMonsterSample(double T, uint Guid, double Error, bool Moving);

/// <summary>Result of one melee replay run.</summary>
/// <param name="Player">Every player truth pose after the first MoveToObject, compared.</param>
/// <param name="Monsters">Every monster UpdatePosition after its first, compared.</param>
/// <param name="Results">How many events ended in each <see cref="MovementEventResult"/> (by the result's value).</param>
public sealed record MeleeReplayResult(List<MeleePlayerSample> Player, List<MeleeMonsterSample> Monsters, int[] Results);

/// <summary>One MoveToObject approach of the player: the errors while approaching and where it stopped.</summary>
/// <param name="Start">Event time, s.</param>
/// <param name="End">The next server-controlled event of the player, s (the approach's window).</param>
/// <param name="Samples">Truth poses inside the window.</param>
/// <param name="Median">Median error, m.</param>
/// <param name="Max">Largest error, m.</param>
/// <param name="RetailStopDistance">Distance from retail's last pose in the window to the target's last report, m.</param>
/// <param name="StopDistance">Distance from the body at that pose's time to the same report, m.</param>
/// <param name="RetailTravel">How far retail's client went from its pose before the event to its last pose, m.</param>
/// <param name="Travel">How far the body went from the same start, m.</param>
public readonly record struct MeleeApproach(double Start, double End, int Samples, double Median, double Max,
    double RetailStopDistance, double StopDistance, double RetailTravel, double Travel);

/// <summary>
/// Replays the melee recording through a <see cref="PhysicsWorld"/> at 30 Hz: the player as the world's player (weenie
/// <see cref="IMotionWeenie.IsThePlayer"/>, its own UpdatePositions not applied) under its MovementEvents, the two monsters
/// as remote objects under their UpdatePositions and MovementEvents. Every event goes through the wire decoder
/// (<see cref="MovementEventDecoder.Decode"/>) and the retail entry point (<see cref="PhysicsObj.HandleMovementEvent"/>).
/// Before each of the player's MoveToObjects, the player's body is placed at its own client's last pose (the state its
/// client was in when the event arrived): each approach starts where retail's did.
/// </summary>
public static class MeleeReplay
{
    /// <summary>The tick, s.</summary>
    public const double Dt = 1.0 / 30.0;

    /// <summary>A monster report this far from its previous one counts as moving, m.</summary>
    public const double MovingStep = 0.05;

    /// <summary>Ground height of the level replay ground (the player's z in every pose), m.</summary>
    public const float GroundZ = 94.0050049f;

    /// <summary>Runs the replay up to <paramref name="endTime"/>.</summary>
    public static MeleeReplayResult Run(MeleeRecording rec, MeleeMode mode, double endTime = double.PositiveInfinity)
    {
        (double startT, Position playerStart) = rec.Creates[MeleeRecording.Player];
        var sweep = new LastReportGroundSweep { GroundZ = GroundZ };
        var world = new PhysicsWorld(startT) { Sweep = sweep };
        PhysicsObj player = world.CreateObject(MeleeRecording.Player);
        player.Weenie = new ReplayPlayerWeenie();
        var playerParts = Walkers.OneSphere(0.35f);
        playerParts.MotionPlayer = new SpeedOnlyMotionPlayer();
        player.PartArray = playerParts;
        player.EnterWorld(playerStart);
        world.Player = player;
        MovementManager.Of(player);
        var monsters = new Dictionary<uint, PhysicsObj>();
        foreach (uint guid in new[] { MeleeRecording.Chicken, MeleeRecording.TheChicken })
        {
            PhysicsObj m = world.CreateObject(guid);
            m.Weenie = RemoteCreatureWeenie.Creature;
            var parts = Walkers.OneSphere(0.35f);
            parts.MotionPlayer = new SpeedOnlyMotionPlayer();
            m.PartArray = parts;
            m.EnterWorld(rec.Creates[guid].Position);
            MovementManager.Of(m);
            monsters[guid] = m;
        }

        // The monsters' UpdatePositions go through the SmartBox entry point (instance gate, stamps).
        var handler = new ServerMessageHandler(world);
        var message = new MovementEventMessage();
        var players = new List<MeleePlayerSample>();
        var monsterSamples = new List<MeleeMonsterSample>();
        int[] results = new int[6];
        var previous = new Dictionary<uint, Vector3>();
        double firstMoveTo = double.PositiveInfinity;
        foreach (MeleeMovement m in rec.Movements)
        {
            if (m.Guid == MeleeRecording.Player && m.Type == 6)
            {
                firstMoveTo = Math.Min(firstMoveTo, m.T);
            }
        }

        int ui = 0, mi = 0, ti = 0;
        double end = Math.Min(endTime, rec.Truth[^1].T);
        for (double now = startT + Dt; now <= end + Dt; now += Dt)
        {
            while (mi < rec.Movements.Count && rec.Movements[mi].T <= now)
            {
                MeleeMovement m = rec.Movements[mi++];
                PhysicsObj? obj = m.Guid == MeleeRecording.Player ? player : monsters.GetValueOrDefault(m.Guid);
                if (obj == player && m.Type == 6)
                {
                    // Every mode: each approach starts where retail's client was.
                    Resync(rec, player, m.T);
                }

                if (obj is null || mode == MeleeMode.InterpolationOnly || (mode == MeleeMode.MoveToIgnored && m.Type != 0))
                {
                    continue;
                }

                MovementEventDecoder.Decode(m.Body, message);
                results[(int)obj.HandleMovementEvent(message)]++;
            }

            while (ui < rec.Updates.Count && rec.Updates[ui].T <= now)
            {
                MeleeUpdate u = rec.Updates[ui++];
                if (!monsters.TryGetValue(u.Guid, out PhysicsObj? monster))
                {
                    continue;
                }

                Vector3 reported = Global(u.Position);
                if (previous.TryGetValue(u.Guid, out Vector3 before))
                {
                    monsterSamples.Add(new MeleeMonsterSample(u.T, u.Guid, Horizontal(Global(monster.Position) - reported),
                        Horizontal(reported - before) > MovingStep));
                }

                previous[u.Guid] = reported;

                handler.HandleMessage((uint)PhysicsMessageOpcode.UpdatePosition, u.Body);
            }

            world.Tick(now);
            while (ti < rec.Truth.Count && rec.Truth[ti].T <= now)
            {
                RealPose p = rec.Truth[ti++];
                if (p.T < firstMoveTo)
                {
                    continue;
                }

                Vector3 body = Global(player.Position);
                Vector3 truth = Global(new Position(p.CellId, p.Origin));
                Vector3 d = body - truth;
                players.Add(new MeleePlayerSample(p.T, Math.Sqrt((double)d.X * d.X + (double)d.Y * d.Y), body, truth));
            }
        }

        return new MeleeReplayResult(players, monsterSamples, results);
    }

    // The player's own client's last pose at or before t: where the player was when the event arrived.
    private static void Resync(MeleeRecording rec, PhysicsObj player, double t)
    {
        int k = LastPoseAtOrBefore(rec, t);
        if (k >= 0)
        {
            player.SetPositionSimple(rec.TruthPositions[k], true);
        }
    }

    /// <summary>Index of the last truth pose at or before <paramref name="t"/>, or −1.</summary>
    public static int LastPoseAtOrBefore(MeleeRecording rec, double t)
    {
        int k = -1;
        for (int i = 0; i < rec.Truth.Count && rec.Truth[i].T <= t; i++)
        {
            k = i;
        }

        return k;
    }

    /// <summary>Global horizontal position (landblock x, y × 192 + local), metres.</summary>
    public static Vector3 Global(in Position p) =>
        new(((p.ObjCellId >> 24) & 0xFF) * 192f + p.Frame.Origin.X, ((p.ObjCellId >> 16) & 0xFF) * 192f + p.Frame.Origin.Y, 0f);

    /// <summary>
    /// The player's approaches: for each MoveToObject, the truth poses from the event to the player's next server-controlled
    /// event (the next MoveToObject, or the TurnToObject after the last), their errors, and where the approach stopped: the
    /// last pose in the window against the target's last report before it, for retail's client and for the body.
    /// </summary>
    public static List<MeleeApproach> Approaches(MeleeRecording rec, MeleeReplayResult run)
    {
        var starts = new List<(double T, uint Target)>();
        var controlled = new List<double>();
        foreach (MeleeMovement m in rec.Movements)
        {
            if (m.Guid != MeleeRecording.Player || m.Autonomous)
            {
                continue;
            }

            if (m.Type == 6)
            {
                starts.Add((m.T, BitConverter.ToUInt32(m.Body, MovementEventDecoder.BodyHeaderLength + 4)));
            }

            if (m.Type != 0)
            {
                controlled.Add(m.T);
            }
        }

        var list = new List<MeleeApproach>();
        foreach ((double t0, uint target) in starts)
        {
            double t1 = double.PositiveInfinity;
            foreach (double c in controlled)
            {
                if (c > t0)
                {
                    t1 = c;
                    break;
                }
            }

            var errors = new List<double>();
            MeleePlayerSample last = default;
            foreach (MeleePlayerSample s in run.Player)
            {
                if (s.T > t0 && s.T < t1)
                {
                    errors.Add(s.Error);
                    last = s;
                }
            }

            if (errors.Count == 0)
            {
                continue;
            }

            Vector3 targetAt = TargetAt(rec, target, last.T);
            Vector3 start = Global(rec.TruthPositions[LastPoseAtOrBefore(rec, t0)]);
            errors.Sort();
            double median = errors.Count % 2 == 1 ? errors[errors.Count / 2] : 0.5 * (errors[errors.Count / 2 - 1] + errors[errors.Count / 2]);
            list.Add(new MeleeApproach(t0, t1, errors.Count, median, errors[^1], Horizontal(last.Truth - targetAt),
                Horizontal(last.Body - targetAt), Horizontal(last.Truth - start), Horizontal(last.Body - start)));
        }

        return list;
    }

    // The target's last reported position at or before t (its create position before its first report).
    private static Vector3 TargetAt(MeleeRecording rec, uint target, double t)
    {
        Position p = rec.Creates[target].Position;
        foreach (MeleeUpdate u in rec.Updates)
        {
            if (u.Guid == target && u.T <= t)
            {
                p = u.Position;
            }
        }

        return Global(p);
    }

    private static double Horizontal(Vector3 d) => Math.Sqrt((double)d.X * d.X + (double)d.Y * d.Y);

    /// <summary>Median, maximum and mean of the monster samples of <paramref name="guid"/> (0: both monsters), only the
    /// moving ones when <paramref name="movingOnly"/>.</summary>
    public static (double Median, double Max, double Mean, int Count) MonsterStats(MeleeReplayResult run, uint guid, bool movingOnly = false)
    {
        var e = new List<double>();
        double sum = 0;
        foreach (MeleeMonsterSample s in run.Monsters)
        {
            if ((guid == 0 || s.Guid == guid) && (!movingOnly || s.Moving))
            {
                e.Add(s.Error);
                sum += s.Error;
            }
        }

        if (e.Count == 0)
        {
            return (double.NaN, double.NaN, double.NaN, 0);
        }

        e.Sort();
        double median = e.Count % 2 == 1 ? e[e.Count / 2] : 0.5 * (e[e.Count / 2 - 1] + e[e.Count / 2]);
        return (median, e[^1], sum / e.Count, e.Count);
    }
}

/// <summary>The recording player's weenie: this client's own player, whose run rate is the one the server sends
/// (<c>my_run_rate</c>, 1.4583 in every MoveToObject here): it does not answer <see cref="InqRunRate"/> itself.</summary>
public sealed class ReplayPlayerWeenie : IMotionWeenie
{
    /// <inheritdoc />
    public bool IsThePlayer => true;

    /// <inheritdoc />
    public bool IsCreature => true;

    /// <inheritdoc />
    public bool IsPlayer => true;

    /// <inheritdoc />
    public bool IsImpenetrable => false;

    /// <inheritdoc />
    public bool IsPK => false;

    /// <inheritdoc />
    public bool IsPKLite => false;

    /// <inheritdoc />
    public bool InqRunRate(out float rate)
    {
        rate = 0f;
        return false;
    }

    /// <inheritdoc />
    public bool InqJumpVelocity(float extent, out float vz)
    {
        vz = 0f;
        return false;
    }

    /// <inheritdoc />
    public bool CanJump(float extent) => false;

    /// <inheritdoc />
    public bool JumpStaminaCost(float extent, out int cost)
    {
        cost = 0;
        return false;
    }
}
