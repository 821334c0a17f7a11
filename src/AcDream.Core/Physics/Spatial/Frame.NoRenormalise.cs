using System.Numerics;

namespace AcDream.Core.Physics.Spatial;

// Rotation updates that skip set_rotate's normalisation, for the PhysicsProfile.RenormaliseEvery fidelity switch. NOT
// retail: retail renormalises on every rotation change. The product is stored as is (its norm drifts by rounding) and
// the cached matrix is rebuilt from it, so a drifted quaternion scales every local-to-global vector by its squared
// norm.
public partial struct Frame
{
    /// <summary>
    /// <see cref="Combine"/> without renormalising: origin = f1.localtoglobal(f2.origin), q = f1.q * f2.q stored unnormalised
    /// (double intermediates as retail's combine). Not retail.
    /// </summary>
    internal void CombineNoRenormalise(in Frame f1, in Frame f2)
    {
        CombineProduct(f1, f2, out float ox, out float oy, out float oz, out float nw, out float nx, out float ny, out float nz);
        Origin = new Vector3(ox, oy, oz);
        StoreUnnormalised(nw, nx, ny, nz);
    }

    /// <summary>
    /// <see cref="GRotate(Vector3)"/> without renormalising: the same rotation by the global vector <paramref name="w"/> (|w| radians),
    /// with the product stored unnormalised. Not retail.
    /// </summary>
    internal void GRotateNoRenormalise(Vector3 w)
    {
        if (AxisAngle.TryCreate(w, out AxisAngle r))
        {
            GRotateProduct(r, out float nw, out float nx, out float ny, out float nz);
            StoreUnnormalised(nw, nx, ny, nz);
        }
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
