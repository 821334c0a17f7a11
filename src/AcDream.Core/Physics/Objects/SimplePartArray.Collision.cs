using System;

namespace AcDream.Core.Physics;

/// <summary>The built-in part array's collision geometry beyond spheres: cylinder spheres and a sorting sphere (no BSP).</summary>
public sealed partial class SimplePartArray : IPartCollision
{
    private CylSphere[] _cylSpheres = Array.Empty<CylSphere>();

    /// <inheritdoc />
    public ReadOnlySpan<CylSphere> CylSpheres => _cylSpheres;

    /// <inheritdoc />
    /// <remarks>Default <see cref="Sphere.Dummy"/>.</remarks>
    public Sphere SortingSphere { get; set; } = Sphere.Dummy;

    /// <inheritdoc />
    /// <remarks>The built-in part array has no physics BSP: 0.</remarks>
    public int NumCollisionParts => 0;

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
    public TransitionState FindPartObjCollisions(int index, Transition transition) => TransitionState.Ok;
}
