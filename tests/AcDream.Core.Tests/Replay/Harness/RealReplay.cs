using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Core.Tests.Replay.Harness;

/// <summary>One S2C UpdatePosition (0xF748): its body as the wire carried it after the opcode (<see cref="WireBodies.UpdatePosition"/>)
/// and the fields <see cref="PhysicsMessageDecoder"/> decodes from it.</summary>
public readonly record struct RealUpdate(double T, Position Position, bool Grounded, ushort SeqPosition, ushort SeqTeleport,
                                         ushort SeqInstance, byte[] Body);

/// <summary>One S2C VectorUpdate (0xF74E) of the replayed guid: its body after the opcode.</summary>
public sealed record RealVector(double T, byte[] Body);

/// <summary>One S2C MovementEvent (0xF74C) of the replayed guid: its movement type and its body as the wire carries it after
/// the opcode (guid, instance, movement and server-control stamps, autonomous byte, pad, then the recorded movement data).</summary>
public sealed record RealMovement(double T, byte Type, byte[] Body);

/// <summary>One pose the character's own client sent (C2S), the ground truth.</summary>
public readonly record struct RealPose(double T, uint CellId, Vector3 Origin);

/// <summary>
/// A real recording (../shared/data/replay, README there) of one player: the updates and movement events every observer
/// received, and the poses its own client sent. Times are the recording's own clock.
/// </summary>
public sealed class RealRecording
{
    /// <summary>Updates in arrival order.</summary>
    public List<RealUpdate> Updates { get; } = new();

    /// <summary>Movement events in arrival order.</summary>
    public List<RealMovement> Movements { get; } = new();

    /// <summary>Vector updates (0xF74E) in arrival order.</summary>
    public List<RealVector> Vectors { get; } = new();

    /// <summary>The updates of every other guid, in arrival order (the objects a client around the player knows).</summary>
    public Dictionary<uint, List<RealUpdate>> OtherUpdates { get; } = new();

    /// <summary>Own poses in send order (F61C and F753 at one instant count once).</summary>
    public List<RealPose> Truth { get; } = new();

    /// <summary>Loads recording <paramref name="slug"/> for <paramref name="guid"/> (whose own recording it must be).</summary>
    public static RealRecording Load(string dir, string slug, uint guid, double endTime = double.PositiveInfinity)
    {
        var r = new RealRecording();
        string g = "0x" + guid.ToString("X8", CultureInfo.InvariantCulture);
        foreach (string[] c in Rows(Path.Combine(dir, slug + "_s2c_updateposition.csv")))
        {
            double t = D(c[0]);
            if (t > endTime)
            {
                continue;
            }

            // The body rebuilt from the columns and decoded by the library, as a client decodes what it receives.
            byte[] body = WireBodies.UpdatePosition(c);
            UpdatePositionMessage m = WireBodies.DecodePosition(body);
            var u = new RealUpdate(t, m.Position, m.HasContact, m.PositionTimestamp, m.TeleportTimestamp, m.InstanceTimestamp, body);
            if (c[1] == g)
            {
                r.Updates.Add(u);
            }
            else
            {
                uint other = U(c[1]);
                if (!r.OtherUpdates.TryGetValue(other, out List<RealUpdate>? list))
                {
                    r.OtherUpdates[other] = list = new List<RealUpdate>();
                }

                list.Add(u);
            }
        }

        foreach (string[] c in Rows(Path.Combine(dir, slug + "_s2c_movementevent.csv")))
        {
            double t = D(c[0]);
            if (c[1] == g && t <= endTime)
            {
                // The body after the opcode, rebuilt from the recorded columns: every field the wire carries is recorded
                // (guid, the three stamps, the autonomous byte; the pad is zero), then the movement data bytes as received.
                byte[] body = WireBodies.MovementEvent(c);
                r.Movements.Add(new RealMovement(t, body[MovementEventDecoder.BodyHeaderLength], body));
            }
        }

        string vectors = Path.Combine(dir, slug + "_s2c_vectorupdate.csv");
        if (File.Exists(vectors))
        {
            foreach (string[] c in Rows(vectors))
            {
                double t = D(c[0]);
                if (c[1] == g && t <= endTime)
                {
                    r.Vectors.Add(new RealVector(t, WireBodies.VectorUpdate(c)));
                }
            }
        }

        double last = double.NaN;
        foreach (string[] c in Rows(Path.Combine(dir, slug + "_c2s_autonomous.csv")))
        {
            double t = D(c[0]);
            if (t > endTime || t == last)
            {
                continue;
            }

            last = t;
            r.Truth.Add(new RealPose(t, U(c[1]), new Vector3(F(c[2]), F(c[3]), F(c[4]))));
        }

        return r;
    }

