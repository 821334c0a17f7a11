using System.Numerics;

namespace AcDream.Core.Physics.Spatial;

// Plain-float32 variants of the Frame operations the tick uses most, for the ArithmeticMode.Float32 fidelity switch.
// Same formulas and operand order as the retail versions, but every product and sum rounds to float.
public partial struct Frame
{
    /// <summary>Float32 variant of <see cref="Cache"/>.</summary>
    internal void CacheFloat32()
    {
        float b2 = _qx + _qx, c2 = _qy + _qy, d2 = _qz + _qz;
        float wb = _qw * b2, wc = _qw * c2, wd = _qw * d2;
        float xb = _qx * b2, xc = _qx * c2, xd = _qx * d2;
        float yc = _qy * c2, yd = _qy * d2, zd = _qz * d2;
        _m11 = 1f - yc - zd;
        _m12 = xc + wd;
        _m13 = xd - wc;
        _m21 = xc - wd;
        float oneMinusXb = 1f - xb;
        _m22 = oneMinusXb - zd;
        _m23 = yd + wb;
        _m31 = xd + wc;
        _m32 = yd - wb;
        _m33 = oneMinusXb - yc;
    }

    /// <summary>Float32 variant of <see cref="SetRotate(float, float, float, float)"/> (same restore-on-invalid rule).</summary>
    internal bool SetRotateFloat32(float qw, float qx, float qy, float qz)
    {
        float oldW = _qw, oldX = _qx, oldY = _qy, oldZ = _qz;
        float inv = 1f / System.MathF.Sqrt(qw * qw + qx * qx + qy * qy + qz * qz);
        _qw = qw * inv;
        _qx = qx * inv;
        _qy = qy * inv;
        _qz = inv * qz;
        if (IsValid())
        {
            CacheFloat32();
            return true;
        }

        _qw = oldW;
        _qx = oldX;
        _qy = oldY;
        _qz = oldZ;
        return false;
    }

    /// <summary>Float32 variant of <see cref="Combine"/>.</summary>
    internal void CombineFloat32(in Frame f1, in Frame f2)
    {
        float ox = f1._m31 * f2.Origin.Z + f1._m11 * f2.Origin.X + f1._m21 * f2.Origin.Y + f1.Origin.X;
        float oy = f1._m32 * f2.Origin.Z + f1._m12 * f2.Origin.X + f1._m22 * f2.Origin.Y + f1.Origin.Y;
        float oz = f1._m33 * f2.Origin.Z + f1._m13 * f2.Origin.X + f1._m23 * f2.Origin.Y + f1.Origin.Z;
        float nz = f2._qy * f1._qx + f2._qz * f1._qw - f1._qy * f2._qx + f1._qz * f2._qw;
        float ny = f2._qy * f1._qw - f2._qz * f1._qx + f1._qz * f2._qx + f1._qy * f2._qw;
        float nx = f1._qw * f2._qx + f2._qz * f1._qy + f2._qw * f1._qx - f2._qy * f1._qz;
        float nw = f1._qw * f2._qw - f2._qx * f1._qx - f2._qy * f1._qy - f2._qz * f1._qz;
        Origin = new Vector3(ox, oy, oz);
        SetRotateFloat32(nw, nx, ny, nz);
    }

    /// <summary>Float32 variant of <see cref="GRotate(Vector3)"/>.</summary>
    internal void GRotateFloat32(Vector3 w)
    {
        float mag2 = w.X * w.X + w.Y * w.Y + w.Z * w.Z;
        if (mag2 < PhysicsGlobals.Epsilon * PhysicsGlobals.Epsilon)
        {
            return;
        }

        float theta = System.MathF.Sqrt(mag2);
        float thetaInv = 1f / theta;
        float half = theta * 0.5f;
        float s = System.MathF.Sin(half);
        float c = System.MathF.Cos(half);
        float f = s * w.X * thetaInv;
        float g = thetaInv * s * w.Y;
        float h = s * thetaInv * w.Z;
        float nz = f * _qy + c * _qz - g * _qx + h * _qw;
        float ny = c * _qy - f * _qz + h * _qx + g * _qw;
        float nx = c * _qx + g * _qz + f * _qw - h * _qy;
        float nw = c * _qw - f * _qx - g * _qy - h * _qz;
        SetRotateFloat32(nw, nx, ny, nz);
    }

    /// <summary>Float32 variant of <see cref="LocalToGlobal"/>.</summary>
    internal readonly Vector3 LocalToGlobalFloat32(Vector3 p) => new(
        _m31 * p.Z + _m11 * p.X + _m21 * p.Y + Origin.X,
        _m32 * p.Z + _m12 * p.X + _m22 * p.Y + Origin.Y,
        _m33 * p.Z + _m13 * p.X + _m23 * p.Y + Origin.Z);

    /// <summary>Float32 variant of <see cref="LocalToGlobalVec"/>.</summary>
    internal readonly Vector3 LocalToGlobalVecFloat32(Vector3 v) => new(
        _m31 * v.Z + _m11 * v.X + _m21 * v.Y,
        _m32 * v.Z + _m12 * v.X + _m22 * v.Y,
        _m33 * v.Z + _m13 * v.X + _m23 * v.Y);
}
