using System;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Spatial;
using Xunit;
using static AcDream.Core.Tests.Retail.AnimTestSupport;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// EPSILON in the animation code (issue #33): retail's x87 code loads the float EPSILON, 0.0002f (0x3951B717), widened to
/// double, 1.99999994947575e-4; the decompiler prints it as 0.00019999999, a double literal 4.95e-12 smaller. The port used
/// that literal in <c>update_internal</c>, <c>advance_to_next_animation</c>, <c>get_starting_frame</c>,
/// <c>get_ending_frame</c> and <c>change_cycle_speed</c>; each now uses <see cref="PhysicsGlobals.Epsilon"/> widened.
/// </summary>
public class AnimationEpsilonTests
{
    private const uint TenFrames = 0x03000010, OneFrame = 0x03000011, Cycle = 0x03000012;

    private static AnimClip Clip(uint id, int frames)
    {
        var b = new AnimationBytes(id);
        for (int i = 0; i < frames; i++)
        {
            b.Frame();
        }

        return b.Build();
    }

    [Fact]
    public void StartingFrameBackwards_IsHighPlusOneMinusTheWidenedFloat()
    {
        // get_starting_frame (acclient.c:341015) of a backwards animation with high frame 9: 10.0 - (double)0.0002f =
        // 9.999800000005052, bits 0x4023FFE5C91D2000 (the low 12 bits of the mantissa are zero: 10 - 2^-13 × 1.6384 needs
        // only the float's 24 significant bits below 10). With the double literal it was 9.99980000001, 0x4023FFE5C91D2AE1.
        var seq = new AnimSequence(Library(Clip(TenFrames, 10)));
        seq.AppendAnimation(new AnimData(TenFrames, 0, 9, -30f));
        Assert.Equal(0x4023FFE5C91D2000L, BitConverter.DoubleToInt64Bits(seq.FrameNumber));
    }

    [Fact]
    public void EndingFrameForwards_IsHighPlusOneMinusTheWidenedFloat()
    {
        // get_ending_frame (acclient.c:341027) of a forward animation, read where advance_to_next_animation uses it going
        // backwards in time: one animation at +30 fps from frame 0, played by -0.05 s (-1.5 frames). The first pass passes
        // the low frame at once (time left -1.5 / 30 = -0.05 s: frame 0 is where it started) and loops to the last animation
        // (itself) at its ending frame 10 - (double)0.0002f = 9.999800000005052; the second pass moves it by -1.5 frames to
        // 8.499800000005052, bits 0x4020FFE5C91D2000 (with the double literal: 8.49980000001, 0x4020FFE5C91D2AE1).
        var seq = new AnimSequence(Library(Clip(TenFrames, 10)));
        seq.AppendAnimation(new AnimData(TenFrames, 0, 9, 30f));
        Frame f = Frame.Identity;
        seq.Update(-0.05, ref f);
        Assert.Equal(0x4020FFE5C91D2000L, BitConverter.DoubleToInt64Bits(seq.FrameNumber));
    }

    [Fact]
    public void FramerateOfExactlyEpsilon_AppliesNoVelocity_WhenItsAnimationStarts()
    {
        // A one-frame link at 30 fps, then a cycle at exactly 0.0002f fps; velocity +x 1 m/s. One 0.05 s update: the link's
        // 1.5 frames pass its high frame 0 without leaving a frame (the high frame's step applies only backwards), and
        // advance_to_next_animation (acclient.c:340472) starts the cycle: its framerate is positive, so it applies
        // 1/framerate s of velocity when |framerate| > EPSILON. With the widened float |0.0002f| > EPSILON is false, as in
        // retail: nothing moves. With the double literal it was true and applied 1/0.0002f = 5000.0001 s (5,000 m). The
        // 0.5 frame left (1/60 s) then advances the cycle 3.3e-6 frames: no frame left, no velocity (update_internal
        // applies velocity × quantum only for a zero frame quantum).
        var seq = new AnimSequence(Library(Clip(OneFrame, 1), Clip(Cycle, 1)));
        seq.AppendAnimation(new AnimData(OneFrame, 0, 0, 30f));
        seq.AppendAnimation(new AnimData(Cycle, 0, 0, PhysicsGlobals.Epsilon));
        seq.SetVelocity(new Vector3(1f, 0f, 0f));
        Frame f = Frame.Identity;
        seq.Update(0.05, ref f);
        Assert.Equal(0f, f.Origin.X);
        Assert.Equal((double)PhysicsGlobals.Epsilon * (0.5 / 30.0), seq.FrameNumber);
    }

    [Fact]
    public void AFrameNorm_IsSummedInDouble_ThenStoredAsFloat()
    {
        // AFrame::IsValid (acclient.c:467555): norm = qz² + qy² + qx² + qw² on the x87 stack, stored to a float. For the
        // quaternion below the exact sum is 1.0010000088887168; stored as float it is 1.0010000467300415, beyond
        // 1 + 5 × (double)0.0002f = 1.0009999999747379: retail refuses it. Summed float by float (the port's old order:
        // 0.33747578, 0.77872252, 0.98992884, then 1.0009999275) it fell inside and was accepted.
        float w = BitConverter.Int32BitsToSingle(0x3DD77D48), x = BitConverter.Int32BitsToSingle(0x3EEB4D02);
        float y = BitConverter.Int32BitsToSingle(unchecked((int)0xBF2A0D36)), z = BitConverter.Int32BitsToSingle(unchecked((int)0xBF14B79C));
        Assert.Throws<ArgumentException>(() => new AFrame(Vector3.Zero, new Quaternion(x, y, z, w)));
    }
}
