using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Determinism;

/// <summary>
/// The restructured Frame arithmetic (fused set_rotate/cache, inlined products, the precomputed grotate rotation, the level
/// set_heading path) against the pre-restructuring code kept in <see cref="ReferenceFrame"/>: every field bit for bit over
/// long random sequences, including non-unit, zero and NaN quaternions, NaN origins, tiny and huge angles. In the
/// Determinism category so CI runs it under every JIT mode (tiering, PGO, ReadyToRun, hardware intrinsics off).
/// </summary>
[Trait("Category", "Determinism")]
public class FrameRestructuringEquivalenceTests
{
    private const int Cases = 120_000;

    private static float Any(Random rng)
    {
        switch (rng.Next(16))
        {
            case 0: return 0f;
            case 1: return -0f;
            case 2: return (float)(rng.NextDouble() * 2e-4 - 1e-4);
            case 3: return (float)(rng.NextDouble() * 2e4 - 1e4);
            default: return (float)(rng.NextDouble() * 4.0 - 2.0);
        }
    }

    private static Vector3 AnyVector(Random rng) => new(Any(rng), Any(rng), Any(rng));

    private static Frame AnyFrame(Random rng)
    {
        Frame f = Frame.Identity;
        f.Origin = AnyVector(rng);
        int kind = rng.Next(20);
        if (kind == 0)
        {
            f.SetQuaternionRaw(0f, 0f, 0f, 0f); // set_frame's recovery leaves a zero quaternion with a stale cache
        }
        else if (kind == 1)
        {
            f.SetQuaternionRaw(float.NaN, Any(rng), Any(rng), Any(rng));
        }
        else if (kind == 2)
        {
            f.SetQuaternionRaw(Any(rng), Any(rng), Any(rng), Any(rng)); // not normalised, cache stale
        }
        else
        {
            f.SetRotate(Any(rng), Any(rng), Any(rng), Any(rng));
        }

        if (rng.Next(50) == 0)
        {
            f.Origin = new Vector3(float.NaN, f.Origin.Y, f.Origin.Z);
        }

        return f;
    }

    [Fact]
    public void Combine_MatchesTheReference_IncludingSelfAliasing()
    {
        var rng = new Random(1801);
        for (int i = 0; i < Cases; i++)
        {
            Frame a = AnyFrame(rng), b = AnyFrame(rng);
            ReferenceFrame ra = ReferenceFrame.From(a), rb = ReferenceFrame.From(b);
            Frame r = AnyFrame(rng);
            ReferenceFrame rr = ReferenceFrame.From(r);
            r.Combine(a, b);
            rr.Combine(ra, rb);
            Assert.True(rr.SameBits(r), $"combine case {i}");

            a.Combine(a, b); // this == f1
            ra.Combine(ra, rb);
            Assert.True(ra.SameBits(a), $"combine (this is f1) case {i}");
            b.Combine(a, b); // this == f2
            rb.Combine(ra, rb);
            Assert.True(rb.SameBits(b), $"combine (this is f2) case {i}");
        }
    }

    [Fact]
    public void SetRotateAndIsValid_MatchTheReference()
    {
        var rng = new Random(1802);
        for (int i = 0; i < Cases; i++)
        {
            Frame f = AnyFrame(rng);
            ReferenceFrame rf = ReferenceFrame.From(f);
            Assert.Equal(rf.IsValid(), f.IsValid());
            float w = Any(rng), x = Any(rng), y = Any(rng), z = Any(rng);
            if (rng.Next(30) == 0)
            {
                x = float.PositiveInfinity;
            }

            Assert.Equal(rf.SetRotate(w, x, y, z), f.SetRotate(w, x, y, z));
            Assert.True(rf.SameBits(f), $"set_rotate case {i}");
            Assert.Equal(rf.IsValid(), f.IsValid());
        }
    }

    [Fact]
    public void GRotateAndRotate_MatchTheReference_OverLongChains()
    {
        var rng = new Random(1803);
        Frame f = Frame.Identity;
        ReferenceFrame rf = ReferenceFrame.From(f);
        for (int i = 0; i < Cases; i++)
        {
            if (i % 1000 == 0)
            {
                f = AnyFrame(rng);
                rf = ReferenceFrame.From(f);
            }

            Vector3 w = rng.Next(4) switch
            {
                0 => new Vector3(0f, 0f, Any(rng)), // pure yaw
                1 => AnyVector(rng) * 1e-4f,        // mostly below EPSILON²: skipped
                _ => AnyVector(rng),
            };
            if ((i & 1) == 0)
            {
                f.GRotate(w);
                rf.GRotate(w);
            }
            else
            {
                f.Rotate(w);
                rf.Rotate(w);
            }

            Assert.True(rf.SameBits(f), $"grotate/rotate case {i}");
        }
    }

