using System;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Benchmarks.Floors;

/// <summary>
/// The bit-identical floor of the Frame operations, a measurement only (not the library): the same roundings in retail's
/// order as <c>Spatial.Frame</c> (<c>Frame::combine</c>, <c>grotate</c>, <c>rotate</c>, <c>set_heading</c>,
/// <c>localtoglobal</c> / <c>globaltolocal</c>), with everything that is not that arithmetic left out: no validity test
/// (set_rotate's <c>IsValid</c> and restore, which a valid input never takes), no early exits, no copies through
/// <c>in</c>/<c>out</c> parameters, every step inlined into one body over locals. On valid input it gives the library's bits,
/// which <see cref="FrameFloorBenchmarks"/> checks at setup; the gap between a library row and its floor is what is not
/// arithmetic. Its rows return the whole frame, as the library's return the whole <c>Frame</c>: a row that returned one
/// component let the JIT drop the rotation matrix of grotate and set_heading (nothing read it), which made those floors
/// 26–35 ns faster than the arithmetic the library must do (docs/performance.md, "#38: the floor that dropped the matrix").
/// </summary>
public struct FloorFrame
{
    public float Qw, Qx, Qy, Qz;
    public float M11, M12, M13, M21, M22, M23, M31, M32, M33;
    public float Ox, Oy, Oz;

    /// <summary>set_rotate without its validity test: normalise (one square root, one division) and cache.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void SetRotate(float qw, float qx, float qy, float qz)
    {
        double inv = 1.0 / Math.Sqrt((double)qw * qw + (double)qx * qx + (double)qy * qy + (double)qz * qz);
        float w = (float)(qw * inv);
        float x = (float)(qx * inv);
        float y = (float)(qy * inv);
        float z = (float)(inv * qz);
        Qw = w;
        Qx = x;
        Qy = y;
        Qz = z;
        double b2 = (double)x + x;
        double c2 = (double)y + y;
        double d2 = (double)z + z;
        double wb = w * b2;
        double wc = w * c2;
        double wd = w * d2;
        double xb = x * b2;
        double xc = x * c2;
        double xd = x * d2;
        double yc = y * c2;
        double yd = y * d2;
        double zd = z * d2;
        M11 = (float)(1.0 - yc - zd);
        M12 = (float)(xc + wd);
        M13 = (float)(xd - wc);
        M21 = (float)(xc - wd);
        double oneMinusXb = 1.0 - xb;
        M22 = (float)(oneMinusXb - zd);
        M23 = (float)(yd + wb);
        M31 = (float)(xd + wc);
        M32 = (float)(yd - wb);
        M33 = (float)(oneMinusXb - yc);
    }

    /// <summary>combine(this, b) into this: the origin lifted, the quaternion product, set_rotate.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void CombineWith(in FloorFrame b)
    {
        double px = b.Ox, py = b.Oy, pz = b.Oz;
        float ox = (float)(M31 * pz + M11 * px + M21 * py + Ox);
        float oy = (float)(M32 * pz + M12 * px + M22 * py + Oy);
        float oz = (float)(M33 * pz + M13 * px + M23 * py + Oz);
        double aw = Qw, ax = Qx, ay = Qy, az = Qz;
        double bw = b.Qw, bx = b.Qx, by = b.Qy, bz = b.Qz;
        float nz = (float)(by * ax + bz * aw - ay * bx + az * bw);
        float ny = (float)(by * aw - bz * ax + az * bx + ay * bw);
        float nx = (float)(aw * bx + bz * ay + bw * ax - by * az);
        float nw = (float)(aw * bw - bx * ax - by * ay - bz * az);
        Ox = ox;
        Oy = oy;
        Oz = oz;
        SetRotate(nw, nx, ny, nz);
    }

