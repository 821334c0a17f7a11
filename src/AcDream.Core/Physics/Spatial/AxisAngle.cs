using System;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.Spatial;

/// <summary>
/// The first half of <c>Frame::grotate</c>: the rotation quaternion (c, f, g, h) = (cos θ/2, sin θ/2 · w/θ) of an angular
/// displacement w (radians, global axes), with the float roundings retail stores. It depends on w alone, so an object
/// whose displacement repeats (constant omega and step) can keep it and skip the square root, the division, the sine and
/// the cosine; <see cref="Frame.GRotate(in AxisAngle)"/> applies it with the same bits as <see cref="Frame.GRotate(Vector3)"/>.
/// </summary>
internal readonly struct AxisAngle
{
    /// <summary>cos θ/2, rounded to float.</summary>
    public readonly float C;

    /// <summary>sin θ/2 · w.x/θ, rounded to float.</summary>
    public readonly float F;

    /// <summary>sin θ/2 · w.y/θ, rounded to float.</summary>
    public readonly float G;

    /// <summary>sin θ/2 · w.z/θ, kept in double (retail keeps it on the x87 stack).</summary>
    public readonly double H;

    private AxisAngle(float c, float f, float g, double h)
    {
        C = c;
        F = f;
        G = g;
        H = h;
    }

    /// <summary>Works out the rotation of <paramref name="w"/>; false (nothing to do) when |w|² is below EPSILON².</summary>
    // retail: Frame::grotate (acclient.c:357421), up to the quaternion product
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool TryCreate(Vector3 w, out AxisAngle r) => TryCreate(w.X, w.Y, w.Z, out r);

    /// <summary><see cref="TryCreate(Vector3, out AxisAngle)"/> on the displacement's components (wx, wy, wz).</summary>
    // retail: Frame::grotate (acclient.c:357421), up to the quaternion product
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool TryCreate(float wx, float wy, float wz, out AxisAngle r)
    {
        double mag2 = (double)wx * wx + (double)wy * wy + (double)wz * wz;
        if (mag2 < (double)PhysicsGlobals.Epsilon * PhysicsGlobals.Epsilon)
        {
            r = default;
            return false;
        }

        double theta = Math.Sqrt(mag2);
        float thetaInv = (float)(1.0 / theta);
        double half = theta * 0.5;
        (double s, double cosHalf) = Math.SinCos(half); // the same bits as Sin and Cos (SinCosEquivalenceTests)
        float c = (float)cosHalf;
        float f = (float)(s * wx * thetaInv);
        float g = (float)(thetaInv * s * wy);
        double h = s * thetaInv * wz;
        r = new AxisAngle(c, f, g, h);
        return true;
    }
}

/// <summary>
/// A one-entry cache of <see cref="AxisAngle"/> keyed by the displacement's bits: the rotation is a function of those bits
/// alone, so a hit gives what <see cref="AxisAngle.TryCreate(Vector3, out AxisAngle)"/> would (its square root, division, sine and cosine skipped).
/// An animation's omega applied frame after frame, or an object's constant spin, repeats its displacement.
/// </summary>
internal struct AxisAngleCache
{
    private int _keyX, _keyY, _keyZ;
    private bool _filled;
    private bool _rotates;
    private AxisAngle _rotation;

    /// <summary><see cref="AxisAngle.TryCreate(float, float, float, out AxisAngle)"/> of (<paramref name="wx"/>,
    /// <paramref name="wy"/>, <paramref name="wz"/>), from the cache when their bits repeat.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public bool TryGet(float wx, float wy, float wz, out AxisAngle r)
    {
        if (!_filled || BitConverter.SingleToInt32Bits(wx) != _keyX || BitConverter.SingleToInt32Bits(wy) != _keyY
            || BitConverter.SingleToInt32Bits(wz) != _keyZ)
        {
            Fill(wx, wy, wz);
        }

        r = _rotation;
        return _rotates;
    }

    // The miss, out of line (#38): its square root, division and sine/cosine call stay out of the caller, whose prologue then
    // saves fewer registers and zeroes no locals for the sine/cosine on every call, hit or miss.
    [MethodImpl(MethodImplOptions.NoInlining)]
    private void Fill(float wx, float wy, float wz)
    {
        _rotates = AxisAngle.TryCreate(wx, wy, wz, out _rotation);
        _keyX = BitConverter.SingleToInt32Bits(wx);
        _keyY = BitConverter.SingleToInt32Bits(wy);
        _keyZ = BitConverter.SingleToInt32Bits(wz);
        _filled = true;
    }
}

