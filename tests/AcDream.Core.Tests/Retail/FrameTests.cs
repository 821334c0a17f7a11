using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class FrameTests
{
    // sin 45 = cos 45 = 0.70710678...; as float 0.70710677f.
    private const float Half2 = 0.70710677f;

    [Fact]
    public void Identity_CachesIdentityMatrix()
    {
        Frame f = Frame.Identity;
        Assert.Equal(1f, f.Qw);
        Assert.Equal((1f, 0f, 0f), (f.M11, f.M12, f.M13));
        Assert.Equal((0f, 1f, 0f), (f.M21, f.M22, f.M23));
        Assert.Equal((0f, 0f, 1f), (f.M31, f.M32, f.M33));
    }

    [Fact]
    public void Cache_QuarterTurnAboutZ_MapsLocalYToWest()
    {
        // q = (cos 45, 0, 0, sin 45): +90 degrees about +Z (anticlockwise seen from above).
        // M21 = 2xy - 2wz = -2 * 0.5 = -1, M22 = 1 - 2x² - 2z² = 0: local +Y -> global -X (west).
        Frame f = Frame.Identity;
        Assert.True(f.SetRotate(Half2, 0f, 0f, Half2));
        Assert.Equal(-1f, f.M21, 6);
        Assert.Equal(0f, f.M22, 6);
        Assert.Equal(1f, f.M12, 6);  // local +X -> global +Y
        Assert.Equal(1f, f.M33, 6);
    }

    [Fact]
    public void Combine_NinetyDegreeYawWithOffset_MovesForwardAlongEast()
    {
        // f1 faces east (heading 90) at (10, 20, 0); f2 is one metre forward (+Y local) and half a metre up.
        // Local +Y of f1 is global +X, so the result is at (11, 20, 0.5) and still faces east.
        Frame f1 = Frame.FromHeading(new Vector3(10f, 20f, 0f), 90f);
        var f2 = new Frame(new Vector3(0f, 1f, 0.5f), Quaternion.Identity);
        Frame r = Frame.Combined(f1, f2);
        Assert.Equal(11f, r.Origin.X, 5);
        Assert.Equal(20f, r.Origin.Y, 5);
        Assert.Equal(0.5f, r.Origin.Z, 5);
        Assert.Equal(90.0, r.Heading, 4);
    }

    [Fact]
    public void Combine_TwoQuarterYaws_MakeAHalfTurn()
    {
        // 90 + 90 degrees of heading = 180 (facing south).
        Frame a = Frame.FromHeading(Vector3.Zero, 90f);
        Frame r = Frame.Combined(a, a);
        Assert.Equal(180.0, r.Heading, 4);
    }

    [Theory]
    [InlineData(0f, 0f, 1f)]     // north: forward (0, 1)
    [InlineData(90f, 1f, 0f)]    // east:  forward (1, 0)
    [InlineData(180f, 0f, -1f)]  // south: forward (0, -1)
    [InlineData(270f, -1f, 0f)]  // west:  forward (-1, 0)
    public void SetHeading_CompassPoints_PointForwardAxisAndReadBack(float heading, float fx, float fy)
    {
        Frame f = Frame.Identity;
        f.SetHeading(heading);
        Vector3 fwd = f.GetVectorHeading();
        Assert.Equal(fx, fwd.X, 6);
        Assert.Equal(fy, fwd.Y, 6);
        Assert.Equal(0f, fwd.Z, 6);
        double back = f.Heading;
        // 0 may come back as 0 or as 360 - tiny; compare on the circle: map the difference into (-180, 180].
        double diff = Math.Abs(((back - heading) % 360.0 + 540.0) % 360.0 - 180.0);
        Assert.True(diff < 1e-4, $"heading {heading} read back as {back}");
    }

    [Fact]
    public void GetHeading_IdentityFacesNorth_Zero()
    {
        // Retail ambiguity pinned: identity (w = 1) faces north, heading 0 (see HeadingMath.CompassFromAtan2).
        Assert.Equal(0.0, Frame.Identity.Heading);
    }

    [Theory]
    [InlineData(450f, 90.0)]     // wraps past 360
    [InlineData(-90f, 270.0)]    // negative heading
    [InlineData(720f, 0.0)]
    public void SetHeading_WrapsAround(float input, double expected)
    {
        Frame f = Frame.Identity;
        f.SetHeading(input);
        double h = f.Heading;
        double d = Math.Abs(h - expected);
        Assert.True(d < 1e-4 || Math.Abs(d - 360.0) < 1e-4, $"{input} -> {h}");
    }

    [Fact]
    public void HeadingMath_FourFifty_MinusAtan2()
    {
        // atan2(1, 0) = 90 degrees (north) -> 450 - 90 = 360 -> fmod -> 0.
        Assert.Equal(0.0, HeadingMath.CompassFromAtan2(Math.Atan2(1.0, 0.0)), 12);
        // atan2(0, 1) = 0 (east) -> 450 % 360 = 90.
        Assert.Equal(90.0, HeadingMath.CompassFromAtan2(0.0));
        // atan2(0, -1) = 180 (west) -> 450 - 180 = 270.
        Assert.Equal(270.0, HeadingMath.CompassFromAtan2(Math.PI), 12);
        // atan2(-1, 0) = -90 (south) -> 450 + 90 = 540 -> 180.
        Assert.Equal(180.0, HeadingMath.CompassFromAtan2(-Math.PI / 2), 12);
    }

    [Fact]
    public void SetRotate_NaN_KeepsOldQuaternionAndCache()
    {
        Frame f = Frame.FromHeading(Vector3.Zero, 90f);
        Frame before = f;
        Assert.False(f.SetRotate(float.NaN, 0f, 0f, 0f));
        Assert.Equal(before, f);
    }

    [Fact]
    public void SetRotate_Zero_KeepsOldQuaternion()
    {
        // 1 / sqrt(0) = +inf; 0 * inf = NaN -> invalid -> the old quaternion is restored.
        Frame f = Frame.FromHeading(Vector3.Zero, 45f);
        Frame before = f;
        Assert.False(f.SetRotate(0f, 0f, 0f, 0f));
        Assert.Equal(before, f);
    }

    [Fact]
    public void SetRotate_Infinity_KeepsOldQuaternion()
    {
        Frame f = Frame.Identity;
        Frame before = f;
        Assert.False(f.SetRotate(float.PositiveInfinity, 0f, 0f, 0f));
        Assert.Equal(before, f);
    }

    [Fact]
    public void SetRotate_Normalises()
    {
        // (2, 0, 0, 0) normalises to (1, 0, 0, 0); (3, 0, 0, 4) to (0.6, 0, 0, 0.8).
        Frame f = Frame.Identity;
        Assert.True(f.SetRotate(3f, 0f, 0f, 4f));
        Assert.Equal(0.6f, f.Qw, 6);
        Assert.Equal(0.8f, f.Qz, 6);
    }

    [Fact]
    public void IsValid_RejectsNaNOriginAndUnnormalisedQuaternion()
    {
        Frame f = Frame.Identity;
        Assert.True(f.IsValid());
        f.Origin = new Vector3(float.NaN, 0, 0);
        Assert.False(f.IsValid());
        Frame g = Frame.Identity;
        // |q|² = 1.0012 is outside 5 * EPSILON = 0.001.
        g.SetQuaternionRaw(1.0006f, 0f, 0f, 0f);
        Assert.False(g.IsValid());
        // |q|² = 1.0008 is inside.
        g.SetQuaternionRaw(1.0004f, 0f, 0f, 0f);
        Assert.True(g.IsValid());
    }

    [Fact]
    public void IsValidExceptForHeading_TrueOnlyForGoodOriginAndNaNQuaternion()
    {
        Frame f = Frame.Identity;
        Assert.False(f.IsValidExceptForHeading());
        f.SetQuaternionRaw(float.NaN, 0f, 0f, 0f);
        Assert.True(f.IsValidExceptForHeading());
        f.Origin = new Vector3(0f, float.NaN, 0f);
        Assert.False(f.IsValidExceptForHeading());
    }

    [Fact]
    public void LocalToGlobal_ThenGlobalToLocal_RoundTripsWithin1e6()
    {
        var rng = new Random(1234);
        for (int i = 0; i < 1000; i++)
        {
            var q = Quaternion.Normalize(new Quaternion(
                (float)rng.NextDouble() - 0.5f, (float)rng.NextDouble() - 0.5f,
                (float)rng.NextDouble() - 0.5f, (float)rng.NextDouble() - 0.5f));
            var f = new Frame(new Vector3((float)rng.NextDouble(), (float)rng.NextDouble(), (float)rng.NextDouble()), q);
            var p = new Vector3((float)rng.NextDouble() - 0.5f, (float)rng.NextDouble() - 0.5f, (float)rng.NextDouble() - 0.5f);
            Vector3 back = f.GlobalToLocal(f.LocalToGlobal(p));
            Assert.True(Vector3.Distance(p, back) < 1e-6f, $"case {i}: {p} -> {back}");
            Vector3 backVec = f.GlobalToLocalVec(f.LocalToGlobalVec(p));
            Assert.True(Vector3.Distance(p, backVec) < 1e-6f);
        }
    }

    [Fact]
    public void GlobalToLocal_OfEastFacingFrame_PutsEastPointAhead()
    {
        // Facing east at (100, 50, 0): the global point (103, 50, 0) is 3 m straight ahead (+Y local).
        Frame f = Frame.FromHeading(new Vector3(100f, 50f, 0f), 90f);
        Vector3 local = f.GlobalToLocal(new Vector3(103f, 50f, 0f));
        Assert.Equal(0f, local.X, 5);
        Assert.Equal(3f, local.Y, 5);
        Assert.Equal(0f, local.Z, 5);
    }

    [Fact]
    public void GlobalToLocal_ZRowKeepsTheZDifferenceInDouble()
    {
        // retail: Frame::globaltolocal (acclient.c:143717): "v6 = in->z - origin.z" stays on the x87 stack for the z row
        // (acclient.c:143733, "v8 = v6 * m_fl2gv[8] + ..."), while the x and y rows use its float spill v7.
        // A tilted frame (quaternion 0.9, 0.3, 0.2, 0.1 normalised) at (10, 20, 100.5), the point (11, 19, 0.3f):
        //   dx = 1, dy = -1; dz = 0.3f - 100.5 = -100.19999998807907 in double (as float: -100.19999694824219).
        //   The cached column Z is M31 = 0.44210529, M32 = -0.52631581, M33 = 0.72631574 (the floats Cache stores).
        //   z = dz*M33 + dx*M31 + dy*M32 = -72.77683681575876 + 0.44210529 + 0.52631581 = -71.80841571418863
        //     -> 0xC28F9DE9 (-71.80841827); with the float dz: -71.80841350630726 -> 0xC28F9DE8 (-71.80841064).
        //   The midpoint of the two floats is -71.80841445922852.
        var f = new Frame(new Vector3(10f, 20f, 100.5f), new Quaternion(0.3f, 0.2f, 0.1f, 0.9f));
        var p = new Vector3(11f, 19f, 0.3f);
        Vector3 local = f.GlobalToLocal(p);
        double dz = (double)p.Z - f.Origin.Z;
        double expected = dz * f.M33 + 1.0 * f.M31 + -1.0 * f.M32;
        Assert.Equal(-71.80841571418863, expected, 12);
        Assert.Equal(unchecked((int)0xC28F9DE9), BitConverter.SingleToInt32Bits(local.Z));

        // The x and y rows use the float dz (-100.19999694824219) exactly as before.
        float dzF = p.Z - f.Origin.Z;
        Assert.Equal((float)((double)dzF * f.M13 + 1.0 * f.M11 + -1.0 * f.M12), local.X);
        Assert.Equal((float)((double)dzF * f.M23 + 1.0 * f.M21 + -1.0 * f.M22), local.Y);
    }

    [Fact]
    public void CachedMatrix_StaysOrthonormal_AfterManyRotations()
    {
        Frame f = Frame.Identity;
        var w = new Vector3(0.013f, -0.021f, 0.034f);
        for (int i = 0; i < 10000; i++)
        {
            f.GRotate(w);
        }

        AssertOrthonormal(f, 1e-5);
        AssertCacheMatchesQuaternion(f, 1e-6);
    }

    [Fact]
    public void GRotate_BelowEpsilonSquared_IsSkipped()
    {
        // |w|² = (1e-4)² = 1e-8 < EPSILON² = 4e-8: no change at all.
        Frame f = Frame.FromHeading(Vector3.Zero, 30f);
        Frame before = f;
        f.GRotate(new Vector3(0f, 0f, 1e-4f));
        Assert.Equal(before, f);
    }

    [Fact]
    public void GRotate_AboutGlobalZ_ByMinusHalfPi_TurnsNorthToEast()
    {
        // A clockwise quarter turn (seen from above) is -pi/2 about +Z: heading 0 -> 90.
        Frame f = Frame.Identity;
        f.GRotate(new Vector3(0f, 0f, -MathF.PI / 2f));
        Assert.Equal(90.0, f.Heading, 4);
    }

    [Fact]
    public void Rotate_UsesLocalAxes()
    {
        // Pitch up 90 degrees about local X of a frame facing east: local X of an east-facing frame is global -Y (south),
        // so rotating +pi/2 about it turns forward (+X global) to +Z (up).
        Frame f = Frame.FromHeading(Vector3.Zero, 90f);
        f.Rotate(new Vector3(MathF.PI / 2f, 0f, 0f));
        Vector3 fwd = f.GetVectorHeading();
        Assert.Equal(0f, fwd.X, 5);
        Assert.Equal(0f, fwd.Y, 5);
        Assert.Equal(1f, fwd.Z, 5);
    }

    [Fact]
    public void SetToRelative_UndoesCombine()
    {
        Frame a = Frame.FromHeading(new Vector3(5f, 6f, 7f), 33f);
        var b = new Frame(new Vector3(1f, 2f, 3f), Quaternion.CreateFromAxisAngle(Vector3.Normalize(new Vector3(1, 2, 3)), 0.7f));
        Frame ab = Frame.Combined(a, b);
        Frame back = Frame.Identity;
        back.SetToRelative(ab, a);
        Assert.True(back.IsEqual(b), $"{back} vs {b}");
    }

    [Fact]
    public void SetToReference_UndoesCombineOnTheRight()
    {
        Frame a = Frame.FromHeading(new Vector3(5f, 6f, 7f), 33f);
        var b = new Frame(new Vector3(1f, 2f, 3f), Quaternion.CreateFromAxisAngle(Vector3.Normalize(new Vector3(1, 2, 3)), 0.7f));
        Frame ab = Frame.Combined(a, b);
        Frame back = Frame.Identity;
        back.SetToReference(ab, b);
        Assert.True(back.IsEqual(a), $"{back} vs {a}");
    }

    [Fact]
    public void IsEqual_ComparesOrientation_AndTreatsMinusQAsDifferent()
    {
        Frame a = Frame.FromHeading(Vector3.Zero, 10f);
        Frame b = Frame.FromHeading(Vector3.Zero, 20f);
        Assert.False(a.IsEqual(b));
        Frame c = a;
        c.SetRotate(-a.Qw, -a.Qx, -a.Qy, -a.Qz);
        Assert.False(a.IsEqual(c));
        Assert.True(a.IsEqual(a));
        // Origins within EPSILON (inclusive) are equal.
        Frame d = a;
        d.Origin = new Vector3(0.0001f, 0f, 0f);
        Assert.True(a.IsEqual(d));
    }

    [Fact]
    public void InterpolateRotation_HalfwayBetweenZeroAndNinety_IsFortyFive()
    {
        Frame from = Frame.FromHeading(Vector3.Zero, 0f);
        Frame to = Frame.FromHeading(Vector3.Zero, 90f);
        Frame r = Frame.Identity;
        r.InterpolateRotation(from, to, 0.5f);
        Assert.Equal(45.0, r.Heading, 3);
    }

    [Fact]
    public void InterpolateRotation_TakesShortArcForNegatedTarget()
    {
        // -q is the same rotation; interpolating towards it must not swing the long way round.
        Frame from = Frame.FromHeading(Vector3.Zero, 0f);
        Frame to = Frame.FromHeading(Vector3.Zero, 90f);
        Frame neg = to;
        neg.SetRotate(-to.Qw, -to.Qx, -to.Qy, -to.Qz);
        Frame r = Frame.Identity;
        r.InterpolateRotation(from, neg, 0.5f);
        Assert.Equal(45.0, r.Heading, 3);
    }

    [Fact]
    public void InterpolateOrigin_IsLinear()
    {
        var from = new Frame(new Vector3(0f, 0f, 0f), Quaternion.Identity);
        var to = new Frame(new Vector3(10f, -4f, 2f), Quaternion.Identity);
        Frame r = Frame.Identity;
        r.InterpolateOrigin(from, to, 0.25f);
        Assert.Equal(new Vector3(2.5f, -1f, 0.5f), r.Origin);
    }

    [Fact]
    public void SetVectorHeading_TooSmall_LeavesFrameUnchanged()
    {
        Frame f = Frame.FromHeading(Vector3.Zero, 123f);
        Frame before = f;
        f.SetVectorHeading(new Vector3(1e-5f, 0f, 0f));
        Assert.Equal(before, f);
    }

    [Fact]
    public void Constructor_RejectsNaNAndZero()
    {
        Assert.Throws<ArgumentException>(() => new Frame(new Vector3(float.NaN, 0, 0), Quaternion.Identity));
        Assert.Throws<ArgumentException>(() => new Frame(Vector3.Zero, new Quaternion(0, 0, 0, 0)));
        Assert.Throws<ArgumentException>(() => new Frame(Vector3.Zero, new Quaternion(float.PositiveInfinity, 0, 0, 1)));
        Assert.Throws<ArgumentException>(() => Frame.FromHeading(Vector3.Zero, float.NaN));
    }

    internal static void AssertOrthonormal(in Frame f, double tol)
    {
        var x = new Vector3(f.M11, f.M12, f.M13);
        var y = new Vector3(f.M21, f.M22, f.M23);
        var z = new Vector3(f.M31, f.M32, f.M33);
        Assert.True(Math.Abs(Vector3.Dot(x, x) - 1) < tol);
        Assert.True(Math.Abs(Vector3.Dot(y, y) - 1) < tol);
        Assert.True(Math.Abs(Vector3.Dot(z, z) - 1) < tol);
        Assert.True(Math.Abs(Vector3.Dot(x, y)) < tol);
        Assert.True(Math.Abs(Vector3.Dot(y, z)) < tol);
        Assert.True(Math.Abs(Vector3.Dot(x, z)) < tol);
    }

    internal static void AssertCacheMatchesQuaternion(in Frame f, double tol)
    {
        // The standard rotation matrix of (w, x, y, z), written column by column as in Frame's doc.
        double w = f.Qw, x = f.Qx, y = f.Qy, z = f.Qz;
        Assert.True(Math.Abs(f.M11 - (1 - 2 * y * y - 2 * z * z)) < tol);
        Assert.True(Math.Abs(f.M12 - (2 * x * y + 2 * w * z)) < tol);
        Assert.True(Math.Abs(f.M21 - (2 * x * y - 2 * w * z)) < tol);
        Assert.True(Math.Abs(f.M23 - (2 * y * z + 2 * w * x)) < tol);
        Assert.True(Math.Abs(f.M33 - (1 - 2 * x * x - 2 * y * y)) < tol);
    }
}
