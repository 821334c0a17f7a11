using System;
using System.Globalization;
using System.IO;
using System.Linq;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Tests.Replay.Harness;
using AcDream.Core.Tests.Support;
using Xunit;
using Xunit.Abstractions;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Core.Tests.Replay;

/// <summary>A fact that needs the real replay recordings (<c>ACDREAM_REPLAY_DIR</c>, else ../shared/data/replay beside the
/// terrain folder; see <see cref="SharedDataDir.Replay"/>); skipped with the reason when they are absent
/// (<c>ReplayDataReportTests</c> prints the reason in every run).</summary>
public sealed class ReplayDataFactAttribute : FactAttribute
{
    /// <summary>Skips the test when the recordings are not available.</summary>
    public ReplayDataFactAttribute()
    {
        if (SharedDataDir.Replay.Find(out string reason) is null)
        {
            Skip = "Real replay data not found: " + reason + ".";
        }
    }
}

// The real recordings (../shared/data/replay): every MovementEvent decoded from its bytes, and a remote player replayed at
// 30 Hz with and without the motion interpreter, compared with the poses its own client sent.
public class RealMotionReplayTests(ITestOutputHelper output)
{
    /// <summary>The replay folder, or null.</summary>
    public static string? Dir => SharedDataDir.Replay.Dir;

    private const uint Brenwick = 0x5000001Du;

    [ReplayDataFact]
    public void EveryInterpretedMovementEvent_DecodesToExactlyItsLength()
    {
        var state = new InterpretedMotionState();
        int total = 0, decoded = 0;
        var otherTypes = new System.Collections.Generic.SortedDictionary<int, int>();
        foreach (string slug in new[] { "long-movement-run", "fellowship-one-vassal", "fellowship-two-monarch", "fellowship-three-vassal" })
        {
            bool header = true;
            foreach (string line in File.ReadLines(Path.Combine(Dir!, slug + "_s2c_movementevent.csv")))
            {
                if (header)
                {
                    header = false;
                    continue;
                }

                byte[] data = Convert.FromHexString(line.Split(',')[6]);
                total++;
                if (MovementEventDecoder.TryDecode(data, state, out MovementEventHeader h))
                {
                    decoded++;
                }
                else
                {
                    // Only the move-to and turn-to types (6..9) are not decoded; a type-0 event must always decode.
                    Assert.NotEqual(0, h.MovementType);
                    otherTypes[h.MovementType] = (otherTypes.TryGetValue(h.MovementType, out int n) ? n : 0) + 1;
                }
            }
        }

        output.WriteLine($"{total} MovementEvents, {decoded} of type 0 decoded exactly; other types: {string.Join(", ", otherTypes)}");
        Assert.True(decoded > 600);
        foreach (int t in otherTypes.Keys)
        {
            Assert.InRange(t, 6, 9);
        }
    }

