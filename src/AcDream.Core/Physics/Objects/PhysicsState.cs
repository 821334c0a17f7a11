using System;

namespace AcDream.Core.Physics.Objects;

/// <summary>
/// The persistent state bits of a physics object (retail <c>PhysicsState</c>, acclient.h:2815).
/// Values are retail's and must not change.
/// </summary>
[Flags]
public enum PhysicsState : uint
{
    /// <summary>No bit set.</summary>
    None = 0,

    /// <summary>STATIC_PS: never simulated; <c>set_active</c> refuses to activate it.</summary>
    Static = 0x1,

    /// <summary>UNUSED1_PS.</summary>
    Unused1 = 0x2,

    /// <summary>ETHEREAL_PS: passes through other objects.</summary>
    Ethereal = 0x4,

    /// <summary>REPORT_COLLISIONS_PS.</summary>
    ReportCollisions = 0x8,

    /// <summary>IGNORE_COLLISIONS_PS.</summary>
    IgnoreCollisions = 0x10,

    /// <summary>NODRAW_PS.</summary>
    NoDraw = 0x20,

    /// <summary>MISSILE_PS.</summary>
    Missile = 0x40,

    /// <summary>PUSHABLE_PS.</summary>
    Pushable = 0x80,

    /// <summary>ALIGNPATH_PS: the object turns to face its direction of travel each step.</summary>
    AlignPath = 0x100,

    /// <summary>PATHCLIPPED_PS.</summary>
    PathClipped = 0x200,

    /// <summary>GRAVITY_PS: <c>calc_acceleration</c> applies gravity.</summary>
    Gravity = 0x400,

    /// <summary>LIGHTING_ON_PS.</summary>
    LightingOn = 0x800,

    /// <summary>PARTICLE_EMITTER_PS: the part array does not follow the object's frame.</summary>
    ParticleEmitter = 0x1000,

    /// <summary>UNNUSED2_PS (retail's spelling).</summary>
    Unused2 = 0x2000,

    /// <summary>HIDDEN_PS: neither the part array nor physics runs in UpdatePositionInternal.</summary>
    Hidden = 0x4000,

    /// <summary>SCRIPTED_COLLISION_PS.</summary>
    ScriptedCollision = 0x8000,

    /// <summary>HAS_PHYSICS_BSP_PS.</summary>
    HasPhysicsBsp = 0x10000,

    /// <summary>INELASTIC_PS.</summary>
    Inelastic = 0x20000,

    /// <summary>HAS_DEFAULT_ANIM_PS.</summary>
    HasDefaultAnim = 0x40000,

    /// <summary>HAS_DEFAULT_SCRIPT_PS.</summary>
    HasDefaultScript = 0x80000,

    /// <summary>CLOAKED_PS.</summary>
    Cloaked = 0x100000,

    /// <summary>REPORT_COLLISIONS_AS_ENVIRONMENT_PS.</summary>
    ReportCollisionsAsEnvironment = 0x200000,

    /// <summary>EDGE_SLIDE_PS.</summary>
    EdgeSlide = 0x400000,

    /// <summary>SLEDDING_PS: sledding friction and velocity heading (the decompilation prints this mask as a string address).</summary>
    Sledding = 0x800000,

    /// <summary>FROZEN_PS: update_object does nothing (not HIDDEN_PS, which is 0x4000).</summary>
    Frozen = 0x1000000,
}
