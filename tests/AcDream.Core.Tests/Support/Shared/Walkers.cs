using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Tests.Support.Shared;

/// <summary>
/// The walker builder of the tests and the benchmarks (compiled into both; no xunit here): a creature with a movement
/// manager (so that it stays active) that enters the world by placement.
/// </summary>
internal static class Walkers
{
    /// <summary>A part array with one sphere of radius <paramref name="radius"/> resting on the origin (centre (0, 0, r)) and
    /// the given step heights.</summary>
    public static SimplePartArray OneSphere(float radius = 0.5f, float stepUp = 0.6f, float stepDown = 0.6f)
    {
        var parts = new SimplePartArray(1, 0)
        {
            StepUpHeight = stepUp,
            StepDownHeight = stepDown,
        };
        parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, radius), radius) });
        return parts;
    }

    /// <summary>
    /// Creates object <paramref name="id"/> with <paramref name="weenie"/> (none when null), <paramref name="parts"/>, a movement
    /// manager and <paramref name="state"/> (retail's default when null), and enters it into the world at <paramref name="p"/>
    /// (placement with slide, then a step down onto the ground); throws when it cannot enter.
    /// </summary>
    public static PhysicsObj Create(PhysicsWorld world, uint id, in Position p, SimplePartArray parts, PhysicsState? state = null,
        IWeenieObject? weenie = null)
    {
        PhysicsObj obj = world.CreateObject(id);
        if (weenie is not null)
        {
            obj.Weenie = weenie;
        }

        obj.PartArray = parts;
        obj.Movement = new BasicMovementManager();
        if (state is not null)
        {
            obj.SetState(state.Value);
        }

        if (!obj.EnterWorld(p))
        {
            throw new InvalidOperationException($"Walker {id} could not enter the world at {p}.");
        }

        return obj;
    }
}
