using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision.Primitives;

/// <summary>Moving planes between the local spaces of the sweep (retail's <c>Plane</c> helpers in PORTAL/geometry/Plane.c).</summary>
public static class PlaneSpace
{
    /// <summary>
    /// The plane <paramref name="localPlane"/>, given in <paramref name="from"/>'s local frame, expressed in
    /// <paramref name="to"/>'s landblock: the normal is rotated by <paramref name="from"/>'s frame and the plane's point
    /// nearest the local origin (<c>-d·N</c>) is carried across.
    /// </summary>
    // retail: Plane::localtoglobal (acclient.c:467671)
    public static CollisionPlane LocalToGlobal(in Position to, in Position from, in CollisionPlane localPlane)
    {
        double nd = -(double)localPlane.D;
        var point = new Vector3((float)(nd * localPlane.N.X), (float)(nd * localPlane.N.Y), (float)(nd * localPlane.N.Z));
        ref readonly Frame f = ref from.Frame;
        Vector3 n = localPlane.N;
        float gx = (float)((double)f.M31 * n.Z + (double)f.M21 * n.Y + (double)f.M11 * n.X);
        float gy = (float)((double)f.M32 * n.Z + (double)f.M22 * n.Y + (double)f.M12 * n.X);
        float gz = (float)((double)f.M33 * n.Z + (double)f.M23 * n.Y + (double)f.M13 * n.X);
        Vector3 g = to.LocalToGlobal(from, point);
        double s = (double)gz * g.Z + (double)gy * g.Y;
        double d = -(s + (double)gx * g.X);
        return new CollisionPlane(new Vector3(gx, gy, gz), (float)d);
    }
}
