using System;
using Xunit;

namespace AcDream.Core.Tests.Stability.Misuse;

/// <summary>
/// Issue #15 item 4: a non-positive, non-finite, subnormal or huge scale is refused at every entry point (SetScaleStatic,
/// SetScale at once and as a fade's target, the part array's SetScale), state unchanged, and the world keeps ticking. Before
/// the fix SetScaleStatic(−1) was accepted and every later Tick threw from inside the sweep (a negative sphere radius).
/// </summary>
public class ScaleDomainTests
{
    // The domain [0.01, 100] (InputLimits.MinScale, MaxScale); the bad values below lie outside it.
    public static TheoryData<float> BadScales => new()
    {
        -1f, -1e30f, float.MinValue, 0f, -0f, 1e-45f, MathF.BitDecrement(0.01f) /* the float below 0.01f */,
        MathF.BitIncrement(100f) /* the float above 100 */, 1e30f, float.MaxValue, float.NaN, float.PositiveInfinity,
        float.NegativeInfinity,
    };

    [Theory]
    [MemberData(nameof(BadScales))]
    public void BadScale_IsRefusedEverywhere_StateUnchanged_AndTicksGoOn(float bad)
    {
        var s = new MisuseScene();
        PublicState before = PublicState.Capture(s);
        Assert.ThrowsAny<ArgumentException>(() => s.Walker.SetScaleStatic(bad));
        Assert.ThrowsAny<ArgumentException>(() => s.Walker.SetScale(bad, 0.0));
        Assert.ThrowsAny<ArgumentException>(() => s.Walker.SetScale(bad, 1.0)); // a fade ending at the bad value
        Assert.ThrowsAny<ArgumentException>(() => s.WalkerParts.SetScale(bad));
        Assert.Empty(PublicState.Diff(before, PublicState.Capture(s)));
        s.Tick(30);
        Assert.Equal(1f, s.Walker.Scale);
    }

    [Theory]
    [InlineData(0.01f)]
    [InlineData(100f)]
    public void ScaleAtTheDomainEdges_IsAccepted_AndTicksGoOn(float edge)
    {
        // The bounds themselves are in the domain: a fade to them passes only through values between 1 and the bound.
        var s = new MisuseScene();
        s.Walker.SetScale(edge, 0.5);
        s.Tick(30); // 1.5 s: the 0.5 s fade has ended
        Assert.Equal(edge, s.Walker.Scale);
        s.Other.SetScaleStatic(edge);
        s.Tick(30);
        Assert.Empty(PublicState.Capture(s).NonFinite);
    }
}