    [ReplayDataFact]
    public void EveryMovementEvent_OfEveryType_DecodesFromItsBody()
    {
        // Every event of the four recordings the motion replay reads, every guid: the body rebuilt from the columns (guid,
        // the three stamps, the autonomous byte, a zero pad, the movement data) decodes exactly (Decode throws on a short or
        // long body), and its type, stamps and guid are the recorded ones. The README: "every message parses to exactly its
        // length"; in these copies long-movement-run's monsters carry 28 MoveToObjects (type 6), the players TurnToObjects (8).
        var message = new MovementEventMessage();
        var byType = new int[10];
        foreach (string slug in new[] { "long-movement-run", "fellowship-one-vassal", "fellowship-two-monarch", "fellowship-three-vassal" })
        {
            bool header = true;
            foreach (string line in File.ReadLines(Path.Combine(Dir!, slug + "_s2c_movementevent.csv")))
            {
                if (header)
                {
                    header = false;
                    continue;
                }

                string[] c = line.Split(',');
                byte[] data = Convert.FromHexString(c[6]);
                byte[] body = new byte[MovementEventDecoder.BodyHeaderLength + data.Length];
                uint guid = uint.Parse(c[1].AsSpan(2), NumberStyles.HexNumber, CultureInfo.InvariantCulture);
                BitConverter.TryWriteBytes(body.AsSpan(0), guid);
                BitConverter.TryWriteBytes(body.AsSpan(4), ushort.Parse(c[2], CultureInfo.InvariantCulture));
                BitConverter.TryWriteBytes(body.AsSpan(6), ushort.Parse(c[3], CultureInfo.InvariantCulture));
                BitConverter.TryWriteBytes(body.AsSpan(8), ushort.Parse(c[4], CultureInfo.InvariantCulture));
                body[10] = c[5] == "1" ? (byte)1 : (byte)0;
                data.CopyTo(body, MovementEventDecoder.BodyHeaderLength);
                MovementEventDecoder.Decode(body, message);
                Assert.Equal(guid, message.ObjectId);
                Assert.Equal(ushort.Parse(c[3], CultureInfo.InvariantCulture), message.MovementTimestamp);
                Assert.Equal(c[5] == "1", message.Autonomous);
                Assert.Equal(data[0], (byte)message.MovementType);
                byType[data[0]]++;
            }
        }

        output.WriteLine($"by type: {string.Join(", ", byType)}");
        Assert.True(byType[6] > 0);
        Assert.True(byType[8] > 0);
    }

    [Fact]
    public void Decode_KnownEvents()
    {
        var s = new InterpretedMotionState();
        // 0000 (type 0, no flags) 3d00 (style index 0x3D) | 03000000 (style + forward) 3d00 0300: NonCombat, Ready; 12 bytes.
        Assert.True(MovementEventDecoder.TryDecode(Convert.FromHexString("00003d00030000003d000300"), s, out MovementEventHeader h));
        Assert.Equal(MotionCommand.NonCombat, h.Style);
        Assert.Equal(MotionCommand.Ready, s.ForwardCommand);
        // 0x66 = style? no: 0x02 forward, 0x04 forward speed, 0x20 turn, 0x40 turn speed: RunForward (7) at 2.8256...
        // 0700 0d00 | 20d73440 (2.8256836) | 0000c0bf (-1.5): run turning left at the run key's 1.5.
        Assert.True(MovementEventDecoder.TryDecode(Convert.FromHexString("000000006600000007000d0020d734400000c0bf"), s, out _));
        Assert.Equal(MotionCommand.RunForward, s.ForwardCommand);
        Assert.Equal(BitConverter.Int32BitsToSingle(0x4034D720), s.ForwardSpeed);
        Assert.Equal(MotionCommand.TurnRight, s.TurnCommand);
        Assert.Equal(-1.5f, s.TurnSpeed);
        // One byte short, or one byte too many: not decoded.
        Assert.False(MovementEventDecoder.TryDecode(Convert.FromHexString("000000006600000007000d0020d734400000c0"), s, out _));
        Assert.False(MovementEventDecoder.TryDecode(Convert.FromHexString("000000006600000007000d0020d734400000c0bf00"), s, out _));
    }

