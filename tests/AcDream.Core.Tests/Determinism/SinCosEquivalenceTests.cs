using System;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Determinism;

/// <summary>
/// The Frame code takes the sine and cosine of one angle from <see cref="Math.SinCos"/>; that is retail-exact only if it
/// gives the bits of <see cref="Math.Sin"/> and <see cref="Math.Cos"/>, which this checks on the platform the tests run on
/// (on glibc, sincos shares sin's and cos's code). Angles of every size the frame code meets, and their float roundings.
/// </summary>
[Trait("Category", "Determinism")]
public class SinCosEquivalenceTests
{
    [Fact]
    public void SinCos_GivesTheBitsOfSinAndCos()
    {
        var rng = new Random(1806);
        double[] scales = { 1e-9, 1e-4, 0.02, 0.3, 1.0, 3.2, 7.0, 13.0, 400.0 };
        foreach (double scale in scales)
        {
            for (int i = 0; i < 40_000; i++)
            {
                double x = (rng.NextDouble() * 2.0 - 1.0) * scale;
                if ((i & 3) == 0)
                {
                    x = (float)x;
                }

                (double s, double c) = Math.SinCos(x);
                Assert.Equal(BitConverter.DoubleToInt64Bits(Math.Sin(x)), BitConverter.DoubleToInt64Bits(s));
                Assert.Equal(BitConverter.DoubleToInt64Bits(Math.Cos(x)), BitConverter.DoubleToInt64Bits(c));
            }
        }

        foreach (double x in new[] { 0.0, -0.0, Math.PI / 2, Math.PI, 1e-300, double.Epsilon })
        {
            (double s, double c) = Math.SinCos(x);
            Assert.Equal(BitConverter.DoubleToInt64Bits(Math.Sin(x)), BitConverter.DoubleToInt64Bits(s));
            Assert.Equal(BitConverter.DoubleToInt64Bits(Math.Cos(x)), BitConverter.DoubleToInt64Bits(c));
        }
    }

    [Fact]
    public void Fmod360Shortcut_GivesTheBitsOfTheRemainder()
    {
        // HeadingMath.Fmod360 returns x or x - 360 on [0, 720) instead of calling fmod; both must agree with % everywhere.
        var rng = new Random(1810);
        for (int i = 0; i < 400_000; i++)
        {
            double x = (i % 4) switch
            {
                0 => 450.0 - (rng.NextDouble() * 2.0 - 1.0) * Math.PI * 57.29577951308232,
                1 => rng.NextDouble() * 720.0,
                2 => (rng.NextDouble() * 2.0 - 1.0) * 1e4,
                _ => 360.0 + (rng.Next(5) - 2) * 1e-13,
            };
            Assert.Equal(BitConverter.DoubleToInt64Bits(x % 360.0), BitConverter.DoubleToInt64Bits(HeadingMath.Fmod360(x)));
        }

        double[] edges = { 0.0, -0.0, 360.0, 720.0, Math.BitDecrement(720.0), Math.BitDecrement(360.0), double.NaN, double.PositiveInfinity, -1e-300 };
        foreach (double x in edges)
        {
            Assert.Equal(BitConverter.DoubleToInt64Bits(x % 360.0), BitConverter.DoubleToInt64Bits(HeadingMath.Fmod360(x)));
        }
    }
}

