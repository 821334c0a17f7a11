using System;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Objects.Parts;

/// <summary>
/// The collision geometry of an object's parts beyond its spheres, implemented by a part array that has it (retail
/// <c>CPartArray</c> / <c>CSetup</c> / <c>CPhysicsPart</c>): the setup's cylinder spheres, and the parts with a physics
/// BSP. <see cref="PhysicsObj.FindObjCollisions"/> asks the object's <see cref="PhysicsObj.PartArray"/> for it with a type
/// test; a part array without it has no cylinder spheres and no BSP parts. Called inside the tick: must not allocate.
/// </summary>
public interface IPartCollision
{
    /// <summary>The setup's cylinder spheres, object-local and unscaled (retail <c>CPartArray::GetCylsphere</c>,
    /// acclient.c:325375; count <c>GetNumCylsphere</c>, acclient.c:325369).</summary>
    ReadOnlySpan<CylSphere> CylSpheres { get; }

    /// <summary>The setup's sorting sphere, object-local (retail <c>CPartArray::GetSortingSphere</c>, acclient.c:326267):
    /// the sphere whose cells an object without cylinder spheres is shadowed in by <c>calc_cross_cells</c>.</summary>
    Sphere SortingSphere { get; }

    /// <summary>Number of parts that may carry a physics BSP (retail <c>num_parts</c>).</summary>
    int NumCollisionParts { get; }

    /// <summary>
    /// Tests part <paramref name="index"/> against the transition: when the part has a physics BSP, caches the check
    /// spheres in the part's space (<see cref="SpherePath.CacheLocalSpaceSphere"/> with the part's position and
    /// <c>gfxobj_scale.z</c>) and runs the BSP's object query; returns OK for a part without one.
    /// </summary>
    /// <remarks>This is the seam to the BSP module (retail <c>CPhysicsPart::find_obj_collisions</c>, acclient.c:314655 →
    /// <c>CGfxObj::find_obj_collisions</c>); <see cref="PhysicsPartCollision.FindObjCollisions"/> does the caching. The
    /// transition is engine-internal: the built-in part array answers with its BSP parts, and any other implementation
    /// answers OK (its parts carry no physics BSP).</remarks>
    internal TransitionState FindPartObjCollisions(int index, Transition transition) => TransitionState.Ok;

    /// <summary>Part <paramref name="index"/> with a physics BSP and where it stands now (the object's frame combined with the
    /// part's, as <see cref="FindPartObjCollisions"/> places it), for the debug view; null for a part without one (and for
    /// any other implementation).</summary>
    internal PhysicsPart? GetCollisionPart(int index, out Position pos)
    {
        pos = default;
        return null;
    }
}

/// <summary>Helpers for <see cref="IPartCollision"/> implementations.</summary>
public static class PhysicsPartCollision
{
    /// <summary>
    /// One part against a transition: caches the check spheres in the part's space and calls
    /// <paramref name="bspQuery"/> (the BSP module's object query on the part's physics BSP).
    /// </summary>
    /// <param name="partPosition">The part's position (retail <c>CPhysicsPart::pos</c>).</param>
    /// <param name="scaleZ">The part's <c>gfxobj_scale.z</c>.</param>
    /// <param name="transition">The transition being tested.</param>
    /// <param name="bspQuery">The BSP query, or null when the part has no physics BSP.</param>
    /// <param name="state">Passed to <paramref name="bspQuery"/> (the part's BSP, typically), so the query needs no closure.</param>
    // retail: CPhysicsPart::find_obj_collisions (acclient.c:314655)
    internal static TransitionState FindObjCollisions<TState>(in Position partPosition, float scaleZ, Transition transition,
        Func<TState, Transition, float, TransitionState>? bspQuery, TState state)
    {
        ArgumentNullException.ThrowIfNull(transition);
        if (bspQuery is null)
        {
            return TransitionState.Ok;
        }

        transition.SpherePath.CacheLocalSpaceSphere(partPosition, scaleZ);
        return bspQuery(state, transition, scaleZ);
    }
}
