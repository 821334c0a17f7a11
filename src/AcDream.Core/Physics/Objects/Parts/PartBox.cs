using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Objects.Parts;

/// <summary>
/// What a static object's cell list needs of one of its parts (retail <c>CPhysicsPart</c>'s <c>gfxobj[0]</c> bounding box,
/// its spheres, its placement frame and <c>Always2D</c>): the part's frame relative to the object, the GfxObj's bounding box
/// (<c>gfx_bound_box</c>, from its vertices, part-local and unscaled), whether it is drawn as a 2-D sprite, and the GfxObj's
/// physics sphere, else its drawing sphere (part-local, unscaled; null when it has neither).
/// </summary>
/// <param name="LocalFrame">The part's frame relative to the object (the setup's placement frame).</param>
/// <param name="Min">The bounding box's low corner, part-local.</param>
/// <param name="Max">The bounding box's high corner, part-local.</param>
/// <param name="Always2D">Retail <c>CPhysicsPart::Always2D</c>: the part's first level of detail is not a 3-D mesh.</param>
/// <param name="PartSphere">The GfxObj's <c>physics_sphere</c>, else its <c>drawing_sphere</c>; null when it has neither.</param>
internal readonly record struct PartBox(Frame LocalFrame, Vector3 Min, Vector3 Max, bool Always2D, Sphere? PartSphere);

/// <summary>One part of a static object placed in its landblock: its position, its GfxObj's bounding box (part-local),
/// whether it is drawn as a 2-D sprite and its GfxObj's physics sphere, else drawing sphere (part-local; retail
/// <c>CPhysicsPart</c>: <c>pos</c>, <c>GetBoundingBox</c>, <c>Always2D</c>, <c>gfxobj[0]->physics_sphere</c> /
/// <c>drawing_sphere</c>).</summary>
internal readonly record struct PlacedPartBox(Position Pos, Vector3 Min, Vector3 Max, bool Always2D, Sphere? PartSphere)
{
    /// <summary>The part sphere's radius (0 without one): what a 2-D part covers outdoors.</summary>
    public float Radius => PartSphere is { } s ? s.Radius : 0f;

    /// <summary>
    /// The part's bounding box taken into <paramref name="to"/>'s frame: each of its 8 corners through the part's position,
    /// then their bounds.
    /// </summary>
    // retail: BBox::LocalToLocal (acclient.c:476802) with CPhysicsPart::GetBoundingBox (acclient.c:314453)
    public void BoxIn(in Position to, out Vector3 min, out Vector3 max)
    {
        Vector3 a = Min, b = Max;
        min = to.LocalToLocal(Pos, a);
        max = min;
        Adjust(ref min, ref max, to.LocalToLocal(Pos, b));
        Adjust(ref min, ref max, to.LocalToLocal(Pos, new Vector3(b.X, b.Y, a.Z)));
        Adjust(ref min, ref max, to.LocalToLocal(Pos, new Vector3(b.X, a.Y, b.Z)));
        Adjust(ref min, ref max, to.LocalToLocal(Pos, new Vector3(a.X, b.Y, b.Z)));
        Adjust(ref min, ref max, to.LocalToLocal(Pos, new Vector3(a.X, b.Y, a.Z)));
        Adjust(ref min, ref max, to.LocalToLocal(Pos, new Vector3(b.X, a.Y, a.Z)));
        Adjust(ref min, ref max, to.LocalToLocal(Pos, new Vector3(a.X, a.Y, b.Z)));
    }

    // retail: BBox::AdjustBBox (acclient.c:356168)
    private static void Adjust(ref Vector3 min, ref Vector3 max, Vector3 v)
    {
        if (v.X < min.X)
        {
            min.X = v.X;
        }

        if (v.Y < min.Y)
        {
            min.Y = v.Y;
        }

        if (v.Z < min.Z)
        {
            min.Z = v.Z;
        }

        if (v.X > max.X)
        {
            max.X = v.X;
        }

        if (v.Y > max.Y)
        {
            max.Y = v.Y;
        }

        if (v.Z > max.Z)
        {
            max.Z = v.Z;
        }
    }
}
