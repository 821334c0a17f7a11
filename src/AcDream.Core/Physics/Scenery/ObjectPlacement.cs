using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Scenery;

/// <summary>
/// Retail's placement functions of an object spot (<c>ObjectDesc</c>), as pure functions of the spot, the terrain vertex's
/// global coordinates (<c>x</c>, <c>y</c>: landblock · 8 + vertex) and the spot's index <c>k</c> in its scene: where the spot
/// lands around its vertex, its frame, its slope window and its scale.
/// </summary>
public static class ObjectPlacement
{
    /// <summary>
    /// The spot's point relative to its vertex: the base origin, displaced by <c>u(45773 + k) · displace_x</c> and
    /// <c>u(72719 + k) · displace_y</c> (each only when its displacement is above 0), then turned by the vertex's quarter turn
    /// <c>q = u(59371)</c> (shared by every object of the vertex): q &lt; ¼ keeps (x, y), q &lt; ½ gives (−y, x), q &lt; ¾
    /// gives (−x, −y), else (y, −x). z is the base z.
    /// </summary>
    /// <exception cref="ArgumentNullException"><paramref name="desc"/> is null.</exception>
    // retail: ObjectDesc::Place (acclient.c:462604)
    public static Vector3 Place(ObjectDesc desc, uint x, uint y, uint k)
    {
        ArgumentNullException.ThrowIfNull(desc);
        Vector3 b = desc.BaseFrame.Origin;
        // x is stored to a float (obj_loca); y stays on the x87 stack until it is stored into the result.
        float px = desc.DisplaceX <= 0.0
            ? b.X
            : (float)(SceneryHash.Unit(x, y, SceneryHash.DisplaceXSalt + k) * desc.DisplaceX + b.X);
        double py = desc.DisplaceY <= 0.0
            ? b.Y
            : SceneryHash.Unit(x, y, SceneryHash.DisplaceYSalt + k) * desc.DisplaceY + b.Y;
        double q = SceneryHash.Unit(x, y, SceneryHash.QuadrantSalt);
        if (q < 0.25)
        {
            return new Vector3(px, (float)py, b.Z);
        }

        if (q < 0.5)
        {
            return new Vector3((float)-py, px, b.Z);
        }

        if (q < 0.75)
        {
            return new Vector3(-px, (float)-py, b.Z);
        }

        return new Vector3((float)py, -px, b.Z);
    }

    /// <summary>
    /// The spot's frame at <paramref name="loc"/>: the base frame with its origin moved there and, when the spot has a
    /// maximum rotation above 0, the heading <c>u(63127 + k) · max_rot</c> degrees (the base frame's pitch kept).
    /// </summary>
    /// <exception cref="ArgumentNullException"><paramref name="desc"/> is null.</exception>
    // retail: ObjectDesc::GetObjFrame (acclient.c:462659)
    public static Frame GetObjFrame(ObjectDesc desc, uint x, uint y, uint k, Vector3 loc)
    {
        ArgumentNullException.ThrowIfNull(desc);
        Frame f = desc.BaseFrame;
        f.Origin = loc;
        if (desc.MaxRotation > 0.0)
        {
            f.SetHeading(SceneryHash.Unit(x, y, SceneryHash.HeadingSalt + k) * desc.MaxRotation);
        }

        return f;
    }

    /// <summary>
    /// The frame of an aligned spot at <paramref name="loc"/>: the base frame with its origin moved there, turned to the
    /// heading of <c>−N</c> taken in x and y only: the terrain's uphill direction (a slope's normal leans downhill). A
    /// heading, no tilt onto the slope; a flat triangle gives heading 0.
    /// </summary>
    /// <exception cref="ArgumentNullException"><paramref name="desc"/> is null.</exception>
    // retail: ObjectDesc::ObjAlign (acclient.c:462707)
    public static Frame ObjAlign(ObjectDesc desc, in CollisionPlane plane, Vector3 loc)
    {
        ArgumentNullException.ThrowIfNull(desc);
        Frame f = desc.BaseFrame;
        f.Origin = loc;
        f.SetHeading(FlatHeading(new Vector3(-plane.N.X, -plane.N.Y, -plane.N.Z)));
        return f;
    }

    /// <summary>True when the terrain normal's z <paramref name="normalZ"/> lies in the spot's slope window, bounds
    /// included: <c>min_slope ≤ N.z ≤ max_slope</c> (cosines).</summary>
    /// <exception cref="ArgumentNullException"><paramref name="desc"/> is null.</exception>
    // retail: ObjectDesc::CheckSlope (acclient.c:351354)
    public static bool CheckSlope(ObjectDesc desc, float normalZ)
    {
        ArgumentNullException.ThrowIfNull(desc);
        return normalZ >= (double)desc.MinSlope && normalZ <= (double)desc.MaxSlope;
    }

    /// <summary>The spot's scale: <c>max_scale</c> when min and max are equal, else the log-uniform
    /// <c>min · (max / min)^u(32593 + k)</c>, rounded to float.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="desc"/> is null.</exception>
    // retail: ObjectDesc::ScaleObj (acclient.c:351360)
    public static float ScaleObj(ObjectDesc desc, uint x, uint y, uint k)
    {
        ArgumentNullException.ThrowIfNull(desc);
        if (desc.MinScale == desc.MaxScale)
        {
            return desc.MaxScale;
        }

        return (float)(Math.Pow((double)desc.MaxScale / desc.MinScale, SceneryHash.Unit(x, y, SceneryHash.ScaleSalt + k)) * desc.MinScale);
    }

    /// <summary>The heading of (v.x, v.y, 0) in degrees clockwise from north; 0 when it is too short to normalise.</summary>
    // retail: AC1Legacy::Vector3::get_heading (acclient.c:148166)
    internal static double FlatHeading(Vector3 v)
    {
        Vector3 n = new(v.X, v.Y, 0f);
        if (VectorMath.NormalizeCheckSmall(ref n))
        {
            return 0.0;
        }

        return HeadingMath.CompassFromAtan2(Math.Atan2(n.Y, n.X));
    }
}
