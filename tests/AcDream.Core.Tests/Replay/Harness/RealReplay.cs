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

namespace AcDream.Core.Tests.Replay.Harness;

/// <summary>One S2C UpdatePosition (0xF748) of the replayed guid.</summary>
public readonly record struct RealUpdate(double T, Position Position, bool Grounded, ushort SeqPosition, ushort SeqTeleport);

/// <summary>One S2C MovementEvent (0xF74C) of the replayed guid: its movement data bytes.</summary>
public sealed record RealMovement(double T, byte[] Data);

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
            if (c[1] != g || t > endTime)
            {
                continue;
            }

            var frame = new Frame(new Vector3(F(c[4]), F(c[5]), F(c[6])), new Quaternion(F(c[8]), F(c[9]), F(c[10]), F(c[7])));
            r.Updates.Add(new RealUpdate(t, new Position(U(c[3]), frame), c[15] == "1", (ushort)int.Parse(c[17], CultureInfo.InvariantCulture),
                (ushort)int.Parse(c[18], CultureInfo.InvariantCulture)));
        }

        foreach (string[] c in Rows(Path.Combine(dir, slug + "_s2c_movementevent.csv")))
        {
            double t = D(c[0]);
            if (c[1] == g && t <= endTime)
            {
                r.Movements.Add(new RealMovement(t, Convert.FromHexString(c[6])));
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

/// <summary>Result of a real replay run.</summary>
/// <param name="Samples">Every compared truth pose.</param>
/// <param name="Decoded">Movement events decoded (type 0, exact length) and applied.</param>
/// <param name="Skipped">Movement events of other types (move-to, turn-to), not applied.</param>
public sealed record RealReplayResult(List<RealSample> Samples, int Decoded, int Skipped);

/// <summary>
/// Replays a recording's updates (and, with motion, its movement events) through a world at 30 Hz, the player as a remote
/// object, and compares the body with the poses the player's own client sent.
/// </summary>
public static class RealReplay
{
    /// <summary>Truth poses within this long after a teleport or a landblock change are not compared, seconds.</summary>
    public const double SettleTime = 2.0;

    /// <summary>A truth pose counts as moving when the truth moved faster than this, m/s.</summary>
    public const double MovingSpeed = 0.5;

    /// <summary>Runs the replay.</summary>
    public static RealReplayResult Run(RealRecording rec, uint guid, bool applyMotion)
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
        parts.MotionTable = new RetailSpeedMotionTable();
        obj.PartArray = parts;
        obj.EnterWorld(first.Position);
        var state = new InterpretedMotionState();
        var samples = new List<RealSample>();
        int ui = 1, mi = 0, ti = 0, decoded = 0, skipped = 0;
        double settleUntil = first.T + SettleTime;
        uint block = first.Position.ObjCellId >> 16;
        while (ti < rec.Truth.Count && rec.Truth[ti].T < first.T)
        {
            ti++;
        }

        double end = rec.Truth[^1].T;
        for (double now = first.T + dt; now <= end + dt; now += dt)
        {
            while (mi < rec.Movements.Count && rec.Movements[mi].T <= now)
            {
                RealMovement m = rec.Movements[mi++];
                if (MovementEventDecoder.TryDecode(m.Data, state, out MovementEventHeader h))
                {
                    decoded++;
                    if (applyMotion)
                    {
                        MovementEvent.ApplyInterpretedMotion(obj, state, h.StickToObject, h.StandingLongJump);
                    }
                }
                else
                {
                    skipped++;
                }
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
                obj.HandleReceivedPosition(u.Position, u.SeqPosition, u.SeqTeleport, u.Grounded);
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

        return new RealReplayResult(samples, decoded, skipped);
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
