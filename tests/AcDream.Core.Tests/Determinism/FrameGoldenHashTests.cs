using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Determinism;

/// <summary>
/// Golden hashes of seeded Frame / Position sequences. The expected values are determinism pins: they were recorded once and
/// must never change — not under another JIT mode (.ci/run re-runs the Determinism category with tiering, PGO, ReadyToRun and
/// hardware intrinsics switched off), not run after run. Their physical correctness is covered by the Retail and Stability tests;
/// a change of a golden value means the arithmetic changed and must be justified as a retail-parity fix.
/// </summary>
[Trait("Category", "Determinism")]
public class FrameGoldenHashTests
{
    internal static ulong RunFrameSequence(int steps)
    {
        var rng = new Random(20261122);
        var pos = new Position(0xA9B40001u, Frame.FromHeading(new Vector3(96f, 96f, 10f), 0f));
        Frame body = Frame.FromHeading(Vector3.Zero, 45f);
        var h = new StateHasher();
        for (int i = 0; i < steps; i++)
        {
            var delta = new Frame(new Vector3(((float)rng.NextDouble() - 0.5f) * 0.4f, (float)rng.NextDouble() * 0.5f, 0f), Quaternion.Identity);
            delta.GRotate(new Vector3(0f, 0f, ((float)rng.NextDouble() - 0.5f) * 0.2f));
            Frame next = pos.Frame;
            next.Combine(pos.Frame, delta);
            pos.Frame = next;
            pos.TryAdjustToOutside();
            body.GRotate(new Vector3((float)rng.NextDouble() * 0.01f, 0.02f, -0.03f));
            if ((i & 63) == 0)
            {
                body.SetHeading((float)(rng.NextDouble() * 720.0 - 360.0));
                h.Add(body.Heading);
                h.Add(body.LocalToGlobal(new Vector3(1f, 2f, 3f)));
            }

            h.Add(pos);
        }

        h.Add(body);
        return h.Value;
    }

    [Fact]
    public void FrameSequence_SameInputs_SameHashEveryRun()
    {
        Assert.Equal(RunFrameSequence(20_000), RunFrameSequence(20_000));
    }

    [Fact]
    public void FrameSequence_MatchesGoldenHash()
    {
        Assert.Equal(GoldenHashes.FrameSequence20000, RunFrameSequence(20_000));
    }
}