    /// <summary>grotate(w) for |w|² ≥ EPSILON² (the floor takes the caller's word for it).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void GRotate(Vector3 w)
    {
        double theta = Math.Sqrt((double)w.X * w.X + (double)w.Y * w.Y + (double)w.Z * w.Z);
        float thetaInv = (float)(1.0 / theta);
        (double s, double cosHalf) = Math.SinCos(theta * 0.5);
        double c = (float)cosHalf;
        double f = (float)(s * w.X * thetaInv);
        double g = (float)(thetaInv * s * w.Y);
        double h = s * thetaInv * w.Z;
        double qw = Qw, qx = Qx, qy = Qy, qz = Qz;
        float nz = (float)(f * qy + c * qz - g * qx + h * qw);
        float ny = (float)(c * qy - f * qz + h * qx + g * qw);
        float nx = (float)(c * qx + g * qz + f * qw - h * qy);
        float nw = (float)(c * qw - f * qx - g * qy - h * qz);
        SetRotate(nw, nx, ny, nz);
    }

    /// <summary>rotate(w): w lifted to global axes by the cached matrix, then grotate.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void Rotate(Vector3 w)
    {
        float gx = (float)((double)M31 * w.Z + (double)M11 * w.X + (double)M21 * w.Y);
        float gy = (float)((double)M32 * w.Z + (double)M12 * w.X + (double)M22 * w.Y);
        float gz = (float)((double)M33 * w.Z + (double)M13 * w.X + (double)M23 * w.Y);
        GRotate(new Vector3(gx, gy, gz));
    }

    /// <summary>globaltolocal(localtoglobal(p)).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly Vector3 RoundTrip(Vector3 p)
    {
        float gz = (float)((double)M33 * p.Z + (double)M13 * p.X + (double)M23 * p.Y + Oz);
        float gy = (float)((double)M32 * p.Z + (double)M12 * p.X + (double)M22 * p.Y + Oy);
        float gx = (float)((double)M31 * p.Z + (double)M11 * p.X + (double)M21 * p.Y + Ox);
        float dx = gx - Ox;
        float dy = gy - Oy;
        double dzWide = (double)gz - Oz;
        float dz = (float)dzWide;
        double z = dzWide * M33 + (double)dx * M31 + (double)dy * M32;
        double y = (double)dz * M23 + (double)dx * M21 + (double)dy * M22;
        double x = (double)dz * M13 + (double)dx * M11 + (double)dy * M12;
        return new Vector3((float)x, (float)y, (float)z);
    }

    /// <summary>set_heading(degrees) of a frame whose forward vector is long enough (set_vector_heading's small-vector exit
    /// not taken) and, for the exact +0 shortcuts, as the library: the same sine, cosine, atan2 and asin calls.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void SetHeading(double degrees)
    {
        float heading = (float)degrees;
        float dz = (float)(((double)M33 + M13) * 0.0 + M23);
        (double sin, double cos) = Math.SinCos(heading * 0.017453292519943295);
        float hx = (float)sin, hy = (float)cos;
        double inv = 1.0 / Math.Sqrt((double)hx * hx + (double)hy * hy + (double)dz * dz);
        float nx = (float)(inv * hx), ny = (float)(inv * hy), nz = (float)(inv * dz);
        double compass = 450.0 - Math.Atan2(ny, nx) * 57.29577951308232;
        compass = compass >= 360.0 ? compass - 360.0 : compass;
        float yaw = (float)(-compass * 0.017453292519943295);
        double sinPitch = Math.Clamp((double)nz, -1.0, 1.0);
        double asin = BitConverter.DoubleToInt64Bits(sinPitch) == 0L ? 0.0 : Math.Asin(sinPitch);
        float pitch = (float)(asin * 57.29577951308232 * 0.017453292519943295);
        double ti = pitch * 0.5;
        float th = (float)(yaw * 0.5);
        (double sinTi, double cosTi) = BitConverter.DoubleToInt64Bits(ti) == 0L ? (0.0, 1.0) : Math.SinCos(ti);
        float ci = (float)cosTi;
        (double sh, double cosTh) = Math.SinCos(th);
        float ch = (float)cosTh;
        float si = (float)sinTi;
        float cc = ch * ci;
        float cs = (float)(ci * sh);
        float sc = si * ch;
        float ss = (float)(sh * si);
        float ai = (float)((double)sc * 1f - cs * 0.0);
        float aj = (float)(cc * 0.0 + (double)ss * 1f);
        float ak = (float)((double)cs * 1f - sc * 0.0);
        float w = (float)(ss * 0.0 + (double)cc * 1f);
        SetRotate(w, ai, aj, ak);
    }
}
