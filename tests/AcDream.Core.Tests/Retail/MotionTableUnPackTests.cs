using System;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Motion;
using Xunit;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// <c>CMotionTable::UnPack</c> (acclient.c:338603) and <c>MotionData::UnPack</c> (acclient.c:341813) over bytes written
/// field by field (<see cref="MotionTableBytes"/>): every table, key and field read back, the MotionData padding, and bad
/// bytes refused with <see cref="RetailDataFormatException"/> only.
/// </summary>
public class MotionTableUnPackTests
{
    private const uint NonCombat = 0x8000003Du, Ready = 0x41000003u, Walk = 0x45000005u, Turn = 0x6500000Du;

    private static byte[] Sample() => new MotionTableBytes { Id = 0x09000123, DefaultStyle = NonCombat }
        .StyleDefault(NonCombat, Ready)
        .Cycle(NonCombat, Ready, MotionDataSpec.One(0x03000001, 0, -1, 30f))
        .Cycle(NonCombat, Walk, MotionDataSpec.One(0x03000002, 2, 7, 25f, velocity: new Vector3(0f, 3.12f, 0f), bitfield: 1))
        .Modifier(0, Turn, new MotionDataSpec(Array.Empty<(uint, int, int, float)>(), Omega: new Vector3(0f, 0f, -1.5f)))
        .Link(NonCombat, Ready, Walk, MotionDataSpec.One(0x03000003, 0, 4, 30f))
        .Link(NonCombat, Ready, 0x10000062u, MotionDataSpec.One(0x03000004, 0, -1, 30f))
        .ToArray();

    [Fact]
    public void EveryTableAndFieldIsReadBack()
    {
        MotionTable t = MotionTable.UnPack(Sample());

        Assert.Equal(0x09000123u, t.Id);
        Assert.Equal((MotionCommand)NonCombat, t.DefaultStyle);
        Assert.Equal(1, t.StyleCount);
        Assert.Equal(2, t.CycleCount);
        Assert.Equal(1, t.ModifierCount);
        Assert.Equal(2, t.LinkCount);
        Assert.True(t.TryGetDefaultSubstate((MotionCommand)NonCombat, out MotionCommand def));
        Assert.Equal(MotionCommand.Ready, def);

        // Cycle key (style << 16) | (substate & 0xFFFFFF): 0x8000003D << 16 = 0x003D0000 (the style's high bits shift out).
        MotionData walk = t.Cycles[0x003D0000u | 0x000005u];
        Assert.Equal(0x003D0005u, walk.Id);
        Assert.Equal(1, walk.NumAnims);
        Assert.Equal(1, walk.Bitfield);
        Assert.Equal(0x03000002u, walk.Anims[0].AnimId);
        Assert.Equal(2, walk.Anims[0].LowFrame);
        Assert.Equal(7, walk.Anims[0].HighFrame);
        Assert.Equal(0x41C80000u, BitConverter.SingleToUInt32Bits(walk.Anims[0].Framerate)); // 25
        Assert.Equal(0x4047AE14u, BitConverter.SingleToUInt32Bits(walk.Velocity.Y));        // 3.12f
        Assert.Equal(Vector3.Zero, walk.Omega);                                               // flag 2 clear: zeroed

        MotionData turn = t.Modifiers[0x00000Du];
        Assert.Equal(0, turn.NumAnims);
        Assert.Equal(0xBFC00000u, BitConverter.SingleToUInt32Bits(turn.Omega.Z));            // -1.5
        Assert.Equal(Vector3.Zero, turn.Velocity);

        var inner = t.Links[0x003D0000u | 0x000003u];
        Assert.Equal(2, inner.Count);
        Assert.Equal(4, inner[Walk].Anims[0].HighFrame);
        Assert.Equal(0x03000004u, inner[0x10000062u].Anims[0].AnimId);
    }

