using System;
using System.Numerics;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Determinism;

/// <summary>
/// The sequence update's frame steps as restructured for #38 (CSequence::apply_physics with the origin read and written by
/// component and omega·s handed on as components into the cached rotate; CSequence's Frame-AFrame combine with the origin
/// stored by component and set_rotate inlined) against the code as it stood, kept in <see cref="ReferenceFrame"/>: every
/// field bit for bit over long random sequences, including non-unit, zero and NaN quaternions and NaN origins.
/// </summary>
[Trait("Category", "Determinism")]
public class SequenceRestructuringEquivalenceTests
{
    private const int Cases = 60_000;

    private static float Any(Random rng) => rng.Next(16) switch
    {
        0 => 0f,
        1 => -0f,
        2 => (float)(rng.NextDouble() * 2e-4 - 1e-4),
        3 => (float)(rng.NextDouble() * 2e4 - 1e4),
        _ => (float)(rng.NextDouble() * 4.0 - 2.0),
    };

    private static Vector3 AnyVector(Random rng) => new(Any(rng), Any(rng), Any(rng));

    private static Frame AnyFrame(Random rng)
    {
        Frame f = Frame.Identity;
        f.Origin = AnyVector(rng);
        switch (rng.Next(20))
        {
            case 0: f.SetQuaternionRaw(0f, 0f, 0f, 0f); break;
            case 1: f.SetQuaternionRaw(float.NaN, Any(rng), Any(rng), Any(rng)); break;
            default: f.SetRotate(Any(rng), Any(rng), Any(rng), Any(rng)); break;
        }

        if (rng.Next(50) == 0)
        {
            f.Origin = new Vector3(f.Origin.X, float.NaN, f.Origin.Z);
        }

        return f;
    }

    [Fact]
    public void ApplyPhysics_MatchesTheReference_WhetherTheRotationCacheHitsOrNot()
    {
        // One sequence (one rotation cache) over chains of steps: the displacement repeats for a while (cache hits), then
        // the omega, velocity, quantum or frame change (misses), as a playing cycle does.
        var rng = new Random(3801);
        var sequence = new AnimSequence(null);
        Frame f = Frame.Identity;
        ReferenceFrame reference = ReferenceFrame.From(f);
        Vector3 v = Vector3.Zero, w = Vector3.Zero;
        double q = 1.0 / 30.0, sign = q;
        for (int i = 0; i < Cases; i++)
        {
            if (rng.Next(16) == 0)
            {
                v = AnyVector(rng);
                w = rng.Next(3) == 0 ? new Vector3(0f, 0f, Any(rng)) : AnyVector(rng);
                sequence.SetVelocity(v);
                sequence.SetOmega(w);
                q = rng.Next(4) == 0 ? rng.NextDouble() * 0.5 : 1.0 / 30.0;
                sign = rng.Next(4) == 0 ? -q : q;
            }

            if (rng.Next(32) == 0)
            {
                // Level frames keep a yaw omega's lifted displacement (the cache hits), others turn it (misses).
                f = rng.Next(2) == 0 ? Frame.FromHeading(AnyVector(rng), Any(rng) * 100f) : AnyFrame(rng);
                reference = ReferenceFrame.From(f);
            }

            sequence.ApplyPhysics(ref f, q, sign);
            reference.ApplyPhysics(q, sign, v, w);
            Assert.True(reference.SameBits(f), $"apply_physics case {i}");
        }
    }

    [Fact]
    public void FrameAFrameCombine_MatchesTheReference()
    {
        var rng = new Random(3802);
        for (int i = 0; i < Cases; i++)
        {
            Frame f = AnyFrame(rng);
            ReferenceFrame reference = ReferenceFrame.From(f);
            AFrame step = AFrame.FromChecked(AnyVector(rng), Any(rng), Any(rng), Any(rng), Any(rng));
            AFrame.Combine(ref f, step);
            reference.CombineAFrame(step);
            Assert.True(reference.SameBits(f), $"combine (AFrame) case {i}");
        }
    }
}
