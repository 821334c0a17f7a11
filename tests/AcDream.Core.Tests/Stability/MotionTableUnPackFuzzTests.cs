using System;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Tests.Support;
using FsCheck;
using FsCheck.Fluent;
using Xunit;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// <see cref="MotionTable.UnPack"/> over random bytes and over a valid humanoid table with bytes flipped, cut and counts
/// inflated: it returns a table or throws <see cref="RetailDataFormatException"/>, never another exception, never hangs.
/// </summary>
public class MotionTableUnPackFuzzTests
{
    private static Config Cfg => PropertyAssert.Replayable(400, 20261202UL, 0x9E3779B97F4A7C15UL);

    private static bool OnlyFormatErrors(byte[] bytes)
    {
        try
        {
            MotionTable.UnPack(bytes);
            return true;
        }
        catch (RetailDataFormatException)
        {
            return true;
        }
    }

    [Fact]
    public void RandomBytes()
    {
        PropertyAssert.Holds(Cfg, Prop.ForAll(Gen.ArrayOf(Gen.Choose(0, 255).Select(i => (byte)i)).ToArbitrary(),
            (byte[] bytes) => OnlyFormatErrors(bytes)));
    }

    [Fact]
    public void MutatedHumanoidTable()
    {
        byte[] valid = HumanoidMotionTable.Bytes();
        Gen<(int At, int Value, int Cut, int Kind)> mutation =
            from at in Gen.Choose(0, valid.Length - 1)
            from value in Gen.Choose(0, 255)
            from cut in Gen.Choose(0, valid.Length)
            from kind in Gen.Choose(0, 2)
            select (at, value, cut, kind);
        PropertyAssert.Holds(Cfg, Prop.ForAll(Gen.ArrayOf(mutation, 4).ToArbitrary(), muts =>
        {
            byte[] b = (byte[])valid.Clone();
            foreach ((int at, int value, int cut, int kind) in muts)
            {
                switch (kind)
                {
                    case 0:
                        if (at < b.Length)
                        {
                            b[at] = (byte)value;
                        }

                        break;
                    case 1:
                        b = b.AsSpan(0, Math.Min(cut, b.Length)).ToArray();
                        break;
                    default:
                        // a count-sized dword set large at a four-byte boundary
                        int a = at & ~3;
                        if (a + 4 <= b.Length)
                        {
                            BitConverter.TryWriteBytes(b.AsSpan(a, 4), 0x00010000u | (uint)value);
                        }

                        break;
                }
            }

            return OnlyFormatErrors(b);
        }));
    }
}
