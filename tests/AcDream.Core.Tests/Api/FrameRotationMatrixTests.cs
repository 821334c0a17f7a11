using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// Issue #23: the cached rotation (retail <c>m_fl2gv</c>) reads as a System.Numerics matrix for row vectors, its rows the
/// global images of the local axes; the nine entries are the engine's (internal, named M11..M33 as System.Numerics does).
/// </summary>
public class FrameRotationMatrixTests
{
    [Fact]
    public void RotationMatrix_OfAQuarterTurnAboutZ_HasTheTurnedAxesAsRows()
    {
        // q = (cos 45°, 0, 0, sin 45°): w z = 1/2, z² = 1/2. M11 = 1 - 2z² = 0, M12 = 2wz = 1, M21 = -2wz = -1, M22 = 0,
        // M33 = 1: local X turns to global +Y, local Y to global -X, local Z stays.
        float h = MathF.Sqrt(0.5f);
        var f = new Frame(new Vector3(5f, 6f, 7f), new Quaternion(0f, 0f, h, h));
        Matrix4x4 m = f.RotationMatrix;

        Assert.Equal(0f, m.M11, 6);
        Assert.Equal(1f, m.M12, 6);
        Assert.Equal(0f, m.M13, 6);
        Assert.Equal(-1f, m.M21, 6);
        Assert.Equal(0f, m.M22, 6);
        Assert.Equal(1f, m.M33, 6);
        Assert.Equal(0f, m.M41);
        Assert.Equal(1f, m.M44);
        // The origin is not in it (a rotation only), and the entries are exactly the engine's.
        Assert.Equal((f.M11, f.M12, f.M13), (m.M11, m.M12, m.M13));
        Assert.Equal((f.M21, f.M22, f.M23), (m.M21, m.M22, m.M23));
        Assert.Equal((f.M31, f.M32, f.M33), (m.M31, m.M32, m.M33));
        Vector3 x = Vector3.TransformNormal(Vector3.UnitX, m);
        Assert.Equal(0f, x.X, 6);
        Assert.Equal(1f, x.Y, 6);
        Assert.Equal(0f, x.Z, 6);
    }
}
