using System;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.Spatial;

public partial struct Frame
{
    /// <summary>Maps a local point to parent (global) coordinates: M * p + origin.</summary>
    // retail: Frame::localtoglobal (acclient.c:143701)
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // #38: inlined, the caller keeps the point in registers
    public readonly Vector3 LocalToGlobal(Vector3 p)
    {
        double z = (double)_m33 * p.Z + (double)_m13 * p.X + (double)_m23 * p.Y + Origin.Z;
        double y = (double)_m32 * p.Z + (double)_m12 * p.X + (double)_m22 * p.Y + Origin.Y;
        double x = (double)_m31 * p.Z + (double)_m11 * p.X + (double)_m21 * p.Y + Origin.X;
        return new Vector3((float)x, (float)y, (float)z);
    }

    /// <summary>Maps a local direction to parent (global) coordinates: M * v (no translation).</summary>
    // retail: Frame::localtoglobalvec (acclient.c:143658)
    public readonly Vector3 LocalToGlobalVec(Vector3 v)
    {
        double z = (double)_m33 * v.Z + (double)_m13 * v.X + (double)_m23 * v.Y;
        double y = (double)_m32 * v.Z + (double)_m12 * v.X + (double)_m22 * v.Y;
        double x = (double)_m31 * v.Z + (double)_m11 * v.X + (double)_m21 * v.Y;
        return new Vector3((float)x, (float)y, (float)z);
    }

    /// <summary>Maps a parent (global) point to local coordinates: Mᵀ * (p - origin).</summary>
    // retail: Frame::globaltolocal (acclient.c:143717)
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // #38: inlined, the caller keeps the point in registers
    public readonly Vector3 GlobalToLocal(Vector3 p)
    {
        float dx = p.X - Origin.X;
        float dy = p.Y - Origin.Y;
        double dzWide = (double)p.Z - Origin.Z; // the z row keeps the difference on the x87 stack (acclient.c:143733)
        float dz = (float)dzWide;               // the x and y rows use its float spill
        double z = dzWide * _m33 + (double)dx * _m31 + (double)dy * _m32;
        double y = (double)dz * _m23 + (double)dx * _m21 + (double)dy * _m22;
        double x = (double)dz * _m13 + (double)dx * _m11 + (double)dy * _m12;
        return new Vector3((float)x, (float)y, (float)z);
    }

    /// <summary>Maps a parent (global) direction to local coordinates: Mᵀ * v.</summary>
    // retail: Frame::globaltolocalvec (acclient.c:143674)
    public readonly Vector3 GlobalToLocalVec(Vector3 v)
    {
        double z = (double)_m33 * v.Z + (double)_m31 * v.X + (double)_m32 * v.Y;
        double y = (double)_m23 * v.Z + (double)_m21 * v.X + (double)_m22 * v.Y;
        double x = (double)_m13 * v.Z + (double)_m11 * v.X + (double)_m12 * v.Y;
        return new Vector3((float)x, (float)y, (float)z);
    }

    /// <summary>
    /// Maps a point local to <paramref name="from"/> into this frame's local space (both frames in the same parent space).
    /// </summary>
    public readonly Vector3 LocalToLocal(in Frame from, Vector3 p) => GlobalToLocal(from.LocalToGlobal(p));

    /// <summary>
    /// Rotates by an angular displacement given in LOCAL axes (radians): the vector is lifted to global axes with the
    /// cached matrix and applied through <see cref="GRotate(Vector3)"/>.
    /// </summary>
    // retail: Frame::rotate (acclient.c:143690)
    public void Rotate(Vector3 w)
    {
        float gx = (float)((double)_m31 * w.Z + (double)_m11 * w.X + (double)_m21 * w.Y);
        float gy = (float)((double)_m32 * w.Z + (double)_m12 * w.X + (double)_m22 * w.Y);
        float gz = (float)((double)_m33 * w.Z + (double)_m13 * w.X + (double)_m23 * w.Y);
        // grotate on the lifted components as they are (not packed into a Vector3 and read back).
        if (AxisAngle.TryCreate(gx, gy, gz, out AxisAngle r))
        {
            GRotate(r);
        }
    }

    /// <summary><see cref="Rotate(Vector3)"/> of the displacement (<paramref name="wx"/>, <paramref name="wy"/>,
    /// <paramref name="wz"/>), with grotate's axis-angle rotation taken from <paramref name="cache"/> when the lifted
    /// displacement repeats: the same bits. Components, not a Vector3: nothing is packed and read back (#38).</summary>
    // retail part: Frame::rotate, grotate's first half from a cache (acclient.c line 143690)
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal void Rotate(float wx, float wy, float wz, ref AxisAngleCache cache)
    {
        float gx = (float)((double)_m31 * wz + (double)_m11 * wx + (double)_m21 * wy);
        float gy = (float)((double)_m32 * wz + (double)_m12 * wx + (double)_m22 * wy);
        float gz = (float)((double)_m33 * wz + (double)_m13 * wx + (double)_m23 * wy);
        if (cache.TryGet(gx, gy, gz, out AxisAngle r))
        {
            GRotate(r);
        }
    }

