using System;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// Retail's degree/radian literals, pinned by the doubles the binary holds. Hex-Rays prints a double constant with 16
/// significant digits, which does not always name the double uniquely: the printed digits narrow the binary's constant to a
/// few neighbouring doubles, and of those we take the one a compiler emits for the source constant (the double nearest the
/// real value), checking that it prints as shown.
/// </summary>
public class AngleConstantsTests
{
    private static long Bits(double d) => BitConverter.DoubleToInt64Bits(d);

    [Fact]
    public void DegToRad_IsTheDoubleNearestPiOver180_0x3F91DF46A2529D39()
    {
        // Printed "0.0174532925199433" (acclient.c:357691, 357667). π/180 = 0.01745329251994329576923...; the nearest double
        // is 0x3F91DF46A2529D39 = 0.017453292519943295 (next below ...D38 = 0.01745329251994329201, next above ...D3A =
        // 0.01745329251994329894). Its 16-digit print is 0.0174532925199433 (digits ...3295 round up). Parsing the print
        // gives ...D3A, one ulp above.
        Assert.Equal(0x3F91DF46A2529D39L, Bits(HeadingMath.DegToRad));
        Assert.Equal("0.0174532925199433", HeadingMath.DegToRad.ToString("G16", System.Globalization.CultureInfo.InvariantCulture));
        Assert.Equal(0x3F91DF46A2529D3AL, Bits(0.0174532925199433));
    }

    [Fact]
    public void RadToDeg_IsTheDoubleNearest180OverPi_0x404CA5DC1A63C1F8()
    {
        // Printed "57.29577951308232" (acclient.c:357409, 357667). 180/π = 57.29577951308232087680...; the nearest double is
        // 0x404CA5DC1A63C1F8 = 57.29577951308232286465 (neighbours 57.29577951308231576 and 57.29577951308232997), and
        // here the 16 digits do parse back to it.
        Assert.Equal(0x404CA5DC1A63C1F8L, Bits(HeadingMath.RadToDeg));
        Assert.Equal(0x404CA5DC1A63C1F8L, Bits(57.29577951308232));
    }

    [Fact]
    public void SleddingSteepAngle_IsTheDoubleNearestTenDegrees_0x3FC657184AE74487()
    {
        // calc_friction (acclient.c:316090) calls cos(0.1745329251994329). 10° = π/18 = 0.17453292519943295769...; the
        // nearest double is 0x3FC657184AE74487 = 0.17453292519943294780 (the next above, ...488, is 0.17453292519943297556).
        // Its 16-digit print is 0.1745329251994329 — as are those of ...484 to ...486, but only ...487 is the value of a
        // source constant (10 * π/180 in double gives it as well). Parsing the print gives ...485, two ulps low.
        Assert.Equal(0x3FC657184AE74487L, Bits(PhysicsObj.SleddingSteepAngle));
        Assert.Equal("0.1745329251994329", PhysicsObj.SleddingSteepAngle.ToString("G16", System.Globalization.CultureInfo.InvariantCulture));
        Assert.Equal(0x3FC657184AE74485L, Bits(0.1745329251994329));
        Assert.Equal(0x3FC657184AE74487L, Bits(10.0 * HeadingMath.DegToRad));
    }

    [Fact]
    public void SleddingSteepCos_IsCosOfTenDegrees_0x3FEF838B8C811C17()
    {
        // cos(π/18) = 0.98480775301220805936...; the nearest double is 0x3FEF838B8C811C17 = 0.98480775301220802032 (a ulp
        // here is 1.1e-16; the argument's two-ulp error of 5.6e-17 moves the cosine by only 1e-17, so both give this double).
        Assert.Equal(0x3FEF838B8C811C17L, Bits(PhysicsObj.SleddingSteepCos));
    }
}
