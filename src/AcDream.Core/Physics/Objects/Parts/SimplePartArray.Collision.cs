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
    // The parts with a physics BSP and their local frames, null until SetPhysicsParts (most objects have none).
    private BspParts? _bspParts;

    /// <inheritdoc />
    public ReadOnlySpan<CylSphere> CylSpheres => _cylSpheres;

    /// <inheritdoc />
    /// <remarks>Default <see cref="Sphere.Dummy"/>.</remarks>
    public Sphere SortingSphere { get; set; } = Sphere.Dummy;

    /// <inheritdoc />
    /// <remarks>The parts given to <see cref="SetPhysicsParts"/> (none by default).</remarks>
    public int NumCollisionParts => _bspParts?.Parts.Length ?? 0;

    /// <summary>
    /// Gives the object parts with a physics BSP: each part's graphics-object physics, its frame relative to the object and
    /// its scale. The object also needs <see cref="PhysicsState.HasPhysicsBsp"/> for sweeps to test them (retail
    /// <c>CPartArray::CacheHasPhysicsBSP</c>).
    /// </summary>
    /// <exception cref="ArgumentException">The spans differ in length, or a frame or scale is not valid.</exception>
    public void SetPhysicsParts(ReadOnlySpan<GfxObjPhysics> gfxObjs, ReadOnlySpan<Frame> localFrames, ReadOnlySpan<System.Numerics.Vector3> scales)
    {
        if (gfxObjs.Length != localFrames.Length || gfxObjs.Length != scales.Length)
        {
            throw new ArgumentException("One frame and one scale per part.", nameof(localFrames));
        }

        var parts = new PhysicsPart[gfxObjs.Length];
        for (int i = 0; i < parts.Length; i++)
        {
            parts[i] = new PhysicsPart(gfxObjs[i], new Position(CellId, Frame.Combined(Frame, localFrames[i])), scales[i]);
        }

        _bspParts = new BspParts(parts, localFrames.ToArray());
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
        UpdateObstacleReach();
    }

    /// <summary>
    /// How far, in metres at scale 1, the collision spheres reach from the object's origin whatever its orientation: the
    /// largest |c.x| + |c.y| + |c.z| + r (which bounds |c| + r); 0 without spheres, and -1 with cylinder spheres (the
    /// object's shapes are then not only spheres). Kept up to date by the constructor, <see cref="SetSpheres"/> and
    /// <see cref="SetCylSpheres"/>, so that a sweep can skip an obstacle out of reach without reading its spheres
    /// (<see cref="PhysicsObj.IsOutOfReach"/>).
    /// </summary>
    internal float ObstacleReach { get; private set; }

    private void UpdateObstacleReach()
    {
        if (_cylSpheres.Length != 0)
        {
            ObstacleReach = -1f;
            return;
        }

        double reach = 0.0;
        foreach (Sphere s in _spheres)
        {
            double r = (double)System.Math.Abs(s.Center.X) + System.Math.Abs(s.Center.Y) + System.Math.Abs(s.Center.Z) + System.Math.Abs(s.Radius);
            reach = System.Math.Max(reach, r);
        }

        // Rounded up to the next float, so that the stored value never falls short of the double bound.
        float f = (float)reach;
        ObstacleReach = f < reach ? MathF.BitIncrement(f) : f;
    }

    /// <inheritdoc />
    /// <remarks>The part is placed at the object's current frame combined with its local frame (retail keeps the parts
    /// placed by <c>CPartArray::SetFrame</c>; the built-in part array places them when asked), then the BSP module's
    /// <see cref="PhysicsPart.FindObjCollisions"/> runs.</remarks>
    // retail: CPhysicsPart::find_obj_collisions (acclient.c:314655), reached from CPartArray::FindObjCollisions (acclient.c:325463)
    TransitionState IPartCollision.FindPartObjCollisions(int index, Transition transition)
    {
        ArgumentNullException.ThrowIfNull(transition);
        BspParts? bsp = _bspParts;
        if (bsp is null || (uint)index >= (uint)bsp.Parts.Length)
        {
            return TransitionState.Ok;
        }

        PhysicsPart part = bsp.Parts[index];
        part.SetPosition(new Position(CellId, Frame.Combined(Frame, bsp.Frames[index])));
        return part.FindObjCollisions(transition);
    }

    private sealed record BspParts(PhysicsPart[] Parts, Frame[] Frames);
}
