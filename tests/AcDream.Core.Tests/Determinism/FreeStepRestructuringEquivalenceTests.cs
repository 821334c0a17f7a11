using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Determinism;

/// <summary>
/// The free step's shortcuts against the code they replace, bit for bit over long random inputs: the built-in part array's
/// idle sequence against the full <c>apply_physics</c> arithmetic (<see cref="ReferenceFrame.SequenceUpdate"/>), the per-object
/// rotation of a repeated omega·dt against grotate recomputed each time, and the step's frame store against
/// <see cref="PhysicsObj.SetFrame"/>.
/// </summary>
[Trait("Category", "Determinism")]
public class FreeStepRestructuringEquivalenceTests
{
    private const int Cases = 120_000;

    private static float Any(Random rng) => rng.Next(12) switch
    {
        0 => 0f,
        1 => -0f,
        2 => (float)(rng.NextDouble() * 2e-4 - 1e-4),
        3 => (float)(rng.NextDouble() * 2e3 - 1e3),
        _ => (float)(rng.NextDouble() * 4.0 - 2.0),
    };

    private static Vector3 AnyVector(Random rng) => new(Any(rng), Any(rng), Any(rng));

    private static Frame AnyFrame(Random rng)
    {
        Frame f = Frame.Identity;
        f.Origin = AnyVector(rng);
        switch (rng.Next(12))
        {
            case 0:
                f.SetQuaternionRaw(0f, 0f, 0f, 0f);
                break;
            case 1:
                f.SetQuaternionRaw(float.NaN, Any(rng), Any(rng), Any(rng));
                break;
            case 2:
                f.SetQuaternionRaw(Any(rng), Any(rng), Any(rng), Any(rng));
                break;
            case 3:
                break; // the identity, as the step's offset starts
            default:
                f.SetRotate(Any(rng), Any(rng), Any(rng), Any(rng));
                break;
        }

        return f;
    }

    [Fact]
    public void IdleSequenceShortcut_MatchesTheFullSequenceArithmetic()
    {
        var rng = new Random(1807);
        var parts = new SimplePartArray();
        for (int i = 0; i < Cases; i++)
        {
            // Mostly idle sequences (the shortcut), with -0 components, and some moving ones (the full path).
            Vector3 v = rng.Next(4) switch
            {
                0 => AnyVector(rng),
                1 => new Vector3(rng.Next(2) == 0 ? 0f : -0f, rng.Next(2) == 0 ? 0f : -0f, rng.Next(2) == 0 ? 0f : -0f),
                _ => Vector3.Zero,
            };
            Vector3 w = rng.Next(4) == 0 ? AnyVector(rng) : new Vector3(rng.Next(2) == 0 ? 0f : -0f, 0f, -0f);
            // The sequence velocity's domain is at most 50 m/s (InputLimits.MaxSequenceSpeed): a larger random vector is
            // scaled into it by a power of two (exact), keeping its bits' variety.
            while ((double)v.X * v.X + (double)v.Y * v.Y + (double)v.Z * v.Z > 2500.0)
            {
                v *= 0.0625f;
            }

            parts.SequenceVelocity = v;
            parts.SequenceOmega = w;
            float q = rng.Next(10) switch
            {
                0 => 0f,
                1 => -0f,
                2 => -(float)rng.NextDouble(),
                3 => float.PositiveInfinity,
                _ => (float)(rng.NextDouble() * 0.25),
            };
            Frame offset = AnyFrame(rng);
            if (rng.Next(8) == 0)
            {
                offset.Origin = new Vector3(-0f, offset.Origin.Y, rng.Next(2) == 0 ? -0f : float.NaN);
            }

            ReferenceFrame reference = ReferenceFrame.From(offset);
            parts.Update(q, ref offset);
            reference.SequenceUpdate(q, v, w);
            Assert.True(reference.SameBits(offset), $"sequence case {i}: v {v} w {w} q {q}");
        }
    }

    [Fact]
    public void RepeatedRotation_FromTheObjectsCache_MatchesGRotateRecomputed()
    {
        var rng = new Random(1808);
        var world = new PhysicsWorld();
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 50f));
        Frame f = Frame.Identity;
        ReferenceFrame reference = ReferenceFrame.From(f);
        Vector3 w = new(0f, 0f, 0.5f / 30f);
        for (int i = 0; i < Cases; i++)
        {
            if (rng.Next(20) == 0)
            {
                // A new displacement now and then (sign of zero included); otherwise it repeats, as with constant omega.
                w = rng.Next(3) switch
                {
                    0 => new Vector3(0f, rng.Next(2) == 0 ? 0f : -0f, Any(rng)),
                    1 => AnyVector(rng),
                    _ => new Vector3(-w.X, w.Y, w.Z),
                };
            }

            if ((double)w.X * w.X + (double)w.Y * w.Y + (double)w.Z * w.Z < (double)PhysicsGlobals.Epsilon * PhysicsGlobals.Epsilon)
            {
                continue; // the step does not ask for a rotation below EPSILON²
            }

            f.GRotate(obj.StepRotation(w));
            reference.GRotate(w);
            Assert.True(reference.SameBits(f), $"rotation case {i}: w {w}");
            if (rng.Next(500) == 0)
            {
                f = AnyFrame(rng);
                reference = ReferenceFrame.From(f);
            }
        }
    }

    [Fact]
    public void StepFrameStore_MatchesSetFrame()
    {
        var rng = new Random(1809);
        var world = new PhysicsWorld();
        PhysicsObj a = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 50f));
        PhysicsObj b = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 50f));
        var partsA = (SimplePartArray)a.PartArray!;
        var partsB = (SimplePartArray)b.PartArray!;
        for (int i = 0; i < Cases; i++)
        {
            Frame f = AnyFrame(rng);
            if (rng.Next(40) == 0)
            {
                f.Origin = new Vector3(float.NaN, 1f, 2f);
            }
            else if (rng.Next(40) == 0)
            {
                f.Origin = new Vector3(1f, float.PositiveInfinity, 2f);
            }

            Frame g = f;
            Exception? eb = Record.Exception(() => b.StoreStepFrame(ref g));
            if (!float.IsFinite(f.Origin.X) || !float.IsFinite(f.Origin.Y) || !float.IsFinite(f.Origin.Z))
            {
                // The step's store refuses a non-finite origin, as set_frame's callers never pass one (nothing changes).
                Assert.IsType<ArgumentException>(eb);
                continue;
            }

            // A finite origin: the engine's set_frame (its retail repair of a NaN quaternion kept; no public domain check).
            Assert.Null(eb);
            a.SetFrameInternal(f);
            Assert.True(ReferenceFrame.From(a.Position.Frame).SameBits(b.Position.Frame), $"store case {i}");
            Assert.True(ReferenceFrame.From(partsA.Frame).SameBits(partsB.Frame), $"part frame case {i}");
        }
    }
}
