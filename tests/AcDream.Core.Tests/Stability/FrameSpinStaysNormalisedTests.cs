using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Tests.Retail;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// A million ticks of constant spin through Frame::grotate keep the quaternion unit-length and the cached matrix orthonormal
/// and equal to the matrix rebuilt from the quaternion.
/// </summary>
public class FrameSpinStaysNormalisedTests
{
    [Fact]
    public void OneMillionTicksOfConstantSpin_QuaternionAndCacheStayWithinBound()
    {
        // Tolerances. set_rotate normalises in double and rounds each of the 4 components to float (relative error
        // <= 2^-24 each), so |q|² - 1 <= 4 * 2 * 2^-24 ~ 4.8e-7 after EVERY tick: the error does not accumulate because each
        // tick renormalises. Bound used: 1e-6.
        // The cache is computed in double from the float quaternion and rounded: each entry's error is its rounding
        // (<= 2^-24 ~ 6e-8) plus the effect of |q|² - 1 (<= 1e-6), so rows are orthonormal within ~2e-6. Bound used: 4e-6.
        // Cache vs. rebuilt: same inputs, only the final float rounding differs: bound 1e-7.
        Frame f = Frame.FromHeading(Vector3.Zero, 10f);
        var w = new Vector3(0.0123f, -0.0456f, 0.0333f); // about 0.058 rad per tick about a skew axis
        double worstNorm = 0;
        for (int i = 0; i < 1_000_000; i++)
        {
            f.GRotate(w);
            if ((i & 1023) == 0)
            {
                double n2 = (double)f.Qw * f.Qw + (double)f.Qx * f.Qx + (double)f.Qy * f.Qy + (double)f.Qz * f.Qz;
                worstNorm = Math.Max(worstNorm, Math.Abs(n2 - 1.0));
            }
        }

        Assert.True(worstNorm < 1e-6, $"| |q|² - 1 | reached {worstNorm}");
        FrameTests.AssertOrthonormal(f, 4e-6);
        FrameTests.AssertCacheMatchesQuaternion(f, 1e-7);
    }

    [Fact]
    public void ConstantSpinAboutZ_HeadingMatchesClosedForm()
    {
        // 0.02 rad clockwise per tick for 9,000 ticks = 180 rad. 180 rad in degrees = 10313.24...; mod 360 = 233.2395 deg.
        // Bound: each tick's float rounding of the angle (~0.02 * 2^-24 relative) plus quaternion rounding per tick
        // (~1e-7 rad) accumulates to ~9000 * 1.2e-7 ~ 1e-3 rad ~ 0.06 degrees at worst; bound 0.1 degrees.
        Frame f = Frame.Identity;
        var w = new Vector3(0f, 0f, -0.02f);
        for (int i = 0; i < 9000; i++)
        {
            f.GRotate(w);
        }

        double expected = (9000 * (double)-w.Z * (180.0 / Math.PI)) % 360.0;
        double diff = Math.Abs(((f.Heading - expected) % 360.0 + 540.0) % 360.0 - 180.0);
        Assert.True(diff < 0.1, $"heading {f.Heading} vs {expected}");
    }
}
