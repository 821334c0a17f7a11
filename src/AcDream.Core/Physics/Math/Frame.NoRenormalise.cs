using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// Rotation updates that skip <c>set_rotate</c>'s normalisation, for the <see cref="PhysicsProfile.RenormaliseEvery"/> fidelity
/// switch. NOT retail: retail renormalises on every rotation change. The product is stored as is (its norm drifts by
/// rounding) and the cached matrix is rebuilt from it, so a drifted quaternion scales every local-to-global vector by its
/// squared norm.
/// </summary>
public partial struct Frame
{
    /// <summary>
    /// <see cref="Combine"/> without renormalising: origin = f1.localtoglobal(f2.origin), q = f1.q * f2.q stored unnormalised
    /// (double intermediates as retail's combine). Not retail.
    /// </summary>
    public void CombineNoRenormalise(in Frame f1, in Frame f2)
    {
        double ox = (double)f1._m6 * f2.Origin.Z + (double)f1._m0 * f2.Origin.X + (double)f1._m3 * f2.Origin.Y + f1.Origin.X;
        double oy = (double)f1._m7 * f2.Origin.Z + (double)f1._m1 * f2.Origin.X + (double)f1._m4 * f2.Origin.Y + f1.Origin.Y;
        double oz = (double)f1._m8 * f2.Origin.Z + (double)f1._m2 * f2.Origin.X + (double)f1._m5 * f2.Origin.Y + f1.Origin.Z;
        float nz = (float)((double)f2._qy * f1._qx + (double)f2._qz * f1._qw - (double)f1._qy * f2._qx + (double)f1._qz * f2._qw);
        float ny = (float)((double)f2._qy * f1._qw - (double)f2._qz * f1._qx + (double)f1._qz * f2._qx + (double)f1._qy * f2._qw);
        float nx = (float)((double)f1._qw * f2._qx + (double)f2._qz * f1._qy + (double)f2._qw * f1._qx - (double)f2._qy * f1._qz);
        float nw = (float)((double)f1._qw * f2._qw - (double)f2._qx * f1._qx - (double)f2._qy * f1._qy - (double)f2._qz * f1._qz);
        Origin = new Vector3((float)ox, (float)oy, (float)oz);
        StoreUnnormalised(nw, nx, ny, nz);
    }

    /// <summary>
    /// <see cref="GRotate"/> without renormalising: the same rotation by the global vector <paramref name="w"/> (|w| radians),
    /// with the product stored unnormalised. Not retail.
    /// </summary>
    public void GRotateNoRenormalise(Vector3 w)
    {
        double mag2 = (double)w.X * w.X + (double)w.Y * w.Y + (double)w.Z * w.Z;
        if (mag2 < (double)PhysicsGlobals.Epsilon * PhysicsGlobals.Epsilon)
        {
            return;
        }

        double theta = System.Math.Sqrt(mag2);
        float thetaInv = (float)(1.0 / theta);
        double half = theta * 0.5;
        double s = System.Math.Sin(half);
        float c = (float)System.Math.Cos(half);
        float f = (float)(s * w.X * thetaInv);
        float g = (float)(thetaInv * s * w.Y);
        double h = s * thetaInv * w.Z;
        float nz = (float)((double)f * _qy + (double)c * _qz - (double)g * _qx + h * _qw);
        float ny = (float)((double)c * _qy - (double)f * _qz + h * _qx + (double)g * _qw);
        float nx = (float)((double)c * _qx + (double)g * _qz + (double)f * _qw - h * _qy);
        float nw = (float)((double)c * _qw - (double)f * _qx - (double)g * _qy - h * _qz);
        StoreUnnormalised(nw, nx, ny, nz);
    }

    /// <summary>Squared norm of the quaternion, in double (1 for every frame retail produces; drifts only without renormalising).</summary>
    public readonly double QuaternionNorm2 => (double)_qw * _qw + (double)_qx * _qx + (double)_qy * _qy + (double)_qz * _qz;

    private void StoreUnnormalised(float nw, float nx, float ny, float nz)
    {
        if (!(float.IsFinite(nw) && float.IsFinite(nx) && float.IsFinite(ny) && float.IsFinite(nz))
            || (double)nw * nw + (double)nx * nx + (double)ny * ny + (double)nz * nz == 0.0)
        {
            return;
        }

        _qw = nw;
        _qx = nx;
        _qy = ny;
        _qz = nz;
        Cache();
    }
}