    private static IEnumerable<string[]> Rows(string path)
    {
        bool header = true;
        foreach (string line in File.ReadLines(path))
        {
            if (header)
            {
                header = false;
                continue;
            }

            if (line.Length != 0)
            {
                yield return line.Split(',');
            }
        }
    }

    private static double D(string s) => double.Parse(s, CultureInfo.InvariantCulture);

    private static float F(string s) => float.Parse(s, CultureInfo.InvariantCulture);

    private static uint U(string s) => uint.Parse(s.AsSpan(2), NumberStyles.HexNumber, CultureInfo.InvariantCulture);
}

/// <summary>
/// A collision sweep for the real replay: the ground is level at the height of the last received update (the recordings
/// carry no terrain), so a body that walks by root motion stays on the ground.
/// </summary>
public sealed class LastReportGroundSweep : CollisionSweep
{
    /// <summary>Ground height, metres (in the landblock of the last update).</summary>
    public float GroundZ { get; set; }

    /// <inheritdoc />
    public override bool SweepObject(PhysicsObj obj, in Position oldPos, in Position newPos, bool adminMove, ref TransitionResult result)
    {
        result = Land(newPos);
        return true;
    }

    /// <inheritdoc />
    public override SetPositionError SetPosition(PhysicsObj obj, in Position pos, SetPositionFlags flags)
    {
        obj.CommitTransition(Land(pos));
        return SetPositionError.Ok;
    }

    private TransitionResult Land(in Position pos)
    {
        TransitionResult r = TransitionResult.FreeSpace(pos);
        if (r.CurrentPosition.Frame.Origin.Z <= GroundZ + 0.02f)
        {
            r.CurrentPosition.Frame.Origin.Z = GroundZ;
            r.ContactPlaneValid = true;
            r.ContactPlaneNormal = new Vector3(0f, 0f, 1f);
            r.ContactPlaneD = -GroundZ;
            r.ContactPlaneCellId = pos.ObjCellId;
        }

        return r;
    }
}

/// <summary>The error of one truth pose: when, how far off, whether the character was moving.</summary>
public readonly record struct RealSample(double T, double Error, bool Moving);

/// <summary>What a real replay does with the replayed player's MovementEvents.</summary>
public enum RealMode
{
    /// <summary>Every event is decoded from its body (<see cref="MovementEventDecoder.Decode"/>) and goes through the
    /// retail entry point (<see cref="PhysicsObj.HandleMovementEvent"/>): types 0 and 6-9, as a client does.</summary>
    AllEvents,

    /// <summary>As <see cref="AllEvents"/>, but events of types 6-9 are dropped (type 0 only: what the replay applied before
    /// the entry point existed).</summary>
    TypeZeroOnly,

    /// <summary>No MovementEvent is applied: the body follows its UpdatePositions only.</summary>
    InterpolationOnly,
}

/// <summary>Result of a real replay run.</summary>
/// <param name="Samples">Every compared truth pose.</param>
/// <param name="ByType">The replayed player's MovementEvents by movement type (index = type, 0..9).</param>
/// <param name="Results">How many events given to <see cref="PhysicsObj.HandleMovementEvent"/> ended in each
/// <see cref="MovementEventResult"/> (index = the result's value); events a mode drops are not counted.</param>
public sealed record RealReplayResult(List<RealSample> Samples, int[] ByType, int[] Results)
{
    /// <summary>Events the entry point applied (<see cref="MovementEventResult.Applied"/>).</summary>
    public int Applied => Results[(int)MovementEventResult.Applied];

    /// <summary>Events of types 6-9.</summary>
    public int MoveToTypes => ByType[6] + ByType[7] + ByType[8] + ByType[9];
}

