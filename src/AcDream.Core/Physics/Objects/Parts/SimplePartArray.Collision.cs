using System;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using System.Numerics;

namespace AcDream.Core.Physics.Objects.Parts;

// The built-in part array's collision geometry beyond spheres: cylinder spheres and a sorting sphere (no BSP).
public sealed partial class SimplePartArray : IPartCollision
{
    private CylSphere[] _cylSpheres = Array.Empty<CylSphere>();
    // The parts with a physics BSP and their local frames, null until SetPhysicsParts (most objects have none).
    // With the sorting sphere, in one side object created when either is set (at setup, never in a tick), so that an
    // object with neither pays one reference.
    private CollisionExtras? _extras;

    /// <inheritdoc />
    public ReadOnlySpan<CylSphere> CylSpheres => _cylSpheres;

    /// <inheritdoc />
    /// <remarks>Default <see cref="Sphere.Dummy"/>. Valid domain: a finite centre and a positive finite radius.</remarks>
    /// <exception cref="ArgumentException">The centre is not finite or the radius not positive and finite (state unchanged).</exception>
    public Sphere SortingSphere
    {
        get => _extras?.SortingSphere ?? Sphere.Dummy;
        set
        {
            if (!VectorMath.IsFinite(value.Center) || !float.IsFinite(value.Radius) || !(value.Radius > 0f))
            {
                throw new ArgumentException("The sorting sphere needs a finite centre and a positive finite radius.", nameof(value));
            }

            Owner?.Touch();
            (_extras ??= new CollisionExtras()).SortingSphere = value;
        }
    }


    /// <inheritdoc />
    /// <remarks>The parts given to <see cref="SetPhysicsParts"/> (none by default).</remarks>
    public int NumCollisionParts => _extras?.Bsp?.Parts.Length ?? 0;

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

        (_extras ??= new CollisionExtras()).Bsp = new BspParts(parts, localFrames.ToArray(), scales.ToArray());
        if (Scale != 1f)
        {
            ScaleBspParts(Scale);
        }
    }

    // Each BSP part's scale: the object's scale times the part's default scale, in retail's order (z, y, then x).
    // retail: CPartArray::SetScaleInternal (acclient.c:326181), the part loop
    private void ScaleBspParts(float scale)
    {
        BspParts? bsp = _extras?.Bsp;
        if (bsp is null)
        {
            return;
        }

        for (int i = 0; i < bsp.Parts.Length; i++)
        {
            Vector3 d = bsp.DefaultScales[i];
            float z = d.Z * scale;
            float y = d.Y * scale;
            float x = d.X * scale;
            bsp.Parts[i].GfxObjScale = new Vector3(x, y, z);
        }
    }

    /// <summary>Replaces the cylinder spheres (a setup's list; object-local, unscaled).</summary>
    /// <param name="cylSpheres">The cylinder spheres: each with a finite low point, a positive radius and height, and
    /// |low point| + radius + height at most <see cref="InputLimits.MaxShapeReach"/> (192 m).</param>
    /// <exception cref="ArgumentException">A cylinder sphere is outside that domain (a value NaN or infinite, a radius or
    /// height not positive, or a reach beyond 192 m; the message names its index); nothing changes.</exception>
    public void SetCylSpheres(ReadOnlySpan<CylSphere> cylSpheres)
    {
        // non-retail: the shapes' domain (see InputLimits.MaxShapeReach)
        CylSphere.ThrowIfAnyOutside(cylSpheres, nameof(cylSpheres));

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
            Owner?.SyncObstacleSummary();
            return;
        }

        double reach = 0.0;
        foreach (Sphere s in _spheres)
        {
            double r = (double)Math.Abs(s.Center.X) + Math.Abs(s.Center.Y) + Math.Abs(s.Center.Z) + Math.Abs(s.Radius);
            reach = Math.Max(reach, r);
        }

        // Rounded up to the next float, so that the stored value never falls short of the double bound.
        ObstacleReach = RoundUpToFloat(reach);
        Owner?.SyncObstacleSummary();
    }

    /// <summary><paramref name="value"/> rounded to the nearest float at or above it (a stored bound never falls short of
    /// the double one).</summary>
    internal static float RoundUpToFloat(double value)
    {
        float f = (float)value;
        return f < value ? MathF.BitIncrement(f) : f;
    }

    /// <inheritdoc />
    /// <remarks>The part is placed at the object's current frame combined with its local frame (retail keeps the parts
    /// placed by <c>CPartArray::SetFrame</c>; the built-in part array places them when asked), then the BSP module's
    /// <see cref="PhysicsPart.FindObjCollisions"/> runs.</remarks>
    // retail: CPhysicsPart::find_obj_collisions (acclient.c:314655), reached from CPartArray::FindObjCollisions (acclient.c:325463)
    TransitionState IPartCollision.FindPartObjCollisions(int index, Transition transition)
    {
        ArgumentNullException.ThrowIfNull(transition);
        BspParts? bsp = _extras?.Bsp;
        if (bsp is null || (uint)index >= (uint)bsp.Parts.Length)
        {
            return TransitionState.Ok;
        }

        PhysicsPart part = bsp.Parts[index];
        part.SetPosition(new Position(CellId, PartFrame(bsp.Frames[index])));
        return part.FindObjCollisions(transition);
    }

    /// <inheritdoc />
    PhysicsPart? IPartCollision.GetCollisionPart(int index, out Position pos)
    {
        BspParts? bsp = _extras?.Bsp;
        if (bsp is null || (uint)index >= (uint)bsp.Parts.Length)
        {
            pos = default;
            return null;
        }

        pos = new Position(CellId, PartFrame(bsp.Frames[index]));
        return bsp.Parts[index];
    }

    // The object's frame combined with a part's local frame, its origin scaled by the object's scale (retail
    // CPartArray::UpdateParts scales each part's origin; at scale 1 the product is the origin itself).
    private Frame PartFrame(in Frame local)
    {
        if (Scale == 1f)
        {
            return Frame.Combined(Frame, local);
        }

        Frame scaled = local;
        Vector3 o = local.Origin;
        scaled.Origin = new Vector3(o.X * Scale, o.Y * Scale, o.Z * Scale);
        return Frame.Combined(Frame, scaled);
    }

    private sealed record BspParts(PhysicsPart[] Parts, Frame[] Frames, Vector3[] DefaultScales);

    private sealed class CollisionExtras
    {
        public Sphere SortingSphere = Sphere.Dummy;

        public BspParts? Bsp;
    }
}