    [ReplayDataFact]
    public void RemotePlayer_Replayed_WithMotion_IsCloserWhileMoving_ThanInterpolationOnly()
    {
        RealRecording rec = RealRecording.Load(Dir!, "long-movement-run", Brenwick);
        RealReplayResult motion = RealReplay.Run(rec, Brenwick, RealMode.AllEvents);
        RealReplayResult interp = RealReplay.Run(rec, Brenwick, RealMode.InterpolationOnly);
        var mm = RealReplay.Stats(motion.Samples, true);
        var im = RealReplay.Stats(interp.Samples, true);
        var ma = RealReplay.Stats(motion.Samples, null);
        var ia = RealReplay.Stats(interp.Samples, null);
        output.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"applied {motion.Applied} of {motion.ByType[0]} type 0 + {motion.MoveToTypes} types 6-9; moving n={mm.Count}: motion median {mm.Median:F3} max {mm.Max:F3}, interp median {im.Median:F3} max {im.Max:F3}; all n={ma.Count}: motion {ma.Median:F3}/{ma.Max:F3}, interp {ia.Median:F3}/{ia.Max:F3}"));
        foreach (RealSample x in motion.Samples)
        {
            if (x.Error > 1.0)
            {
                output.WriteLine(string.Create(CultureInfo.InvariantCulture, $"  motion error {x.Error:F2} m at t {x.T:F2} (moving {x.Moving})"));
            }
        }

        Assert.True(motion.Applied > 100);
        Assert.True(mm.Count > 20);
        Assert.True(mm.Median < im.Median);
    }

    [ReplayDataFact]
    public void LongMovementRun_EveryMovementEvent_GoesThroughTheEntryPoint_AndIsApplied()
    {
        RealRecording rec = RealRecording.Load(Dir!, "long-movement-run", Brenwick);
        // Counted independently of the harness: the first byte of each of +Brenwick's movement data is its type.
        int type0 = 0, type8 = 0, other = 0;
        foreach (string line in File.ReadLines(Path.Combine(Dir!, "long-movement-run_s2c_movementevent.csv")))
        {
            string[] c = line.Split(',');
            if (c[1] != "0x5000001D")
            {
                continue;
            }

            switch (c[6][..2])
            {
                case "00": type0++; break;
                case "08": type8++; break;
                default: other++; break;
            }
        }

        RealReplayResult all = RealReplay.Run(rec, Brenwick, RealMode.AllEvents);
        RealReplayResult zero = RealReplay.Run(rec, Brenwick, RealMode.TypeZeroOnly);
        Assert.Equal(type0, all.ByType[0]);
        Assert.Equal(type8, all.ByType[8]);
        Assert.Equal(0, other);
        Assert.True(type8 > 0);
        // Every event is delivered (the last, 394.3485 s, is 1.8 ms after the last own pose and the replay ticks one tick
        // past it); the movement stamps are 1, 2, ..., 142 in arrival order (always newer), the server-control stamps 0..11
        // never fall, and the replayed player is a remote object (no echo of "this client's" motion to ignore): every one
        // is Applied, type 8 included; with types 6-9 dropped, exactly the type-0 ones.
        Assert.Equal(type0 + type8, all.Applied);
        Assert.Equal(type0 + type8, all.Results.Sum());
        Assert.Equal(type0, zero.Applied);

        // The TurnToObjects (bitfield 0x1EE0F, StopCompletely among them) turn the body in place, and each is followed by a
        // type-0 event of +Brenwick within 0.03-0.85 s (234.797 -> 234.822, 366.667 -> 367.377, 369.106 -> 369.952,
        // 386.556 -> 387.141, 390.720 -> 391.317, 394.264 -> 394.349) that sets the motion again; a turn moves no origin, so
        // every compared (horizontal) error is the same with them as without.
        Assert.Equal(zero.Samples, all.Samples);

        // t 234.82: a sticky type-0 event (motion flag 0x01) sticks +Brenwick to 0x80001EF2, now in the world under its
        // updates; its last report (199.40 s) is (52.5030899, -58.5909538), +Brenwick's pose at 234.84 s is (52.0668335,
        // -60.4548492): 1.914 m apart (dx 0.436, dy 1.864). The stand-ins' cylinder radii are 0 (OneSphere sets spheres
        // only), so the sticky manager pulls the body to StickyRadius 0.3 m of the target's centre, while retail's client
        // (real radii) stayed put: the body can be off by at most 1.914 - 0.3 = 1.614 m in that window.
        var w = RealReplay.Stats(all.Samples.Where(x => x.T >= 233.0 && x.T < 239.0).ToList(), null);
        double dx = 52.5030899 - 52.0668335, dy = -58.5909538 - -60.4548492;
        double bound = Math.Sqrt(dx * dx + dy * dy) - 0.3;
        Assert.InRange(bound, 1.61, 1.62);
        Assert.InRange(w.Max, 0.0, bound);
    }
}