/// <summary>
/// Replays a recording's updates (and, by <see cref="RealMode"/>, its movement events) through a world at 30 Hz, the player
/// as a remote object, and compares the body with the poses the player's own client sent. Every object the player's
/// MoveToObject / TurnToObject events target or its type-0 events stick to that has UpdatePositions in the recording is in the world too (a remote
/// object under its updates, created at its first one), as it is in a client that sees the player: the move-to manager
/// then tracks it; a target without updates (a static the recording has no position for) is unknown to the world, and the
/// entry point does what retail does then (turns to the event's heading, moves to the event's origin).
/// </summary>
public static class RealReplay
{
    /// <summary>Truth poses within this long after a teleport or a landblock change are not compared, seconds.</summary>
    public const double SettleTime = 2.0;

    /// <summary>A truth pose counts as moving when the truth moved faster than this, m/s.</summary>
    public const double MovingSpeed = 0.5;

    /// <summary>Runs the replay.</summary>
    public static RealReplayResult Run(RealRecording rec, uint guid, RealMode mode)
    {
        const double dt = 1.0 / 30.0;
        RealUpdate first = rec.Updates[0];
        var sweep = new LastReportGroundSweep { GroundZ = first.Position.Frame.Origin.Z };
        var world = new PhysicsWorld(first.T) { Sweep = sweep };
        // The observer: an idle player that follows the replayed character's reports (so it is always within the 96 m
        // gate, as the fellow observers were), moved only when a report lands in another landblock.
        PhysicsObj observer = world.CreateObject(1);
        observer.PartArray = new SimplePartArray(1, 0);
        observer.EnterWorld(first.Position);
        world.Player = observer;
        PhysicsObj obj = world.CreateObject(guid);
        obj.Weenie = RemoteCreatureWeenie.Player;
        SimplePartArray parts = Walkers.OneSphere();
        parts.MotionPlayer = new SpeedOnlyMotionPlayer();
        obj.PartArray = parts;
        obj.EnterWorld(first.Position);
        // The server's UpdatePositions and VectorUpdates go through the SmartBox entry points (instance gate, stamps); the
        // object holds the recording's instance stamp, as its CreateObject would have set it.
        var handler = new ServerMessageHandler(world);
        obj.NewerEvent(PhysicsTimeStamp.Instance, first.SeqInstance);
        var message = new MovementEventMessage();
        var targets = Targets(rec);
        var samples = new List<RealSample>();
        int[] byType = new int[10];
        int[] results = new int[6];
        int ui = 1, mi = 0, ti = 0, vi = 0;
        double settleUntil = first.T + SettleTime;
        uint block = first.Position.ObjCellId >> 16;
        while (ti < rec.Truth.Count && rec.Truth[ti].T < first.T)
        {
            ti++;
        }

        foreach (RealMovement m in rec.Movements)
        {
            byType[m.Type]++;
        }

        double end = rec.Truth[^1].T;
        for (double now = first.T + dt; now <= end + dt; now += dt)
        {
            foreach (Target target in targets)
            {
                uint tg = target.Guid;
                while (target.Next < target.Updates.Count && target.Updates[target.Next].T <= now)
                {
                    RealUpdate u = target.Updates[target.Next++];
                    if (world.GetObjectById(tg) is not null)
                    {
                        handler.HandleMessage((uint)PhysicsMessageOpcode.UpdatePosition, u.Body);
                    }
                    else
                    {
                        // Created where its first update puts it (the recordings carry no CreateObject for these).
                        PhysicsObj created = world.CreateObject(tg);
                        created.Weenie = (tg >> 28) == 5 ? RemoteCreatureWeenie.Player : RemoteCreatureWeenie.Creature;
                        created.PartArray = Walkers.OneSphere();
                        created.EnterWorld(u.Position);
                        created.NewerEvent(PhysicsTimeStamp.Instance, u.SeqInstance);
                    }
                }
            }

            while (mi < rec.Movements.Count && rec.Movements[mi].T <= now)
            {
                RealMovement m = rec.Movements[mi++];
                if (mode == RealMode.InterpolationOnly || (mode == RealMode.TypeZeroOnly && m.Type != 0))
                {
                    continue;
                }

                MovementEventDecoder.Decode(m.Body, message);
                results[(int)obj.HandleMovementEvent(message)]++;
            }

            while (vi < rec.Vectors.Count && rec.Vectors[vi].T <= now)
            {
                handler.HandleMessage((uint)PhysicsMessageOpcode.VectorUpdate, rec.Vectors[vi++].Body);
            }

            while (ui < rec.Updates.Count && rec.Updates[ui].T <= now)
            {
                RealUpdate u = rec.Updates[ui++];
                if ((u.Position.ObjCellId >> 16) != block || u.SeqTeleport != rec.Updates[ui - 2].SeqTeleport)
                {
                    settleUntil = u.T + SettleTime;
                    block = u.Position.ObjCellId >> 16;
                    observer.SetPositionSimple(u.Position, false);
                }

                sweep.GroundZ = u.Position.Frame.Origin.Z;
                handler.HandleMessage((uint)PhysicsMessageOpcode.UpdatePosition, u.Body);
            }

            world.Tick(now);
            while (ti < rec.Truth.Count && rec.Truth[ti].T <= now)
            {
                RealPose p = rec.Truth[ti];
                bool moving = ti > 0 && Speed(rec.Truth[ti - 1], p) > MovingSpeed;
                ti++;
                if (p.T < settleUntil || (p.CellId >> 16) != (obj.Position.ObjCellId >> 16))
                {
                    continue;
                }

                Vector3 d = obj.Position.Frame.Origin - p.Origin;
                samples.Add(new RealSample(p.T, Math.Sqrt((double)d.X * d.X + (double)d.Y * d.Y), moving));
            }
        }

        return new RealReplayResult(samples, byType, results);
    }

