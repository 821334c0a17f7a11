using System;

namespace AcDream.Core.Physics.Motion.Wire;

/// <summary>The flag word of a <see cref="PhysicsDesc"/> (retail <c>PhysicsDesc::bitfield</c>): which optional fields the
/// CreateObject's physics description carries. Retail <c>PhysicsDesc::UnPack</c> (acclient.c:331864) reads them in the
/// order movement / animation frame, position, motion table, sound table, physics script table, setup, parent, children,
/// scale, friction, elasticity, translucency, velocity, acceleration, omega, default script, its intensity, then the nine
/// timestamps.</summary>
[Flags]
public enum PhysicsDescFlags : uint
{
    /// <summary>No optional field.</summary>
    None = 0,

    /// <summary>0x1: the Setup id.</summary>
    Setup = 0x1,

    /// <summary>0x2: the motion table id.</summary>
    MotionTable = 0x2,

    /// <summary>0x4: the velocity.</summary>
    Velocity = 0x4,

    /// <summary>0x8: the acceleration.</summary>
    Acceleration = 0x8,

    /// <summary>0x10: the omega.</summary>
    Omega = 0x10,

    /// <summary>0x20: the parent and the holding location.</summary>
    Parent = 0x20,

    /// <summary>0x40: the children (ids and holding locations).</summary>
    Children = 0x40,

    /// <summary>0x80: the object scale.</summary>
    ObjScale = 0x80,

    /// <summary>0x100: the friction.</summary>
    Friction = 0x100,

    /// <summary>0x200: the elasticity.</summary>
    Elasticity = 0x200,

    /// <summary>0x400: set by servers; retail reads the timestamps whatever this bit says.</summary>
    Timestamps = 0x400,

    /// <summary>0x800: the sound table id.</summary>
    SoundTable = 0x800,

    /// <summary>0x1000: the physics script table id.</summary>
    PhysicsScriptTable = 0x1000,

    /// <summary>0x2000: the default script.</summary>
    DefaultScript = 0x2000,

    /// <summary>0x4000: the default script's intensity.</summary>
    DefaultScriptIntensity = 0x4000,

    /// <summary>0x8000: the position (cell and frame).</summary>
    Position = 0x8000,

    /// <summary>0x10000: the movement buffer (a MovementEvent's movement data) and the autonomous flag.</summary>
    Movement = 0x10000,

    /// <summary>0x20000: the animation (placement) frame id (read only without <see cref="Movement"/>).</summary>
    AnimationFrame = 0x20000,

    /// <summary>0x40000: the translucency.</summary>
    Translucency = 0x40000,
}