    [Fact]
    public void GRotateWithAPrecomputedRotation_MatchesGRotate()
    {
        var rng = new Random(1804);
        for (int i = 0; i < Cases; i++)
        {
            Frame f = AnyFrame(rng);
            Frame g = f;
            Vector3 w = AnyVector(rng);
            f.GRotate(w);
            if (AxisAngle.TryCreate(w, out AxisAngle r))
            {
                g.GRotate(r);
            }

            Assert.True(ReferenceFrame.From(f).SameBits(g), $"precomputed grotate case {i}");
        }
    }

    [Fact]
    public void RotateWithACachedRotation_MatchesRotate_WhetherTheCacheHitsOrNot()
    {
        // The animation sequence's omega step (CSequence::apply_physics) keeps grotate's rotation in an AxisAngleCache, keyed
        // by the displacement lifted to global axes. Frames and displacements come from small pools so that the lifted
        // displacement repeats (a hit) about half the time, including a tiny displacement that does not rotate.
        var rng = new Random(1806);
        var frames = new Frame[4];
        for (int k = 0; k < frames.Length; k++)
        {
            frames[k] = k < 2 ? Frame.FromHeading(AnyVector(rng), k * 90f) : AnyFrame(rng);
        }

        var ws = new[] { AnyVector(rng), new Vector3(0f, 0f, 0.5f / 30f), new Vector3(0f, 0f, 1e-5f) };
        var cache = new AxisAngleCache();
        int repeats = 0, last = -1;
        for (int i = 0; i < Cases; i++)
        {
            int fi = rng.Next(8) == 0 ? rng.Next(frames.Length) : (last < 0 ? 0 : last / 3);
            int wi = rng.Next(8) == 0 ? rng.Next(ws.Length) : (last < 0 ? 0 : last % 3);
            repeats += fi * 3 + wi == last ? 1 : 0;
            last = fi * 3 + wi;
            Frame f = frames[fi];
            Frame g = f;
            f.Rotate(ws[wi]);
            g.Rotate(ws[wi].X, ws[wi].Y, ws[wi].Z, ref cache);
            Assert.True(ReferenceFrame.From(f).SameBits(g), $"cached rotate case {i}");
        }

        Assert.True(repeats > Cases / 2, "the cases repeat the displacement");
    }

    [Fact]
    public void SetHeadingAndSetVectorHeading_MatchTheReference()
    {
        var rng = new Random(1805);
        for (int i = 0; i < Cases; i++)
        {
            Frame f = rng.Next(3) == 0 ? Frame.FromHeading(AnyVector(rng), Any(rng) * 200f) : AnyFrame(rng);
            ReferenceFrame rf = ReferenceFrame.From(f);
            if ((i & 1) == 0)
            {
                float h = rng.Next(8) == 0 ? rng.Next(-4, 5) * 90f : (float)(rng.NextDouble() * 1440.0 - 720.0);
                f.SetHeading(h);
                rf.SetHeading(h);
            }
            else
            {
                Vector3 v = rng.Next(3) == 0 ? new Vector3(Any(rng), Any(rng), 0f) : AnyVector(rng);
                f.SetVectorHeading(v);
                rf.SetVectorHeading(v);
            }

            Assert.True(rf.SameBits(f), $"set_heading case {i}");
        }
    }

    [Fact]
    public void LocalToGlobalAndGlobalToLocal_MatchTheReference_InlinedIntoOneChain()
    {
        // #38 inlines localtoglobal and globaltolocal into their callers; a chain of round trips (each point the result of
        // the one before, as the benchmark's) and single conversions of any point, on any frame, give the same bits.
        var rng = new Random(1807);
        for (int i = 0; i < Cases; i++)
        {
            Frame f = AnyFrame(rng);
            ReferenceFrame rf = ReferenceFrame.From(f);
            Vector3 p = AnyVector(rng);
            Vector3 q = p;
            for (int k = 0; k < 4; k++)
            {
                p = f.GlobalToLocal(f.LocalToGlobal(p));
                q = rf.GlobalToLocal(rf.LocalToGlobal(q));
                AssertSameBits(q, p, $"round trip case {i}, step {k}");
            }

            Vector3 v = AnyVector(rng);
            AssertSameBits(rf.LocalToGlobal(v), f.LocalToGlobal(v), $"localtoglobal case {i}");
            AssertSameBits(rf.GlobalToLocal(v), f.GlobalToLocal(v), $"globaltolocal case {i}");
        }
    }

    private static void AssertSameBits(Vector3 expected, Vector3 actual, string what)
    {
        Assert.True(
            BitConverter.SingleToInt32Bits(expected.X) == BitConverter.SingleToInt32Bits(actual.X)
            && BitConverter.SingleToInt32Bits(expected.Y) == BitConverter.SingleToInt32Bits(actual.Y)
            && BitConverter.SingleToInt32Bits(expected.Z) == BitConverter.SingleToInt32Bits(actual.Z),
            $"{what}: expected {expected}, got {actual}");
    }
}
