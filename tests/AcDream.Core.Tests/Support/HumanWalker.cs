using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;

namespace AcDream.Core.Tests.Support;

/// <summary>A human-sized walker for the stair and cellar tests: the library's human Setup, <see cref="SetupPhysics.Human"/>
/// (radius 0.48 m, feet sphere centre 0.48 m up, head sphere centre 1.2 m up, step-up 0.6 m, step-down 1.5 m), in retail's
/// default state (EDGE_SLIDE included).</summary>
internal static class HumanWalker
{
    /// <summary>Sphere radius, metres (both spheres).</summary>
    public static float Radius => SetupPhysics.Human.Spheres[0].Radius;

    /// <summary>Height of the head sphere's centre above the origin, metres.</summary>
    public static float HeadCentre => SetupPhysics.Human.Spheres[1].Center.Z;

    /// <summary>The human's part array.</summary>
    public static SimplePartArray Parts() => new(SetupPhysics.Human);

    /// <summary>Creates and enters a human walker at <paramref name="p"/> (retail's default state unless given).</summary>
    public static PhysicsObj Create(PhysicsWorld world, in Position p, uint id = 1, PhysicsState? state = null) =>
        Walkers.Create(world, id, p, Parts(), state);
}
