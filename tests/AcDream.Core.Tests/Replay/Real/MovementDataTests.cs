using System;
using Xunit;

namespace AcDream.Core.Tests.Replay.Real;

/// <summary>Decoding of the MovementEvent (0xF74C) movement data, by hand and over every recorded message.</summary>
public class MovementDataTests
{
    [Fact]
    public void CommandIds_AreRetailsTable()
    {
        // command_ids (acclient_data.h:1456), checked against the named commands of the decompilation's notes
        // (docs/01-physics.md §5): 3 Ready, 13 TurnRight, 14 TurnLeft, 15 SideStepRight, 16 SideStepLeft, 60 HandCombat;
        // 0 = 0x80000000 and 0x3D = NonCombat 0x8000003D (InterpretedMotionState's default style, -2147483587).
        Assert.Equal(0x80000000u, CommandIds.FromIndex(0));
        Assert.Equal(0x85000001u, CommandIds.FromIndex(1));   // HoldRun
        Assert.Equal(0x41000003u, CommandIds.FromIndex(3));
        Assert.Equal(0x45000005u, CommandIds.FromIndex(5));   // WalkForward
        Assert.Equal(0x45000006u, CommandIds.FromIndex(6));   // WalkBackwards
        Assert.Equal(0x44000007u, CommandIds.FromIndex(7));   // RunForward
        Assert.Equal(0x6500000Du, CommandIds.FromIndex(13));
        Assert.Equal(0x6500000Eu, CommandIds.FromIndex(14));
        Assert.Equal(0x6500000Fu, CommandIds.FromIndex(15));
        Assert.Equal(0x65000010u, CommandIds.FromIndex(16));
        Assert.Equal(0x8000003Cu, CommandIds.FromIndex(60));
        Assert.Equal(0x8000003Du, CommandIds.FromIndex(61));
        Assert.Throws<FormatException>(() => CommandIds.FromIndex(408));
    }

    [Fact]
    public void TurnInPlace_ByHand()
    {
        // 00 00 | 00 00 | 60 00 00 00 | 0d 00 | 00 00 c0 bf | 00 00  (long-movement-run t 32.53, Brenwick)
        // header: type 0, flags 0; style index 0 -> 0x80000000; state flags 0x60 = turn command (0x20) + turn speed (0x40);
        // turn command index 13 = TurnRight; turn speed bits 0xBFC00000 = -1.5; then 2 bytes of padding to 16.
        MovementData d = MovementData.Decode(Convert.FromHexString("00000000600000000d000000c0bf0000"));
        Assert.Equal(0, d.MovementType);
        Assert.Equal(0x80000000u, d.Style);
        WireMotionState m = d.Motion!.Value;
        Assert.Equal(0x6500000Du, m.TurnCommand);
        Assert.Equal(-1.5f, m.TurnSpeed);
        Assert.Equal(0x41000003u, m.ForwardCommand);   // absent: Ready
        Assert.Equal(0x8000003Du, m.CurrentStyle);     // absent: NonCombat
        Assert.Equal(1f, m.ForwardSpeed);
        Assert.Equal(1f, m.SidestepSpeed);
    }

    [Fact]
    public void ChaseWithStickyObject_ByHand()
    {
        // 00 01 | 40 00 | 47 00 00 00 | 40 00 | 60 00 | 00 00 00 40 | 00 00 10 40 | f2 1e 00 80  (monster chase, t 234.82)
        // header: type 0, flags 0x01 (sticky id follows); style index 0x40; state flags 0x47 = style, forward, forward
        // speed, turn speed; style 0x40, forward index 0x60; forward speed 2.0 (0x40000000), turn speed 2.25 (0x40100000);
        // 12 + 8 = 20 bytes, aligned; sticky object 0x80001EF2; 24 bytes in all.
        MovementData d = MovementData.Decode(Convert.FromHexString("0001400047000000400060000000004000001040f21e0080"));
        WireMotionState m = d.Motion!.Value;
        Assert.Equal(CommandIds.FromIndex(0x40), m.CurrentStyle);
        Assert.Equal(CommandIds.FromIndex(0x60), m.ForwardCommand);
        Assert.Equal(2f, m.ForwardSpeed);
        Assert.Equal(2.25f, m.TurnSpeed);
        Assert.Equal(0x80001EF2u, d.StickyObject);
    }

    [Fact]
    public void TrailingOrMissingBytes_AreDecodingErrors()
    {
        Assert.Throws<FormatException>(() => MovementData.Decode(Convert.FromHexString("00000000600000000d000000c0bf000000")));
        Assert.Throws<FormatException>(() => MovementData.Decode(Convert.FromHexString("00000000600000000d000000c0bf")));
    }

    [ReplayDataFact]
    public void EveryRecordedMovementEvent_ParsesToExactlyItsLength()
    {
        // The data README's census: 171 (two-monarch) + 172 (one-vassal) + 134 (three-vassal) F74C in the fellowship
        // captures; the long-run copy stops at t_rel = 400 s (README), which leaves 281 of its 1,163 rows.
        int total = 0;
        foreach (string recording in ReplayData.Recordings)
        {
            total += ReplayData.MovementEvents(recording).Count; // Decode throws on any byte left over or missing
        }

        Assert.Equal(171 + 172 + 134 + 281, total);
    }
}
