using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;

namespace AcDream.Core.Tests.Support;

/// <summary>A human-sized walker for the stair and cellar tests.</summary>
/// <remarks>Local values until the library has a human setup preset (another change adds one): radius 0.48 m, height
/// 1.835 m as two spheres (feet centre 0.48 m up, head centre 1.835 - 0.48 = 1.355 m up), step-up 0.6 m, step-down 1.5 m,
/// retail's default state (EDGE_SLIDE included).</remarks>
internal static class HumanWalker
{
    /// <summary>Sphere radius, metres.</summary>
    public const float Radius = 0.48f;

    /// <summary>Height (top of the head sphere), metres.</summary>
    public const float Height = 1.835f;

    /// <summary>Step-up height, metres.</summary>
    public const float StepUp = 0.6f;

    /// <summary>Step-down height, metres.</summary>
    public const float StepDown = 1.5f;

    /// <summary>The human's part array (two spheres and the step heights above).</summary>
    public static SimplePartArray Parts()
    {
        var parts = new SimplePartArray(1, 0) { StepUpHeight = StepUp, StepDownHeight = StepDown };
        parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, Radius), Radius), new Sphere(new Vector3(0f, 0f, Height - Radius), Radius) });
        return parts;
    }

    /// <summary>Creates and enters a human walker at <paramref name="p"/> (retail's default state unless given).</summary>
    public static PhysicsObj Create(PhysicsWorld world, in Position p, uint id = 1, PhysicsState? state = null) =>
        Walkers.Create(world, id, p, Parts(), state);
}
