using System;

namespace AcDream.Core.Physics.World;

/// <summary>
/// The effects a scene simulates, declared once per <see cref="PhysicsWorld"/> (<see cref="PhysicsWorld.Effects"/>).
/// <see cref="All"/> (the default) is retail. Leaving an effect out removes its cost for every object: the tick never
/// enters that code. Per object, an effect costs only when the object has the state or component it acts on (no spheres:
/// never swept; no position manager: never interpolated; no hooks: no hook walk).
/// </summary>
[Flags]
public enum SceneEffects
{
    /// <summary>Nothing but the time bookkeeping and orientation.</summary>
    None = 0,

    /// <summary>Gravity in <c>calc_acceleration</c> (objects with the GRAVITY state bit).</summary>
    Gravity = 1 << 0,

    /// <summary>Ground friction (<c>calc_friction</c>).</summary>
    Friction = 1 << 1,

    /// <summary>The collision sweep (<c>transition</c>). Without it, objects with spheres move freely (no sweep, no cells
    /// crossed but by re-homing), and no collision structures are consulted.</summary>
    Collision = 1 << 2,

    /// <summary>The position-manager family (interpolation, sticky, constraint): <c>adjust_offset</c> and <c>UseTime</c>.</summary>
    Interpolation = 1 << 3,

    /// <summary>Physics-object hooks (fades) and anim hooks (<c>process_hooks</c>).</summary>
    Hooks = 1 << 4,

    /// <summary>Animation root motion (<c>CPartArray::Update</c>) and the movement seams (movement manager, detection, targeting).</summary>
    RootMotion = 1 << 5,

    /// <summary>The particle and script seams.</summary>
    ParticlesAndScripts = 1 << 6,

    /// <summary>Every effect: retail.</summary>
    All = Gravity | Friction | Collision | Interpolation | Hooks | RootMotion | ParticlesAndScripts,
}
