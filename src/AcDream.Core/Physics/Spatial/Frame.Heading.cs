using System;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.Spatial;

public partial struct Frame
{
    /// <summary>The global direction of the local +Y (forward) axis, as retail computes it from the cached matrix.</summary>
    // retail: Frame::get_vector_heading (acclient.c:357393)
    public readonly Vector3 GetVectorHeading()
    {
        // Retail multiplies the other two columns by 0.0 rather than dropping them; a NaN or infinity there propagates.
        float y = (float)(((double)_m32 + _m12) * 0.0 + _m22);
        float z = (float)(((double)_m33 + _m13) * 0.0 + _m23);
        float x = (float)(((double)_m31 + _m11) * 0.0 + _m21);
        return new Vector3(x, y, z);
    }

    /// <summary>
    /// Heading of the local +Y (forward) axis in degrees clockwise from north, in [0, 360):
    /// <c>fmod(450 - atan2(fy, fx) in degrees, 360)</c>. North (+Y, the identity frame) is 0, east (+X) is 90.
    /// Retail <c>Frame::get_heading</c>, which returns the x87 double kept here.
    /// </summary>
    // retail: Frame::get_heading (acclient.c:357409)
    public readonly double Heading
    {
        get
        {
            double x = ((double)_m31 + _m11) * 0.0 + _m21;
            double y = ((double)_m32 + _m12) * 0.0 + _m22;
            return HeadingMath.CompassFromAtan2(Math.Atan2(y, x));
        }
    }

    /// <summary>
    /// Turns the frame to face <paramref name="degrees"/> (clockwise from north) while keeping its current pitch:
    /// the forward vector becomes (sin h, cos h, current forward z) and <see cref="SetVectorHeading"/> rebuilds the rotation.
    /// </summary>
    /// <param name="degrees">Compass heading, degrees (the type of <see cref="Heading"/>); rounded to float first, as retail's
    /// <c>Frame::set_heading(float)</c> takes it, so a heading read with <see cref="Heading"/> and set back turns the frame by
    /// less than a float ulp of the angle.</param>
    /// <remarks>A method, not a setter of <see cref="Heading"/>: it rebuilds the rotation (no roll, the current pitch), so
    /// the heading read back is the wrapped, float-rounded value, not the one given.</remarks>
    // retail: Frame::set_heading (acclient.c:357691)
    public void SetHeading(double degrees)
    {
        float heading = (float)degrees;
        float dz = (float)(((double)_m33 + _m13) * 0.0 + _m23);
        double rad = heading * HeadingMath.DegToRad;
        (double sin, double cos) = Math.SinCos(rad); // the same bits as Sin and Cos (SinCosEquivalenceTests)
        SetVectorHeadingInlined((float)sin, (float)cos, dz);
    }

    /// <summary>
    /// Rebuilds the rotation so that local +Y points along <paramref name="heading"/> with no roll: yaw from its x,y and pitch
    /// from its z. A vector shorter than EPSILON leaves the frame unchanged.
    /// </summary>
    // retail: Frame::set_vector_heading (acclient.c:357667)
    public void SetVectorHeading(Vector3 heading) => SetVectorHeadingInlined(heading.X, heading.Y, heading.Z);

    // set_vector_heading's body on the vector's components, inlined into set_heading (#38): one body from the heading to the
    // cached matrix, no call and no Vector3 packing between them.
    // retail: Frame::set_vector_heading (acclient.c:357667)
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void SetVectorHeadingInlined(float hx, float hy, float hz)
    {
        // VectorMath.NormalizeCheckSmall's arithmetic, written out on the components (a NaN length is "small" there too).
        double len = Math.Sqrt((double)hx * hx + (double)hy * hy + (double)hz * hz);
        if (!(len >= PhysicsGlobals.Epsilon))
        {
            return;
        }

        double inv = 1.0 / len;
        float nx = (float)(inv * hx);
        float ny = (float)(inv * hy);
        float nz = (float)(inv * hz);
        float yaw = (float)(-HeadingMath.CompassFromAtan2(Math.Atan2(ny, nx)) * HeadingMath.DegToRad);
        // Divergence: retail passes n.z straight to asin; a normalised z one ulp past ±1 would give NaN there and set_rotate
        // would silently keep the old rotation. We clamp to [-1, 1] so such a vector still sets the heading.
        double sinPitch = Math.Clamp((double)nz, -1.0, 1.0);
        float pitch = (float)(ExactAsin(sinPitch) * HeadingMath.RadToDeg * HeadingMath.DegToRad);
        EulerSetRotateXyzNoRoll(pitch, yaw);
    }

