using System;
using System.Collections.Generic;
using System.Linq;
using System.Globalization;
using System.IO;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Tests.Replay.Harness;
using AcDream.Core.Tests.Support;
using Xunit;
using Xunit.Abstractions;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Core.Tests.Replay;

/// <summary>A fact that needs the melee-attack-run recording (<see cref="MeleeRecording.MarkerFile"/> in the replay folder,
/// <see cref="SharedDataDir.Replay"/>); skipped with the reason when it is absent.</summary>
public sealed class MeleeDataFactAttribute : FactAttribute
{
    /// <summary>Skips the test when the recording is not available.</summary>
    public MeleeDataFactAttribute()
    {
        string? dir = SharedDataDir.Replay.Find(out string reason);
        if (dir is null)
        {
            Skip = "Real replay data not found: " + reason + ".";
        }
        else if (!File.Exists(Path.Combine(dir, MeleeRecording.MarkerFile)))
        {
            Skip = $"The melee-attack-run recording is not in {dir} (no {MeleeRecording.MarkerFile}).";
        }
    }
}

// The melee-attack-run recording (../shared/data/replay, README "melee-attack-run"): every MovementEvent decoded from its
// bytes through the retail entry point; the player's server-driven approaches and the monsters' wandering replayed.
public class MeleeReplayTests(ITestOutputHelper output)
{
    private static string Dir => SharedDataDir.Replay.Dir!;

    [MeleeDataFact]
    public void EveryMovementEvent_DecodesToExactlyItsLength_AndMatchesTheDecodedColumns()
    {
        var m = new MovementEventMessage();
        int total = 0, moveTo = 0;
        bool header = true;
        foreach (string line in File.ReadLines(Path.Combine(Dir, MeleeRecording.MarkerFile)))
        {
            if (header || line.Length == 0)
            {
                header = false;
                continue;
            }

            string[] c = line.Split(',');
            MovementEventDecoder.DecodeMovementData(Convert.FromHexString(c[6]), m);
            total++;
            Assert.Equal(int.Parse(c[8], CultureInfo.InvariantCulture), (int)m.MovementType);
            if (m.MovementType == MovementEventType.InterpretedMotion)
            {
                continue;
            }

            // The README's independently decoded columns: target, origin, bitfield, the move-to floats, heading, run rate.
            moveTo++;
            MovementParameters p = m.Parameters;
            Assert.Equal(c[9], "0x" + m.TargetId.ToString("X8", CultureInfo.InvariantCulture));
            Assert.Equal(c[14], "0x" + ((uint)p.Flags).ToString("X", CultureInfo.InvariantCulture));
            Assert.Equal(F(c[18]), p.Speed);
            Assert.Equal(F(c[20]), p.DesiredHeading);
            if (m.MovementType is MovementEventType.MoveToObject or MovementEventType.MoveToPosition)
            {
                Assert.Equal(c[10], "0x" + m.Origin.ObjCellId.ToString("X8", CultureInfo.InvariantCulture));
                Assert.Equal(F(c[11]), m.Origin.Frame.Origin.X);
                Assert.Equal(F(c[12]), m.Origin.Frame.Origin.Y);
                Assert.Equal(F(c[13]), m.Origin.Frame.Origin.Z);
                Assert.Equal(F(c[15]), p.DistanceToObject);
                Assert.Equal(F(c[16]), p.MinDistance);
                Assert.Equal(F(c[17]), p.FailDistance);
                Assert.Equal(F(c[19]), p.WalkRunThreshold);
                Assert.Equal(F(c[21]), m.RunRate);
            }

            if (m.MovementType == MovementEventType.TurnToObject)
            {
                Assert.Equal(F(c[22]), m.TurnToObjectHeading);
            }
        }

        output.WriteLine($"{total} MovementEvents decoded exactly, {moveTo} of types 6-9 equal to the README's columns");
        // The shared part (t < 60 s): 56 events, 12 of types 6-9 (player 4 MoveToObject + 1 TurnToObject; Chicken 4
        // MoveToPosition + 1 TurnToHeading; The Chicken 2 MoveToPosition).
        Assert.True(total >= 56);
        Assert.True(moveTo >= 12);
    }

