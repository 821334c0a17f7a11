using System;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Tests.Retail;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>Sequences at the edges of the domain: every update returns (no endless advance loop) and leaves finite state.</summary>
public class AnimSequenceTerminationTests
{
    private const uint Empty = 0x03000001, One = 0x03000002, Three = 0x03000003;

    private static AnimSequence Sequence() => new(AnimTestSupport.Library(
        new AnimationBytes(Empty).Build(),
        new AnimationBytes(One).Frame(new Vector3(0.1f, 0f, 0f)).Build(),
        new AnimationBytes(Three).Frame(new Vector3(0.1f, 0f, 0f)).Frame(new Vector3(0.1f, 0f, 0f)).Frame(new Vector3(0.1f, 0f, 0f)).Build()));

    private static void PlaysAndReturns(AnimSequence seq, double quantum)
    {
        Frame f = Frame.Identity;
        for (int i = 0; i < 20; i++)
        {
            seq.Update(quantum, ref f);
            Assert.False(double.IsNaN(seq.FrameNumber));
            Assert.True(VectorMathIsFinite(f.Origin));
        }
    }

    private static bool VectorMathIsFinite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);

    [Fact]
    public void AnimationWithoutFrames_LoopsByOneThirtiethPerPass_AndReturns()
    {
        // set_animation_id on 0 frames: high = low = -1; each pass uses 1/30 s.
        AnimSequence seq = Sequence();
        seq.AppendAnimation(new AnimData(Empty, 0, -1, 30f));
        Assert.Equal(-1, seq.Head!.LowFrame);
        Assert.Equal(-1, seq.Head!.HighFrame);
        PlaysAndReturns(seq, 0.2);
        Assert.Null(seq.CurrentAnimFrame);
    }

    [Fact]
    public void MaxFramerate_OneFrame_Returns()
    {
        AnimSequence seq = Sequence();
        seq.AppendAnimation(new AnimData(One, 0, -1, AnimData.MaxFramerate));
        PlaysAndReturns(seq, 0.2);
        seq.AppendAnimation(new AnimData(Three, 0, -1, -AnimData.MaxFramerate));
        PlaysAndReturns(seq, 0.2);
        PlaysAndReturns(seq, -0.2);
    }

    [Fact]
    public void NegativeMultiplier_InvertsTheRange_UpdatesStillReturn()
    {
        // multiply_framerate(-1) swaps low and high (2..0) and negates the framerate: backwards from high + 1 - EPSILON =
        // 0.9998 the low frame 2 is "passed" at once and every pass leaves more time than it was given; retail loops without
        // end here, the library drops the rest of the step.
        AnimSequence seq = Sequence();
        seq.AppendAnimation(new AnimData(Three, 0, -1, 30f));
        seq.MultiplyCyclicAnimationFramerate(-1f);
        Assert.Equal(2, seq.FirstCyclic!.LowFrame);
        Assert.Equal(0, seq.FirstCyclic!.HighFrame);
        PlaysAndReturns(seq, 0.0625);
        PlaysAndReturns(seq, -0.0625);
    }

    [Fact]
    public void HugeMultiplier_IsClampedToTheFramerateDomain()
    {
        AnimSequence seq = Sequence();
        seq.AppendAnimation(new AnimData(Three, 0, -1, 30f));
        seq.MultiplyCyclicAnimationFramerate(1e30f);
        Assert.Equal(AnimData.MaxFramerate, seq.FirstCyclic!.Framerate);
        seq.MultiplyCyclicAnimationFramerate(float.NaN);
        Assert.Equal(AnimData.MaxFramerate, seq.FirstCyclic!.Framerate);
        PlaysAndReturns(seq, 0.2);
    }

    [Fact]
    public void AnimData_RefusesAFramerateOutsideTheDomain()
    {
        Assert.Throws<ArgumentException>(() => new AnimData(1, 0, -1, float.NaN));
        Assert.Throws<ArgumentException>(() => new AnimData(1, 0, -1, float.PositiveInfinity));
        Assert.Throws<ArgumentException>(() => new AnimData(1, 0, -1, 10001f));
        Assert.Throws<ArgumentException>(() => 1e6f * new AnimData(1, 0, -1, 30f));
        Assert.Equal(-AnimData.MaxFramerate, new AnimData(1, 0, -1, -AnimData.MaxFramerate).Framerate);
    }

    [Fact]
    public void AFrame_RefusesNonFiniteAndNonUnit()
    {
        Assert.Throws<ArgumentException>(() => new AFrame(new Vector3(float.NaN, 0f, 0f), Quaternion.Identity));
        Assert.Throws<ArgumentException>(() => new AFrame(Vector3.Zero, new Quaternion(0f, 0f, 0f, 0.9f)));
        Assert.Throws<ArgumentException>(() => new AFrame(Vector3.Zero, new Quaternion(float.PositiveInfinity, 0f, 0f, 1f)));
        var a = new AFrame(Vector3.One, new Quaternion(0f, 0f, 0f, 0.9995f));
        Assert.Equal(0.9995f, a.Qw); // kept as given
        Assert.Equal(1f, a.ToFrame().Qw); // a Frame renormalises
    }
}
