using System;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Math;

namespace AcDream.Core.Physics.Objects.Parts;

// The built-in part array's collision geometry beyond spheres: cylinder spheres and a sorting sphere (no BSP).
public sealed partial class SimplePartArray : IPartCollision
{
    private CylSphere[] _cylSpheres = Array.Empty<CylSphere>();
    private PhysicsPart[] _physicsParts = Array.Empty<PhysicsPart>();
    private Frame[] _partFrames = Array.Empty<Frame>();

    /// <inheritdoc />
    public ReadOnlySpan<CylSphere> CylSpheres => _cylSpheres;

    /// <inheritdoc />
    /// <remarks>Default <see cref="Sphere.Dummy"/>. Valid domain: a finite centre and a positive finite radius.</remarks>
    /// <exception cref="ArgumentException">The centre is not finite or the radius not positive and finite (state unchanged).</exception>
    public Sphere SortingSphere
    {
        get => _sortingSphere;
        set
        {
            if (!VectorMath.IsFinite(value.Center) || !float.IsFinite(value.Radius) || !(value.Radius > 0f))
            {
                throw new ArgumentException("The sorting sphere needs a finite centre and a positive finite radius.", nameof(value));
            }

            Owner?.Touch();
            _sortingSphere = value;
        }
    }

    private Sphere _sortingSphere = Sphere.Dummy;

    /// <inheritdoc />
    /// <remarks>The parts given to <see cref="SetPhysicsParts"/> (none by default).</remarks>
    public int NumCollisionParts => _physicsParts.Length;

    /// <summary>
    /// Gives the object parts with a physics BSP: each part's graphics-object physics, its frame relative to the object and
    /// its scale. The object also needs <see cref="PhysicsState.HasPhysicsBsp"/> for sweeps to test them (retail
    /// <c>CPartArray::CacheHasPhysicsBSP</c>).
    /// </summary>
    /// <param name="gfxObjs">The parts' graphics-object physics.</param>
    /// <param name="localFrames">Each part's frame relative to the object: a unit quaternion, each origin component within
    /// ±<see cref="InputLimits.MaxChildOffset"/> (192 m).</param>
    /// <param name="scales">Each part's scale: components in [<see cref="InputLimits.MinScale"/>,
    /// <see cref="InputLimits.MaxScale"/>] = [0.01, 100].</param>
    /// <exception cref="ArgumentException">The spans differ in length, or a frame or scale is outside its domain (state
    /// unchanged).</exception>
    public void SetPhysicsParts(ReadOnlySpan<GfxObjPhysics> gfxObjs, ReadOnlySpan<Frame> localFrames, ReadOnlySpan<System.Numerics.Vector3> scales)
    {
        if (gfxObjs.Length != localFrames.Length || gfxObjs.Length != scales.Length)
        {
            throw new ArgumentException("One frame and one scale per part.", nameof(localFrames));
        }

        for (int i = 0; i < localFrames.Length; i++)
        {
            // non-retail: a part's offset has the child frame's domain
            if (!InputLimits.IsChildFrameInDomain(localFrames[i]))
            {
                throw new ArgumentException("Part frames need a unit quaternion and an offset within ±192 m.", nameof(localFrames));
            }
        }

        var parts = new PhysicsPart[gfxObjs.Length];
        for (int i = 0; i < parts.Length; i++)
        {
            parts[i] = new PhysicsPart(gfxObjs[i], new Position(CellId, Frame.Combined(Frame, localFrames[i])), scales[i]);
        }

        _physicsParts = parts;
        _partFrames = localFrames.ToArray();
    }

    /// <summary>Replaces the cylinder spheres (a setup's list; object-local, unscaled).</summary>
    /// <exception cref="ArgumentException">A value is NaN or infinite, or a radius or height is not positive.</exception>
    public void SetCylSpheres(ReadOnlySpan<CylSphere> cylSpheres)
    {
        for (int i = 0; i < cylSpheres.Length; i++)
        {
            CylSphere c = cylSpheres[i];
            if (!VectorMath.IsFinite(c.LowPt) || !float.IsFinite(c.Radius) || !float.IsFinite(c.Height) || !(c.Radius > 0f) || !(c.Height > 0f))
            {
                throw new ArgumentException("Cylinder spheres need a finite low point and positive finite radius and height.", nameof(cylSpheres));
            }
        }

        _cylSpheres = cylSpheres.ToArray();
    }

    /// <inheritdoc />
    /// <remarks>The part is placed at the object's current frame combined with its local frame (retail keeps the parts
    /// placed by <c>CPartArray::SetFrame</c>; the built-in part array places them when asked), then the BSP module's
    /// <see cref="PhysicsPart.FindObjCollisions"/> runs.</remarks>
    // retail: CPhysicsPart::find_obj_collisions (acclient.c:314655), reached from CPartArray::FindObjCollisions (acclient.c:325463)
    TransitionState IPartCollision.FindPartObjCollisions(int index, Transition transition)
    {
        ArgumentNullException.ThrowIfNull(transition);
        if ((uint)index >= (uint)_physicsParts.Length)
        {
            return TransitionState.Ok;
        }

        PhysicsPart part = _physicsParts[index];
        part.SetPosition(new Position(CellId, Frame.Combined(Frame, _partFrames[index])));
        return part.FindObjCollisions(transition);
    }
}