    [Fact]
    public void MotionDataPadsItsThreeBytesToFour()
    {
        // id (4) + num_anims, bitfield, physics (3) + 1 padding byte = 8 bytes before the first AnimData; the table's
        // header is id, default_style, style count 0, cycle count 1 = 16 bytes, so the cycle's padding byte is byte 23.
        byte[] bytes = new MotionTableBytes { DefaultStyle = NonCombat }
            .Cycle(NonCombat, Ready, MotionDataSpec.One(0x03000001, 0, -1, 30f)).ToArray();
        Assert.Equal(0, bytes[23]);
        Assert.Equal(0x03000001u, BitConverter.ToUInt32(bytes, 24));
        // header 16 + MotionData 8 + AnimData 16 + modifier count 4 + link count 4
        Assert.Equal(48, bytes.Length);
        MotionTable t = MotionTable.UnPack(bytes);
        Assert.Equal(0x03000001u, t.Cycles[0x003D0003u].Anims[0].AnimId);
    }

    [Fact]
    public void ALaterEntryWithTheSameKeyIsTheOneFound()
    {
        // Retail inserts at the head of the bucket: a lookup finds the later entry of two with one key.
        byte[] bytes = new MotionTableBytes { DefaultStyle = NonCombat }
            .StyleDefault(NonCombat, Ready).StyleDefault(NonCombat, Walk).ToArray();
        Assert.True(MotionTable.UnPack(bytes).TryGetDefaultSubstate((MotionCommand)NonCombat, out MotionCommand d));
        Assert.Equal(MotionCommand.WalkForward, d);
    }

    [Fact]
    public void EveryTruncationIsAFormatError()
    {
        byte[] bytes = Sample();
        for (int n = 0; n < bytes.Length; n++)
        {
            var ex = Assert.Throws<RetailDataFormatException>(() => MotionTable.UnPack(bytes.AsSpan(0, n)));
            Assert.Equal("CMotionTable", ex.Structure);
        }
    }

    [Fact]
    public void ACountBeyondTheBytesIsRefusedBeforeAnythingIsSizedByIt()
    {
        byte[] bytes = Sample();
        BitConverter.TryWriteBytes(bytes.AsSpan(8, 4), 0x7FFFFFFFu); // the style-default count
        var ex = Assert.Throws<RetailDataFormatException>(() => MotionTable.UnPack(bytes));
        Assert.Equal(8, ex.Offset); // the error names the count's own field (@8), not the byte after it
    }

    [Fact]
    public void ANonFiniteOrTooFastVelocityIsRefused()
    {
        byte[] nan = new MotionTableBytes { DefaultStyle = NonCombat }
            .Cycle(NonCombat, Walk, new MotionDataSpec(Array.Empty<(uint, int, int, float)>(), Velocity: new Vector3(0f, float.NaN, 0f)))
            .ToArray();
        Assert.Throws<RetailDataFormatException>(() => MotionTable.UnPack(nan));
        byte[] fast = new MotionTableBytes { DefaultStyle = NonCombat }
            .Cycle(NonCombat, Walk, new MotionDataSpec(Array.Empty<(uint, int, int, float)>(), Velocity: new Vector3(0f, 50.5f, 0f)))
            .ToArray();
        Assert.Throws<RetailDataFormatException>(() => MotionTable.UnPack(fast));
    }
    [Fact]
    public void NumAnims_IsASignedChar_128AndAboveAreRefused()
    {
        // MotionData::UnPack (acclient.c:341813) reads num_anims as a char: it sizes the array by the unsigned byte but its
        // read loop (`v14 < num_anims`) and GetObjectSequence's sums use the sign-extended value, so 128..255 read past the
        // array. 127 animations are read; 128 are a format error at the count's byte (after the 4-byte id).
        static byte[] With(int n)
        {
            var anims = new (uint, int, int, float)[n];
            for (int i = 0; i < n; i++)
            {
                anims[i] = (0x03000001u, 0, -1, 30f);
            }

            return new MotionTableBytes { DefaultStyle = NonCombat }
                .StyleDefault(NonCombat, Ready)
                .Cycle(NonCombat, Ready, new MotionDataSpec(anims))
                .ToArray();
        }

        Assert.Equal(1, MotionTable.UnPack(With(127)).CycleCount);
        var ex = Assert.Throws<RetailDataFormatException>(() => MotionTable.UnPack(With(128)));
        Assert.Contains("127", ex.Message);
        Assert.Throws<RetailDataFormatException>(() => MotionTable.UnPack(With(255)));
    }
}