    // A targeted object with updates: its guid, its updates and the index of the next one to deliver.
    private sealed class Target(uint guid, List<RealUpdate> updates)
    {
        public uint Guid { get; } = guid;

        public List<RealUpdate> Updates { get; } = updates;

        public int Next { get; set; }
    }

    /// <summary>The objects the player's events target (types 6 and 8) or stick to (type 0) that have updates in the
    /// recording.</summary>
    private static List<Target> Targets(RealRecording rec)
    {
        var list = new List<Target>();
        var seen = new HashSet<uint>();
        foreach (RealMovement m in rec.Movements)
        {
            // Type 6 and 8 name their target right after the 4-byte header; a sticky type-0 event (motion flag 0x01) names
            // its object in its last 4 bytes.
            int at = m.Type is 6 or 8 ? MovementEventDecoder.BodyHeaderLength + 4
                : m.Type == 0 && (m.Body[MovementEventDecoder.BodyHeaderLength + 1] & 0x01) != 0 ? m.Body.Length - 4 : -1;
            if (at >= 0)
            {
                uint target = BitConverter.ToUInt32(m.Body, at);
                if (rec.OtherUpdates.TryGetValue(target, out List<RealUpdate>? ups) && seen.Add(target))
                {
                    list.Add(new Target(target, ups));
                }
            }
        }

        return list;
    }

    private static double Speed(RealPose a, RealPose b)
    {
        if ((a.CellId >> 16) != (b.CellId >> 16) || b.T <= a.T)
        {
            return 0.0;
        }

        Vector3 d = b.Origin - a.Origin;
        return Math.Sqrt((double)d.X * d.X + (double)d.Y * d.Y) / (b.T - a.T);
    }

    /// <summary>Median and maximum of the errors selected by <paramref name="moving"/> (null: all).</summary>
    public static (double Median, double Max, int Count) Stats(List<RealSample> s, bool? moving)
    {
        var e = new List<double>();
        foreach (RealSample x in s)
        {
            if (moving is null || x.Moving == moving)
            {
                e.Add(x.Error);
            }
        }

        if (e.Count == 0)
        {
            return (double.NaN, double.NaN, 0);
        }

        e.Sort();
        double median = e.Count % 2 == 1 ? e[e.Count / 2] : 0.5 * (e[e.Count / 2 - 1] + e[e.Count / 2]);
        return (median, e[^1], e.Count);
    }
}
