using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>The plain-float32 fidelity switch computes the same transforms as the retail double-intermediate path, to float accuracy.</summary>
public class FrameFloat32Tests
{
    [Fact]
    public void CombineFloat32_NinetyDegreeYaw_MatchesRetail()
    {
        // Facing east at (10, 20, 0), one metre forward -> (11, 20, 0) in both modes.
        Frame f1 = Frame.FromHeading(new Vector3(10f, 20f, 0f), 90f);
        var f2 = new Frame(new Vector3(0f, 1f, 0f), Quaternion.Identity);
        Frame r = f1;
        r.CombineFloat32(f1, f2);
        Assert.Equal(11f, r.Origin.X, 5);
        Assert.Equal(20f, r.Origin.Y, 5);
        Assert.Equal(90.0, r.Heading, 4);
    }

    [Fact]
    public void Float32AndRetail_AgreeToFloatAccuracy_ButAreDistinctComputations()
    {
        var rng = new Random(99);
        int bitDifferent = 0;
        for (int i = 0; i < 2000; i++)
        {
            var q = Quaternion.Normalize(new Quaternion((float)rng.NextDouble() - 0.5f, (float)rng.NextDouble() - 0.5f,
                (float)rng.NextDouble() - 0.5f, (float)rng.NextDouble() - 0.5f));
            var a = new Frame(new Vector3((float)rng.NextDouble() * 192f, (float)rng.NextDouble() * 192f, 50f), q);
            var b = new Frame(new Vector3(0.3f, 0.2f, 0.1f), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, (float)rng.NextDouble()));
            Frame retail = a;
            retail.Combine(a, b);
            Frame f32 = a;
            f32.CombineFloat32(a, b);
            // Origins up to ~250 m: a float32 sum of three products differs from the double sum by at most a few spacings
            // (3e-5 m each) -> bound 1e-4 m. Quaternions: bound 1e-6.
            Assert.True(Vector3.Distance(retail.Origin, f32.Origin) < 1e-4f);
            Assert.True(Math.Abs(retail.Qw - f32.Qw) < 1e-6f && Math.Abs(retail.Qz - f32.Qz) < 1e-6f);
            if (!retail.Equals(f32))
            {
                bitDifferent++;
            }

            Frame g1 = a;
            g1.GRotate(new Vector3(0.01f, 0.02f, 0.03f));
            Frame g2 = a;
            g2.GRotateFloat32(new Vector3(0.01f, 0.02f, 0.03f));
            Assert.True(Math.Abs(g1.Qw - g2.Qw) < 1e-6f && Math.Abs(g1.Qx - g2.Qx) < 1e-6f);
        }

        // Double intermediates round once, float32 rounds at every step, so some results must differ in their last bits.
        Assert.True(bitDifferent > 0);
    }

    [Fact]
    public void SetRotateFloat32_RestoresOldQuaternionOnInvalidInput()
    {
        Frame f = Frame.FromHeading(Vector3.Zero, 30f);
        Frame before = f;
        Assert.False(f.SetRotateFloat32(0f, 0f, 0f, 0f));
        Assert.Equal(before, f);
    }
}
