using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>Zero and denormal quaternions and vectors, and trigonometric arguments at ±1, never turn a frame into NaN.</summary>
public class DegenerateInputsNeverGiveNaNTests
{
    private static void AssertNoNaN(in Frame f)
    {
        Assert.False(float.IsNaN(f.Qw) || float.IsNaN(f.Qx) || float.IsNaN(f.Qy) || float.IsNaN(f.Qz));
        Assert.False(float.IsNaN(f.M11) || float.IsNaN(f.M22) || float.IsNaN(f.M33));
        Assert.True(f.IsValid());
    }

    [Theory]
    [InlineData(0f, 0f, 0f, 0f)]
    [InlineData(1e-45f, 0f, 0f, 0f)]          // smallest denormal
    [InlineData(1e-40f, 1e-40f, 0f, 0f)]      // denormals
    [InlineData(float.Epsilon, float.Epsilon, float.Epsilon, float.Epsilon)]
    [InlineData(float.MaxValue, 0f, 0f, 0f)]  // the double sum of squares does not overflow
    public void SetRotate_ZeroDenormalOrHuge_NeverLeavesNaN(float w, float x, float y, float z)
    {
        Frame f = Frame.FromHeading(Vector3.Zero, 77f);
        f.SetRotate(w, x, y, z);
        AssertNoNaN(f);
    }

    [Fact]
    public void SetRotate_DenormalQuaternion_NormalisesInDouble()
    {
        // (1e-40, 0, 0, 0): the sum of squares 1e-80 is a normal double, 1/sqrt = 1e40, so qw becomes exactly 1.
        Frame f = Frame.FromHeading(Vector3.Zero, 77f);
        Assert.True(f.SetRotate(1e-40f, 0f, 0f, 0f));
        Assert.Equal(1f, f.Qw);
    }

    [Theory]
    [InlineData(0f, 0f, 0f)]
    [InlineData(1e-45f, 0f, 0f)]
    [InlineData(1e-38f, 1e-38f, 1e-38f)]
    [InlineData(0.00019f, 0f, 0f)] // just below EPSILON
    public void NormalizeCheckSmall_TinyVector_ReportsSmallAndLeavesIt(float x, float y, float z)
    {
        var v = new Vector3(x, y, z);
        Vector3 before = v;
        Assert.True(VectorMath.NormalizeCheckSmall(ref v));
        Assert.Equal(before, v);
    }

    [Fact]
    public void NormalizeCheckSmall_AtEpsilon_Normalises()
    {
        // len = 0.0002f widened = EPSILON exactly -> "len >= EPSILON" -> normalised to (1, 0, 0).
        var v = new Vector3(PhysicsGlobals.Epsilon, 0f, 0f);
        Assert.False(VectorMath.NormalizeCheckSmall(ref v));
        Assert.Equal(new Vector3(1f, 0f, 0f), v);
    }

    [Theory]
    [InlineData(0f, 0f, 1f)]            // straight up: asin(1)
    [InlineData(0f, 0f, -1f)]           // straight down: asin(-1)
    [InlineData(1e-7f, 0f, 1f)]         // normalised z rounds to 1
    [InlineData(0f, -1e-7f, -1f)]
    public void SetVectorHeading_VerticalVectors_NeverNaN(float x, float y, float z)
    {
        Frame f = Frame.FromHeading(Vector3.Zero, 12f);
        f.SetVectorHeading(new Vector3(x, y, z));
        AssertNoNaN(f);
    }

    [Fact]
    public void InterpolateRotation_IdenticalAndOppositeSign_NeverNaN()
    {
        // cos(omega) = 1 (or rounds just past 1): acos would be NaN, but the 1 - cos <= EPSILON branch takes linear weights.
        Frame a = Frame.FromHeading(Vector3.Zero, 33f);
        Frame neg = a;
        neg.SetRotate(-a.Qw, -a.Qx, -a.Qy, -a.Qz);
        for (float t = 0f; t <= 1f; t += 0.125f)
        {
            Frame r = Frame.Identity;
            r.InterpolateRotation(a, a, t);
            AssertNoNaN(r);
            Assert.True(r.IsEqual(a));
            r.InterpolateRotation(a, neg, t);
            AssertNoNaN(r);
        }
    }

    [Fact]
    public void GRotate_HugeAngle_StaysValid()
    {
        Frame f = Frame.Identity;
        f.GRotate(new Vector3(1e6f, -3e5f, 7e4f));
        AssertNoNaN(f);
    }

    [Theory]
    [InlineData(0f)]
    [InlineData(359.9999f)]
    [InlineData(360f)]
    [InlineData(-0.0001f)]
    [InlineData(719.9999f)]
    public void Headings_NearZeroAnd360_ReadBackOnTheCircle(float heading)
    {
        // Angular difference on the circle within 1e-3 degrees (float heading resolution near 360 is ~3e-5).
        Frame f = Frame.Identity;
        f.SetHeading(heading);
        double back = f.Heading;
        Assert.InRange(back, 0.0, 360.0);
        double diff = Math.Abs(((back - heading) % 360.0 + 540.0) % 360.0 - 180.0);
        Assert.True(diff < 1e-3, $"{heading} -> {back}");
    }

    [Fact]
    public void QAndMinusQ_AreTheSameRotation()
    {
        Frame a = Frame.FromHeading(new Vector3(1, 2, 3), 140f);
        Frame b = a;
        b.SetRotate(-a.Qw, -a.Qx, -a.Qy, -a.Qz);
        var p = new Vector3(0.3f, -0.7f, 0.2f);
        Assert.True(Vector3.Distance(a.LocalToGlobal(p), b.LocalToGlobal(p)) < 1e-6f);
        Assert.Equal(a.Heading, b.Heading, 5);
    }
}