    /// <summary>
    /// Rotates by an angular displacement given in GLOBAL axes (radians, e.g. omega * dt): the axis-angle quaternion
    /// (cos θ/2, sin θ/2 · w/θ) is pre-multiplied onto the current quaternion and the result renormalised.
    /// Skipped when |w|² is below EPSILON².
    /// </summary>
    // retail: Frame::grotate (acclient.c:357421)
    public void GRotate(Vector3 w)
    {
        if (AxisAngle.TryCreate(w, out AxisAngle r))
        {
            GRotate(r);
        }
    }

    /// <summary>grotate's second half: pre-multiplies the axis-angle quaternion <paramref name="r"/> (already worked out
    /// from the displacement) and renormalises.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal void GRotate(in AxisAngle r)
    {
        GRotateProduct(r, out float nw, out float nx, out float ny, out float nz);
        SetRotateInlined(nw, nx, ny, nz);
    }

    /// <summary>grotate's product: the axis-angle quaternion <paramref name="r"/> times this quaternion (not normalised).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private readonly void GRotateProduct(in AxisAngle r, out float nw, out float nx, out float ny, out float nz)
    {
        double f = r.F, g = r.G, c = r.C, h = r.H;
        double qw = _qw, qx = _qx, qy = _qy, qz = _qz;
        nz = (float)(f * qy + c * qz - g * qx + h * qw);
        ny = (float)(c * qy - f * qz + h * qx + g * qw);
        nx = (float)(c * qx + g * qz + f * qw - h * qy);
        nw = (float)(c * qw - f * qx - g * qy - h * qz);
    }

    /// <summary>Linear interpolation of the origin between two frames: (1 - t) * from + t * to.</summary>
    // retail: Frame::interpolate_origin (acclient.c:357228)
    public void InterpolateOrigin(in Frame from, in Frame to, float t)
    {
        float ty = t * to.Origin.Y;
        float tz = t * to.Origin.Z;
        double oneMinusT = 1.0 - t;
        float fx = (float)(oneMinusT * from.Origin.X);
        float fy = (float)(oneMinusT * from.Origin.Y);
        float fz = (float)(oneMinusT * from.Origin.Z);
        float z = fz + tz;
        float x = t * to.Origin.X + fx;
        float y = fy + ty;
        Origin = new Vector3(x, y, z);
    }

    /// <summary>
    /// Spherical interpolation of the rotation from <paramref name="from"/> to <paramref name="to"/> at fraction <paramref name="t"/>,
    /// taking the shorter arc (negating <paramref name="to"/> when the dot product is negative); falls back to linear weights when
    /// the rotations are within EPSILON or the slerp weights leave [0, 1].
    /// </summary>
    // retail: Frame::interpolate_rotation (acclient.c:357257)
    public void InterpolateRotation(in Frame from, in Frame to, float t)
    {
        double cosom = (double)from._qy * to._qy + (double)from._qw * to._qw + (double)from._qx * to._qx + (double)from._qz * to._qz;
        float tw, tx, ty, tz;
        if (cosom < 0.0)
        {
            cosom = -cosom;
            tw = -to._qw;
            tx = -to._qx;
            ty = -to._qy;
            tz = -to._qz;
        }
        else
        {
            tw = to._qw;
            tx = to._qx;
            ty = to._qy;
            tz = to._qz;
        }

        double scale0, scale1;
        if (1.0 - cosom <= PhysicsGlobals.Epsilon)
        {
            scale0 = 1.0 - t;
            scale1 = t;
        }
        else
        {
            double omega = Math.Acos(cosom);
            double oneMinusT = 1.0 - t;
            double invSin = 1.0 / Math.Sin(omega);
            scale0 = invSin * Math.Sin(omega * oneMinusT);
            scale1 = Math.Sin(t * omega) * invSin;
            if (scale0 < 0.0 || scale0 > 1.0 || scale1 < 0.0 || scale1 > 1.0)
            {
                scale0 = oneMinusT;
                scale1 = t;
            }
        }

        float nz = (float)(tz * scale1 + from._qz * scale0);
        float ny = (float)(from._qy * scale0 + ty * scale1);
        float nx = (float)(from._qx * scale0 + tx * scale1);
        float nw = (float)(scale0 * from._qw + tw * scale1);
        SetRotate(nw, nx, ny, nz);
    }
}