    [ReplayDataFact]
    public void EveryMovementEventOfTheOtherRecordings_DecodesToExactlyItsLength_EveryType()
    {
        // long-movement-run and the fellowship captures hold 55 events of types 6 and 8 that the type-0 decoder leaves
        // (RealMotionReplayTests): the whole decoder reads them all.
        var m = new MovementEventMessage();
        var byType = new SortedDictionary<MovementEventType, int>();
        foreach (string slug in new[] { "long-movement-run", "fellowship-one-vassal", "fellowship-two-monarch", "fellowship-three-vassal" })
        {
            foreach (string line in File.ReadLines(Path.Combine(Dir, slug + "_s2c_movementevent.csv")).Skip(1))
            {
                if (line.Length == 0)
                {
                    continue;
                }

                MovementEventDecoder.DecodeMovementData(Convert.FromHexString(line.Split(',')[6]), m);
                byType[m.MovementType] = (byType.TryGetValue(m.MovementType, out int n) ? n : 0) + 1;
            }
        }

        output.WriteLine(string.Join(", ", byType.Select(kv => $"{kv.Key} {kv.Value}")));
        Assert.True(byType[MovementEventType.InterpretedMotion] > 600);
        Assert.True(byType[MovementEventType.MoveToObject] + byType[MovementEventType.TurnToObject] >= 55);
    }

    [MeleeDataFact]
    public void PlayersMoveToObject_CarriesACEsMeleeApproachParameters()
    {
        // msg 141, t 19.21: MoveToObject onto the Chicken; fail distance 15, speed 1.5, walk/run threshold 1, run rate 1.4583.
        MeleeRecording rec = MeleeRecording.Load(Dir);
        var m = new MovementEventMessage();
        MovementEventDecoder.Decode(rec.PlayerMoveToObjects()[0].Body, m);
        Assert.Equal(MeleeRecording.Player, m.ObjectId);
        Assert.Equal((ushort)7, m.MovementTimestamp);
        Assert.Equal((ushort)2, m.ServerControlTimestamp);
        Assert.False(m.Autonomous);
        Assert.Equal(MovementEventType.MoveToObject, m.MovementType);
        Assert.Equal(MeleeRecording.Chicken, m.TargetId);
        Assert.Equal(0x41700000u, BitConverter.SingleToUInt32Bits(m.Parameters.FailDistance));
        Assert.Equal(0x3FC00000u, BitConverter.SingleToUInt32Bits(m.Parameters.Speed));
        Assert.Equal(0x3F800000u, BitConverter.SingleToUInt32Bits(m.Parameters.WalkRunThreshold));
        // 0x1EFFF: every flag of bits 0-11 (walk, run, side-step, backwards, charge, fail-walk, final heading, sticky, away,
        // towards, spheres, set hold key) and bits 13-16 (modify raw and interpreted state, cancel move-to, stop completely).
        Assert.Equal(0x1EFFFu, (uint)m.Parameters.Flags);
    }

