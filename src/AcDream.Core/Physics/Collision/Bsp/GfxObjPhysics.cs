using System;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Collision.Bsp;

/// <summary>
/// The physics half of a graphics object (a part's mesh): its physics BSP and the sphere bounding it, in part-local
/// space. Retail: <c>CGfxObj</c>'s <c>physics_bsp</c> and <c>physics_sphere</c> (PORTAL/gfxobj/CGfxObj.c).
/// </summary>
public sealed class GfxObjPhysics
{
    /// <summary>Creates the physics of a graphics object; the bounding sphere defaults to the BSP root's sphere.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="physicsBsp"/> is null.</exception>
    /// <exception cref="ArgumentException">The bounding sphere is not finite or has a negative radius.</exception>
    public GfxObjPhysics(BspTree physicsBsp, Sphere? physicsSphere = null)
    {
        ArgumentNullException.ThrowIfNull(physicsBsp);
        Sphere s = physicsSphere ?? physicsBsp.Sphere;
        if (!VectorMath.IsFinite(s.Center) || !float.IsFinite(s.Radius) || s.Radius < 0f)
        {
            throw new ArgumentException("The physics sphere must be finite with a radius >= 0.", nameof(physicsSphere));
        }

        PhysicsBsp = physicsBsp;
        PhysicsSphere = s;
    }

    /// <summary>The physics BSP, part-local. Retail: <c>physics_bsp</c>.</summary>
    public BspTree PhysicsBsp { get; }

    /// <summary>The sphere bounding the physics geometry, part-local. Retail: <c>physics_sphere</c>.</summary>
    public Sphere PhysicsSphere { get; }

    /// <summary>
    /// The transition's local-space spheres (already cached in this object's space) against the BSP, when any of them
    /// meets <see cref="PhysicsSphere"/>: placement for an initial placement, otherwise the sweep's
    /// <see cref="BspTree.FindCollisions"/>. OK when none meets the sphere.
    /// </summary>
    // retail: CGfxObj::find_obj_collisions (acclient.c:356514)
    internal TransitionState FindObjCollisions(Transition transition, float scale)
    {
        ArgumentNullException.ThrowIfNull(transition);
        SpherePath path = transition.SpherePath;
        for (int i = 0; i < path.NumSphere; i++)
        {
            if (PhysicsSphere.Intersects(path.LocalSpaceSphere[i]))
            {
                return path.InsertType == InsertType.InitialPlacement
                    ? PhysicsBsp.PlacementInsert(transition)
                    : PhysicsBsp.FindCollisions(transition, scale);
            }
        }

        return TransitionState.Ok;
    }
}