    /// <summary>
    /// <see cref="EulerSetRotate"/> for order 0 with y = +0 (set_vector_heading's call): the same arithmetic with the order
    /// decoded at compile time, cos(+0) = 1 and sin(+0) = +0 written out, and each sine and cosine of one angle from SinCos.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void EulerSetRotateXyzNoRoll(float x, float z)
    {
        double ti = x * 0.5;
        const double tj = 0.0;
        float th = (float)(z * 0.5);
        (double sinTi, double cosTi) = IsPositiveZero(ti) ? (0.0, 1.0) : Math.SinCos(ti);
        float ci = (float)cosTi;
        const float cj = 1f;
        (double sh, double cosTh) = Math.SinCos(th);
        float ch = (float)cosTh;
        float si = (float)sinTi;
        const double sj = tj;
        float cc = ch * ci;
        float cs = (float)(ci * sh);
        float sc = si * ch;
        float ss = (float)(sh * si);
        float ai = (float)((double)sc * cj - cs * sj);
        float aj = (float)(cc * sj + (double)ss * cj);
        float ak = (float)((double)cs * cj - sc * sj);
        float w = (float)(ss * sj + (double)cc * cj);
        SetRotateInlined(w, ai, aj, ak);
    }

    // sin, cos and asin have exact values at +0 (C99 Annex F: sin(+0) = +0, cos(+0) = 1, asin(+0) = +0), written out so that
    // a level frame (pitch 0) skips the library calls.
    private static double ExactAsin(double x) => IsPositiveZero(x) ? 0.0 : Math.Asin(x);

    private static bool IsPositiveZero(double x) => System.BitConverter.DoubleToInt64Bits(x) == 0L;

    /// <summary>
    /// Sets the rotation from Euler angles (radians) in the given Shoemake order code (retail uses order 0 = XYZ static):
    /// the quaternion of rotating by <paramref name="x"/> about X, then <paramref name="y"/> about Y, then <paramref name="z"/> about Z,
    /// all about the fixed axes.
    /// </summary>
    /// <remarks>Only order 0 is used by the physics; other order codes follow Shoemake's <c>Eul_ToQuat</c> as retail's table does.</remarks>
    // retail: Frame::euler_set_rotate (acclient.c:357588), EulGetOrd (acclient.c:356963)
    public void EulerSetRotate(float x, float y, float z, int order)
    {
        // Shoemake's order decoding: EulSafe = {0,1,2,0}, EulNext = {1,2,0,1}.
        int f = order & 1;
        int s = (order >> 1) & 1;
        int n = (order >> 2) & 1;
        int i = (order >> 3 & 3) switch { 0 => 0, 1 => 1, 2 => 2, _ => 0 };
        int j = Next(i + n);
        int k = Next(i + 1 - n);

        double zv;
        if (f == 1)
        {
            zv = x;
            x = z;
        }
        else
        {
            zv = z;
        }

        if (n == 1)
        {
            y = -y;
        }

        double ti = x * 0.5;
        double tj = y * 0.5;
        float th = (float)(zv * 0.5);
        float ci = (float)Math.Cos(ti);
        float cj = (float)Math.Cos(tj);
        float ch = (float)Math.Cos(th);
        float si = (float)Math.Sin(ti);
        double sj = Math.Sin(tj);
        double sh = Math.Sin(th);
        float cc = ch * ci;
        float cs = (float)(ci * sh);
        float sc = si * ch;
        float ss = (float)(sh * si);

        float a0 = 0f, a1 = 0f, a2 = 0f;
        float w;
        float ai, aj, ak;
        if (s == 1)
        {
            ai = (float)(((double)sc + cs) * cj);
            aj = (float)(((double)ss + cc) * sj);
            ak = (float)(((double)cs - sc) * sj);
            w = (float)(((double)cc - ss) * cj);
        }
        else
        {
            ai = (float)((double)sc * cj - cs * sj);
            aj = (float)(cc * sj + (double)ss * cj);
            ak = (float)((double)cs * cj - sc * sj);
            w = (float)(ss * sj + (double)cc * cj);
        }

        if (n == 1)
        {
            aj = -aj;
        }

        Set(ref a0, ref a1, ref a2, i, ai);
        Set(ref a0, ref a1, ref a2, j, aj);
        Set(ref a0, ref a1, ref a2, k, ak);
        SetRotate(w, a0, a1, a2);

        static int Next(int idx) => idx switch { 0 => 1, 1 => 2, 2 => 0, _ => 1 };

        static void Set(ref float v0, ref float v1, ref float v2, int index, float value)
        {
            switch (index)
            {
                case 0: v0 = value; break;
                case 1: v1 = value; break;
                default: v2 = value; break;
            }
        }
    }
}
