using System;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Tests.Support;
using AcDream.Core.Physics.Data;
using Xunit;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// The animation unpackers over random and mutated bytes (a seeded loop, replayable from the seed): each input either
/// unpacks or throws <see cref="RetailDataFormatException"/> — no other exception, no hang — and a count larger than the
/// bytes is refused before anything is sized by it.
/// </summary>
public class AnimationUnPackFuzzTests
{
    private const int Iterations = 4000;

    private static byte[] ValidEntry()
    {
        var b = new AnimationBytes(0x03000001, numParts: 2);
        b.Frame(new Vector3(1f, 0f, 0f), new Quaternion(0f, 0f, 0.70710677f, 0.70710677f))
            .Sound(5, AnimHookDirection.Forward)
            .Hook(AnimHookType.ReplaceObject, AnimHookDirection.Both, w => w.Byte(1).UInt16(0x8001).UInt16(2))
            .Hook(AnimHookType.Scale, AnimHookDirection.Both, w => w.Single(2f).Single(0.5f));
        b.Frame(new Vector3(0f, 1f, 0f))
            .Hook(AnimHookType.CreateParticle, AnimHookDirection.Backward,
                w => w.UInt32(1).UInt32(0).Frame(Vector3.Zero, Quaternion.Identity).UInt32(3))
            .Hook(AnimHookType.Attack, AnimHookDirection.Both,
                w => w.Int32(0).Single(1f).Single(0f).Single(0f).Single(1f).Single(2f).Single(1f));
        return b.ToArray();
    }

    private static void UnPacksOrRefuses(byte[] bytes)
    {
        try
        {
            AnimClip a = AnimClip.UnPack(bytes);
            Assert.True(a.NumFrames >= 0);
        }
        catch (RetailDataFormatException)
        {
        }
    }

    [Fact]
    public void ValidEntry_Unpacks()
    {
        AnimClip a = AnimClip.UnPack(ValidEntry());
        Assert.Equal(2, a.NumFrames);
        Assert.Equal(3, a.PartFrames[0].NumFrameHooks);
    }

    [Fact]
    public void RandomBytes_UnpackOrRefuse()
    {
        var rng = new Random(20271);
        for (int i = 0; i < Iterations; i++)
        {
            byte[] bytes = new byte[rng.Next(0, 200)];
            rng.NextBytes(bytes);
            // Small counts half the time, so that the reads go past the header.
            if (bytes.Length >= 16 && rng.Next(2) == 0)
            {
                BitConverter.TryWriteBytes(bytes.AsSpan(8), (uint)rng.Next(0, 3));
                BitConverter.TryWriteBytes(bytes.AsSpan(12), (uint)rng.Next(0, 3));
            }

            UnPacksOrRefuses(bytes);
        }
    }

    [Fact]
    public void MutatedEntries_UnpackOrRefuse()
    {
        byte[] valid = ValidEntry();
        var rng = new Random(20272);
        for (int i = 0; i < Iterations; i++)
        {
            byte[] bytes = (byte[])valid.Clone();
            switch (rng.Next(4))
            {
                case 0: // flip bits
                    for (int k = rng.Next(1, 4); k > 0; k--)
                    {
                        bytes[rng.Next(bytes.Length)] ^= (byte)(1 << rng.Next(8));
                    }

                    break;
                case 1: // truncate
                    Array.Resize(ref bytes, rng.Next(bytes.Length));
                    break;
                case 2: // a random word at a word boundary (counts, types, floats)
                    int at = rng.Next(bytes.Length / 4) * 4;
                    BitConverter.TryWriteBytes(bytes.AsSpan(at), rng.Next(3) == 0 ? uint.MaxValue : (uint)rng.Next());
                    break;
                default: // a random byte anywhere
                    bytes[rng.Next(bytes.Length)] = (byte)rng.Next(256);
                    break;
            }

            UnPacksOrRefuses(bytes);
        }
    }

    [Fact]
    public void HugeCounts_AreRefusedBeforeAllocating()
    {
        // num_frames 0x7FFFFFFF with 64 parts each would be ~7.7e12 bytes: refused from the count alone.
        byte[] bytes = new RetailDataWriter().UInt32(1).UInt32(1).UInt32(64).UInt32(0x7FFFFFFF).ToArray();
        long before = GC.GetAllocatedBytesForCurrentThread();
        Assert.Throws<RetailDataFormatException>(() => AnimClip.UnPack(bytes));
        Assert.True(GC.GetAllocatedBytesForCurrentThread() - before < 64 * 1024);
    }

    [Fact]
    public void SequenceUnPack_RandomAndMutated_UnpackOrRefuse_AndLeaveTheSequenceUnchangedWhenRefused()
    {
        var lib = new AnimationLibrary();
        lib.Add(new AnimationBytes(0x03000001).Frame().Frame().Frame().ToArray());
        byte[] valid = new RetailDataWriter()
            .UInt32(2)
            .UInt32(0x03000001).Int32(0).Int32(-1).Single(30f)
            .UInt32(0x03000001).Int32(0).Int32(-1).Single(-30f)
            .Bytes(BitConverter.GetBytes(1.5)).UInt32(1).UInt32(0)
            .UInt32(3).Single(1f).Single(0f).Single(0f).Single(0f).Single(0f).Single(1f)
            .ToArray();
        var rng = new Random(20273);
        for (int i = 0; i < Iterations; i++)
        {
            byte[] bytes;
            if (rng.Next(2) == 0)
            {
                bytes = new byte[rng.Next(0, 120)];
                rng.NextBytes(bytes);
                if (bytes.Length >= 4)
                {
                    BitConverter.TryWriteBytes(bytes.AsSpan(0), (uint)rng.Next(0, 4));
                }
            }
            else
            {
                bytes = (byte[])valid.Clone();
                bytes[rng.Next(bytes.Length)] = (byte)rng.Next(256);
                if (rng.Next(3) == 0)
                {
                    Array.Resize(ref bytes, rng.Next(bytes.Length));
                }
            }

            var seq = new AnimSequence(lib);
            seq.SetVelocity(new Vector3(7f, 0f, 0f));
            try
            {
                seq.UnPack(bytes);
            }
            catch (RetailDataFormatException)
            {
                Assert.Equal(new Vector3(7f, 0f, 0f), seq.Velocity);
                Assert.False(seq.HasAnims);
                continue;
            }

            // Whatever was accepted plays without throwing or hanging.
            var f = AcDream.Core.Physics.Spatial.Frame.Identity;
            for (int k = 0; k < 10; k++)
            {
                seq.Update(0.2, ref f);
            }
        }
    }
}
