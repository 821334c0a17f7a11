using System;
using System.Numerics;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Determinism;

/// <summary>
/// The sequence update's root-motion shortcut (#38): an update starts from an identity offset frame, so the first frame it
/// crosses combines <see cref="Frame.Identity"/> with that frame's root motion; <see cref="AnimClip"/> works that combine
/// out once per frame and the node copies it. Checked against the Frame-AFrame combine as it stood
/// (<see cref="ReferenceFrame.CombineAFrame"/>), every field bit for bit, over random root-motion frames with signed zeros,
/// tiny, large and non-unit components; a frame that is the identity but for one bit (a -0) takes the general combine.
/// </summary>
[Trait("Category", "Determinism")]
public class RootMotionFromIdentityTests
{
    private const int Cases = 60_000;

    private static float Any(Random rng) => rng.Next(16) switch
    {
        0 => 0f,
        1 => -0f,
        2 => (float)(rng.NextDouble() * 2e-4 - 1e-4),
        3 => (float)(rng.NextDouble() * 2e4 - 1e4),
        4 => 1f,
        _ => (float)(rng.NextDouble() * 4.0 - 2.0),
    };

    private static AFrame AnyStep(Random rng) =>
        AFrame.FromChecked(new Vector3(Any(rng), Any(rng), Any(rng)), Any(rng), Any(rng), Any(rng), Any(rng));

    private static AnimSequenceNode Playing(AnimClip clip)
    {
        var library = new AnimationLibrary();
        library.Add(clip);
        var node = new AnimSequenceNode();
        node.Init(new AnimData(clip.Id, 0, -1, 30f), library);
        return node;
    }

    private static AnimClip Clip(AFrame[] pos)
    {
        var parts = new AnimFrame[pos.Length];
        for (int i = 0; i < parts.Length; i++)
        {
            parts[i] = new AnimFrame([AFrame.Identity], null, 0);
        }

        return new AnimClip(0x03000010, 1, pos, parts, hasHooks: false);
    }

    [Fact]
    public void FromIdentity_MatchesTheCombineOnEveryBit()
    {
        var rng = new Random(3803);
        var pos = new AFrame[Cases];
        for (int i = 0; i < pos.Length; i++)
        {
            pos[i] = AnyStep(rng);
        }

        AnimSequenceNode node = Playing(Clip(pos));
        for (int i = 0; i < pos.Length; i++)
        {
            Frame f = Frame.Identity;
            node.CombinePosFrame(i, ref f);
            ReferenceFrame reference = ReferenceFrame.From(Frame.Identity);
            reference.CombineAFrame(pos[i]);
            Assert.True(reference.SameBits(f), $"root motion from identity, frame {i}");
        }
    }

    [Fact]
    public void AFrameOneBitFromTheIdentity_TakesTheGeneralCombine()
    {
        // The identity but for its origin's x, the smallest denormal (one bit): the general combine runs. Worked out: the
        // origin is (0·1.5 + 1·0 + 0·0.25 + 1.4e-45, 0·1.5 + 0·0 + 1·0.25 + 0, ...) = (1.4e-45, 0.25, 1.5), where the shortcut
        // would give x = 0; the quaternion (0.8, 0, 0, 0.6) has the float norm² 1.0000000477 and renormalises to 0.79999999
        // and 0.60000001, which round back to 0.8f and 0.6f.
        var pos = new[] { AFrame.FromChecked(new Vector3(0f, 0.25f, 1.5f), 0.8f, 0f, 0f, 0.6f) };
        AnimSequenceNode node = Playing(Clip(pos));
        Frame f = Frame.Identity;
        f.Origin = new Vector3(float.Epsilon, 0f, 0f);
        Assert.False(f.HasIdentityBits());
        ReferenceFrame reference = ReferenceFrame.From(f);
        node.CombinePosFrame(0, ref f);
        reference.CombineAFrame(pos[0]);
        Assert.True(reference.SameBits(f));
        Assert.Equal(new Vector3(float.Epsilon, 0.25f, 1.5f), f.Origin);
        Assert.Equal(0.8f, f.Rotation.W);
        Assert.Equal(0.6f, f.Rotation.Z);
    }

    [Fact]
    public void HasIdentityBits_IsTheIdentityAlone()
    {
        Assert.True(Frame.Identity.HasIdentityBits());
        Assert.False(default(Frame).HasIdentityBits());
        Frame moved = Frame.Identity;
        moved.Origin = new Vector3(0f, 0f, 1e-45f);
        Assert.False(moved.HasIdentityBits());
        Frame turned = Frame.FromHeading(Vector3.Zero, 90f);
        Assert.False(turned.HasIdentityBits());
        Frame heading0 = Frame.FromHeading(Vector3.Zero, 0f);
        Assert.Equal(Frame.Identity.Rotation, heading0.Rotation);
    }

    [Fact]
    public void ARootMotionFrameThatIsNotFinite_LeavesTheShortcutOff()
    {
        var pos = new[]
        {
            AFrame.FromChecked(new Vector3(0f, 0.1f, 0f), 1f, 0f, 0f, 0f),
            AFrame.FromChecked(new Vector3(0f, float.NaN, 0f), 1f, 0f, 0f, 0f),
        };
        AnimClip clip = Clip(pos);
        Assert.Null(clip.PosFromIdentityArray);
        AnimSequenceNode node = Playing(clip);
        Frame f = Frame.Identity;
        node.CombinePosFrame(0, ref f);
        Assert.Equal(new Vector3(0f, 0.1f, 0f), f.Origin);
        Assert.Equal(Frame.Identity.Rotation, f.Rotation);
    }

    [Fact]
    public void AClipWithoutRootMotion_HasNoShortcutAndCombinesNothing()
    {
        var clip = new AnimClip(0x03000011, 1, null, [new AnimFrame([AFrame.Identity], null, 0)], hasHooks: false);
        Assert.Null(clip.PosFromIdentityArray);
        AnimSequenceNode node = Playing(clip);
        Frame f = Frame.Identity;
        node.CombinePosFrame(0, ref f);
        Assert.True(f.HasIdentityBits());
    }
}
