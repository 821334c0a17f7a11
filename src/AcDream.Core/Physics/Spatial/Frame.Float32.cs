using System.Numerics;

namespace AcDream.Core.Physics.Spatial;

// Plain-float32 variants of the Frame operations the tick uses most, for the ArithmeticMode.Float32 fidelity switch.
// Same formulas and operand order as the retail versions, but every product and sum rounds to float.
public partial struct Frame
{
    /// <summary>Float32 variant of <see cref="Cache"/>.</summary>
    public void CacheFloat32()
    {
        float b2 = _qx + _qx, c2 = _qy + _qy, d2 = _qz + _qz;
        float wb = _qw * b2, wc = _qw * c2, wd = _qw * d2;
        float xb = _qx * b2, xc = _qx * c2, xd = _qx * d2;
        float yc = _qy * c2, yd = _qy * d2, zd = _qz * d2;
        _m0 = 1f - yc - zd;
        _m1 = xc + wd;
        _m2 = xd - wc;
        _m3 = xc - wd;
        float oneMinusXb = 1f - xb;
        _m4 = oneMinusXb - zd;
        _m5 = yd + wb;
        _m6 = xd + wc;
        _m7 = yd - wb;
        _m8 = oneMinusXb - yc;
    }

    /// <summary>Float32 variant of <see cref="SetRotate(float, float, float, float)"/> (same restore-on-invalid rule).</summary>
    public bool SetRotateFloat32(float qw, float qx, float qy, float qz)
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
    public void CombineFloat32(in Frame f1, in Frame f2)
    {
        float ox = f1._m6 * f2.Origin.Z + f1._m0 * f2.Origin.X + f1._m3 * f2.Origin.Y + f1.Origin.X;
        float oy = f1._m7 * f2.Origin.Z + f1._m1 * f2.Origin.X + f1._m4 * f2.Origin.Y + f1.Origin.Y;
        float oz = f1._m8 * f2.Origin.Z + f1._m2 * f2.Origin.X + f1._m5 * f2.Origin.Y + f1.Origin.Z;
        float nz = f2._qy * f1._qx + f2._qz * f1._qw - f1._qy * f2._qx + f1._qz * f2._qw;
        float ny = f2._qy * f1._qw - f2._qz * f1._qx + f1._qz * f2._qx + f1._qy * f2._qw;
        float nx = f1._qw * f2._qx + f2._qz * f1._qy + f2._qw * f1._qx - f2._qy * f1._qz;
        float nw = f1._qw * f2._qw - f2._qx * f1._qx - f2._qy * f1._qy - f2._qz * f1._qz;
        Origin = new Vector3(ox, oy, oz);
        SetRotateFloat32(nw, nx, ny, nz);
    }

    /// <summary>Float32 variant of <see cref="GRotate(Vector3)"/>.</summary>
    public void GRotateFloat32(Vector3 w)
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
    public readonly Vector3 LocalToGlobalFloat32(Vector3 p) => new(
        _m6 * p.Z + _m0 * p.X + _m3 * p.Y + Origin.X,
        _m7 * p.Z + _m1 * p.X + _m4 * p.Y + Origin.Y,
        _m8 * p.Z + _m2 * p.X + _m5 * p.Y + Origin.Z);

    /// <summary>Float32 variant of <see cref="LocalToGlobalVec"/>.</summary>
    public readonly Vector3 LocalToGlobalVecFloat32(Vector3 v) => new(
        _m6 * v.Z + _m0 * v.X + _m3 * v.Y,
        _m7 * v.Z + _m1 * v.X + _m4 * v.Y,
        _m8 * v.Z + _m2 * v.X + _m5 * v.Y);
}
