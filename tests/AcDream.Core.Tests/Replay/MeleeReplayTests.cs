using System;
using System.Globalization;
using System.IO;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Tests.Replay.Harness;
using AcDream.Core.Tests.Support;
using Xunit;
using Xunit.Abstractions;

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
    public void Probe()
    {
        MeleeRecording rec = MeleeRecording.Load(Dir);
        foreach (MeleeMode mode in new[] { MeleeMode.MoveToApplied, MeleeMode.MoveToIgnored, MeleeMode.InterpolationOnly })
        {
            MeleeReplayResult r = MeleeReplay.Run(rec, mode);
            output.WriteLine($"{mode}: results {string.Join(",", r.Results)}");
            foreach (MeleeApproach a in MeleeReplay.Approaches(rec, r))
            {
                output.WriteLine(string.Create(CultureInfo.InvariantCulture, $"  {a}"));
            }

            foreach (uint g in new[] { MeleeRecording.Chicken, MeleeRecording.TheChicken })
            {
                var st = MeleeReplay.MonsterStats(r, g);
                var mv = MeleeReplay.MonsterStats(r, g, true);
                output.WriteLine(string.Create(CultureInfo.InvariantCulture, $"  monster {g:X8}: all {st} moving {mv}"));
            }
        }
    }

    private static float F(string s) => float.Parse(s, CultureInfo.InvariantCulture);
}