    [MeleeDataFact]
    public void PlayerApproach_WithMoveTo_FollowsItsOwnClient_AndStopsWhereRetailStopped()
    {
        MeleeRecording rec = MeleeRecording.Load(Dir);
        List<MeleeApproach> applied = SharedPart(MeleeReplay.Approaches(rec, MeleeReplay.Run(rec, MeleeMode.MoveToApplied)));
        List<MeleeApproach> ignored = SharedPart(MeleeReplay.Approaches(rec, MeleeReplay.Run(rec, MeleeMode.MoveToIgnored)));
        // The shared part holds the four MoveToObjects onto the Chicken (t 19.21, 25.52, 32.57, 39.83).
        Assert.Equal(4, applied.Count);
        Assert.Equal(4, ignored.Count);

        // Tolerance. (1) One replay tick of the charge: the event lands up to 1/30 s before the tick that starts the run,
        // at RunAnimSpeed 4.0 x run rate 1.45833337 (the event's) x speed 1.5 (the event's) = 8.75 m/s: 0.2917 m.
        var m = new MovementEventMessage();
        MovementEventDecoder.Decode(rec.PlayerMoveToObjects()[0].Body, m);
        double tick = MotionInterp.RunAnimSpeed * m.RunRate * m.Parameters.Speed * MeleeReplay.Dt;
        // (2) The glide retail's client plays after a run stops (the run-to-ready link animation moves it on), which the
        // stand-in motion table (SpeedOnlyMotionPlayer) does not: measured on first-login-walk-jump, the same retail
        // client's stop pose to its pose 1 s later (0.7884 m, both runs).
        double glide = StopGlide(Dir);
        double bound = glide + tick;
        double fail = m.Parameters.FailDistance;
        for (int k = 0; k < 4; k++)
        {
            MeleeApproach a = applied[k], n = ignored[k];
            output.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"approach {k + 1} at {a.Start:F2}: applied median {a.Median:F3} max {a.Max:F3}, ignored median {n.Median:F3} max {n.Max:F3}; "
                + $"stop to target retail {a.RetailStopDistance:F2} body {a.StopDistance:F2} (ignored {n.StopDistance:F2}); "
                + $"travel retail {a.RetailTravel:F2} body {a.Travel:F2}; bound {bound:F3}"));
            Assert.True(a.Median < n.Median && a.Max < n.Max, "MoveTo applied is closer to the own client's poses than ignored");
            Assert.InRange(a.Max, 0.0, bound);
            // Each approach ends by its fail distance (15 m from the start, CheckProgressMade/HandleMoveToPosition), within
            // the tick that crosses it; retail's client went on by its glide.
            Assert.InRange(a.Travel, fail, fail + tick);
            Assert.InRange(a.RetailTravel - a.Travel, 0.0, bound);
            Assert.InRange(Math.Abs(a.StopDistance - a.RetailStopDistance), 0.0, bound);
            // Ignoring the MoveTo leaves the body at the start: off by the whole approach.
            Assert.True(n.Max > fail);
        }
    }

    [MeleeDataFact]
    public void MonsterPrediction_WithMoveToPosition_BeatsInterpolationOnly()
    {
        MeleeRecording rec = MeleeRecording.Load(Dir);
        MeleeReplayResult applied = MeleeReplay.Run(rec, MeleeMode.MoveToApplied, SharedEnd);
        MeleeReplayResult ignored = MeleeReplay.Run(rec, MeleeMode.MoveToIgnored, SharedEnd);
        MeleeReplayResult interp = MeleeReplay.Run(rec, MeleeMode.InterpolationOnly, SharedEnd);
        foreach (uint g in new uint[] { MeleeRecording.Chicken, MeleeRecording.TheChicken, 0 })
        {
            var a = MeleeReplay.MonsterStats(applied, g);
            var n = MeleeReplay.MonsterStats(ignored, g);
            var i = MeleeReplay.MonsterStats(interp, g);
            output.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"0x{g:X8}: n {a.Count}; MoveToPosition applied median {a.Median:F3} mean {a.Mean:F3} max {a.Max:F3}; "
                + $"type 0 only {n.Median:F3} / {n.Mean:F3} / {n.Max:F3}; interpolation only {i.Median:F3} / {i.Mean:F3} / {i.Max:F3}"));
        }

        // Both monsters together, and The Chicken (speed 1, walking at about the stand-in table's 3.12 m/s) alone: the body
        // moved by its MoveToPosition is nearer each next report than the body that only follows the reports.
        var all = MeleeReplay.MonsterStats(applied, 0);
        var allInterp = MeleeReplay.MonsterStats(interp, 0);
        Assert.True(all.Count >= 70);
        Assert.True(all.Mean < allInterp.Mean);
        Assert.True(all.Median < allInterp.Median);
        var theChicken = MeleeReplay.MonsterStats(applied, MeleeRecording.TheChicken);
        var theChickenInterp = MeleeReplay.MonsterStats(interp, MeleeRecording.TheChicken);
        Assert.True(theChicken.Mean < theChickenInterp.Mean);
        Assert.True(theChicken.Max < theChickenInterp.Max);
        // The type-0 events alone (emotes, Ready) do not move a monster: the same as interpolation only for the Chicken.
        Assert.Equal(MeleeReplay.MonsterStats(interp, MeleeRecording.Chicken).Mean, MeleeReplay.MonsterStats(ignored, MeleeRecording.Chicken).Mean);
    }

    /// <summary>End of the shared part of the recording, s.</summary>
    private const double SharedEnd = 60.0;

    private static List<MeleeApproach> SharedPart(List<MeleeApproach> all) => all.FindAll(a => a.Start < SharedEnd);

    // first-login-walk-jump (same retail client): for each run stop (a MoveToState with raw flags 0x1 after one with 0x5),
    // the distance from its pose to the next AutonomousPosition; the largest.
    private static double StopGlide(string dir)
    {
        string path = Path.Combine(dir, "first-login-walk-jump_c2s_autonomous.csv");
        Assert.True(File.Exists(path), "first-login-walk-jump is needed for the stop glide: " + path);
        string[][] rows = File.ReadAllLines(path)[1..].Where(l => l.Length != 0).Select(l => l.Split(',')).ToArray();
        double glide = 0;
        for (int i = 1; i + 1 < rows.Length; i++)
        {
            if (rows[i][9] == "0xF61C" && rows[i][15] == "0x1" && rows[i - 1][15] == "0x5" && rows[i + 1][9] == "0xF753")
            {
                double dx = F(rows[i + 1][2]) - F(rows[i][2]), dy = F(rows[i + 1][3]) - F(rows[i][3]);
                glide = Math.Max(glide, Math.Sqrt(dx * dx + dy * dy));
            }
        }

        Assert.InRange(glide, 0.5, 1.0);
        return glide;
    }

    private static float F(string s) => float.Parse(s, CultureInfo.InvariantCulture);
}
