using System;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Objects.Parts;

/// <summary>
/// One placed part of an object (or a building) as a collision body: its graphics object's physics, where the part is
/// (a position in a landblock) and its scale. Retail: <c>CPhysicsPart</c> (PORTAL/cphysobj/CPhysicsPart.c), the fields
/// the collision query reads (<c>gfxobj</c>, <c>pos</c>, <c>gfxobj_scale</c>).
/// </summary>
/// <remarks>This is the BSP entry point for object-to-object collision: call <see cref="FindObjCollisions"/> for each
/// part of a shadow object with the part's current position.</remarks>
public sealed class PhysicsPart
{
    private Position _pos;

    /// <summary>Creates a part.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="gfxObj"/> is null.</exception>
    /// <param name="gfxObj">The graphics object's physics.</param>
    /// <param name="pos">Where the part is: a finite origin and a unit quaternion.</param>
    /// <param name="scale">The part's scale: each component in [<see cref="InputLimits.MinScale"/>,
    /// <see cref="InputLimits.MaxScale"/>] = [0.01, 100].</param>
    /// <exception cref="ArgumentException">The position or scale is not valid (non-finite position or rotation, or a scale
    /// component outside [0.01, 100]).</exception>
    public PhysicsPart(GfxObjPhysics gfxObj, in Position pos, Vector3 scale)
    {
        ArgumentNullException.ThrowIfNull(gfxObj);
        // non-retail: the object scale's domain for each component (a subnormal one divides the cached spheres to infinity)
        if (!InputLimits.IsScaleInDomain(scale.X) || !InputLimits.IsScaleInDomain(scale.Y) || !InputLimits.IsScaleInDomain(scale.Z))
        {
            throw new ArgumentException("Each scale component must be in [0.01, 100].", nameof(scale));
        }

        GfxObj = gfxObj;
        SetPosition(pos);

        GfxObjScale = scale;
    }

    /// <summary>The part's graphics object physics. Retail: <c>gfxobj</c>.</summary>
    public GfxObjPhysics GfxObj { get; }

    /// <summary>Where the part is (cell id and frame in its landblock). Retail: <c>pos</c>.</summary>
    public ref readonly Position Pos => ref _pos;

    /// <summary>The part's scale; the collision uses its z. Retail: <c>gfxobj_scale</c>.</summary>
    public Vector3 GfxObjScale { get; internal set; }

    /// <summary>Moves the part.</summary>
    /// <exception cref="ArgumentException">The frame is not finite.</exception>
    public void SetPosition(in Position pos)
    {
        if (!VectorMath.IsFinite(pos.Frame.Origin) || !pos.Frame.IsValid())
        {
            throw new ArgumentException("The part position must be finite with a valid rotation.", nameof(pos));
        }

        _pos = pos;
    }

    /// <summary>
    /// The transition's spheres against this part: they are cached in the part's space (divided by the scale's z) and
    /// tested against the graphics object's physics BSP.
    /// </summary>
    // retail: CPhysicsPart::find_obj_collisions (acclient.c:314655)
    internal TransitionState FindObjCollisions(Transition transition)
    {
        ArgumentNullException.ThrowIfNull(transition);
        transition.SpherePath.CacheLocalSpaceSphere(_pos, GfxObjScale.Z);
        return GfxObj.FindObjCollisions(transition, GfxObjScale.Z);
    }
}
