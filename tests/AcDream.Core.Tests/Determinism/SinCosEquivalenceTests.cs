using System;
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
}
