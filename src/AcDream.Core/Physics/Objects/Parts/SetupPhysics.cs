using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Objects.Parts;

/// <summary>
/// The physics fields of a Setup (retail <c>CSetup</c>, the 0x02xxxxxx records of <c>client_portal.dat</c>): collision spheres,
/// cylinder spheres, bounding radius and height, and the step-up and step-down heights. A client reads them from the object's
/// Setup and builds its part array from them (<see cref="SimplePartArray(SetupPhysics, int)"/>); <see cref="Human"/> holds the
/// values of the human character Setup 0x02000001.
/// </summary>
/// <remarks>Immutable: the spans are copies taken at construction, so one instance can be shared by many objects and
/// worlds.</remarks>
public sealed class SetupPhysics
{
    private readonly Sphere[] _spheres;
    private readonly CylSphere[] _cylSpheres;

    /// <summary>Creates a setup's physics fields (object-local, unscaled, metres).</summary>
    /// <param name="spheres">Collision spheres (retail <c>CSetup::sphere</c>): the domain of
    /// <see cref="SimplePartArray.SetSpheres"/> (|centre| + radius at most <see cref="InputLimits.MaxShapeReach"/>, 192 m).</param>
    /// <param name="cylSpheres">Cylinder spheres (retail <c>CSetup::cylsphere</c>): the domain of
    /// <see cref="SimplePartArray.SetCylSpheres"/> (|low point| + radius + height at most 192 m).</param>
    /// <param name="radius">Bounding radius (retail <c>CSetup::radius</c>): finite, not negative.</param>
    /// <param name="height">Height (retail <c>CSetup::height</c>): finite, not negative.</param>
    /// <param name="stepUpHeight">Step-up height (retail <c>CSetup::step_up_height</c>): in [0, 192] m
    /// (<see cref="InputLimits.MaxStepHeight"/>).</param>
    /// <param name="stepDownHeight">Step-down height (retail <c>CSetup::step_down_height</c>): in [0, 192] m.</param>
    /// <exception cref="ArgumentException">A value is outside its domain: NaN or infinite, a sphere or cylinder radius or a
    /// cylinder height not positive, a shape reaching beyond 192 m, a size negative or a step height above 192 m.</exception>
    public SetupPhysics(ReadOnlySpan<Sphere> spheres, ReadOnlySpan<CylSphere> cylSpheres, float radius, float height,
        float stepUpHeight, float stepDownHeight)
    {
        // non-retail: the shapes' and step heights' domains (see InputLimits.MaxShapeReach, MaxStepHeight)
        Sphere.ThrowIfAnyOutside(spheres, nameof(spheres));
        CylSphere.ThrowIfAnyOutside(cylSpheres, nameof(cylSpheres));
        Check(radius, nameof(radius));
        Check(height, nameof(height));
        InputLimits.ThrowIfStepHeightOutside(stepUpHeight, nameof(stepUpHeight));
        InputLimits.ThrowIfStepHeightOutside(stepDownHeight, nameof(stepDownHeight));
        _spheres = spheres.ToArray();
        _cylSpheres = cylSpheres.ToArray();
        Radius = radius;
        Height = height;
        StepUpHeight = stepUpHeight;
        StepDownHeight = stepDownHeight;
    }

    /// <summary>
    /// The human character Setup 0x02000001 (every player and human creature): two spheres of radius 0.48 m, centred
    /// 0.48 m (feet) and 1.2 m (head) above the origin, no cylinder spheres, bounding radius 0.48 m, height 1.835 m, step-up
    /// 0.6 m and step-down 1.5 m. Sources are listed in <c>docs/getting-started.md</c> ("The human setup").
    /// </summary>
    public static SetupPhysics Human { get; } = new(
        new[] { new Sphere(new Vector3(0f, 0f, 0.48f), 0.48f), new Sphere(new Vector3(0f, 0f, 1.2f), 0.48f) },
        ReadOnlySpan<CylSphere>.Empty,
        radius: 0.48f,
        height: 1.835f,
        stepUpHeight: 0.6f,
        stepDownHeight: 1.5f);

    /// <summary>Collision spheres, object-local and unscaled.</summary>
    public ReadOnlySpan<Sphere> Spheres => _spheres;

    /// <summary>Cylinder spheres, object-local and unscaled.</summary>
    public ReadOnlySpan<CylSphere> CylSpheres => _cylSpheres;

    /// <summary>Bounding radius, metres.</summary>
    public float Radius { get; }

    /// <summary>Height, metres.</summary>
    public float Height { get; }

    /// <summary>Step-up height, metres: the highest ledge a walk climbs.</summary>
    public float StepUpHeight { get; }

    /// <summary>Step-down height, metres: the deepest drop a walk follows without leaving the ground.</summary>
    public float StepDownHeight { get; }

    private static void Check(float value, string name)
    {
        if (!float.IsFinite(value) || value < 0f)
        {
            throw new ArgumentException("Setup sizes must be finite and not negative.", name);
        }
    }
}
