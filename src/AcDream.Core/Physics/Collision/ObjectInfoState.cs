using System;

namespace AcDream.Core.Physics.Collision;

/// <summary>
/// What the sweep knows about the moving object. Retail: <c>enum ObjectInfoEnum</c> (acclient.h:6180), the
/// <c>OBJECTINFO::state</c> bits built by <c>CPhysicsObj::get_object_info</c> (acclient.c:319073).
/// </summary>
[Flags]
internal enum ObjectInfoState : uint
{
    /// <summary>No bits (retail <c>DEFAULT_OI</c>).</summary>
    None = 0x0,

    /// <summary>The object starts the sweep touching a contact plane (retail <c>CONTACT_OI</c>).</summary>
    Contact = 0x1,

    /// <summary>That contact plane is walkable (retail <c>ON_WALKABLE_OI</c>).</summary>
    OnWalkable = 0x2,

    /// <summary>The camera sweep (retail <c>IS_VIEWER_OI</c>): floor-plus-one steps, no stationary-fall bookkeeping.</summary>
    IsViewer = 0x4,

    /// <summary>Stop the sweep at the first collision (retail <c>PATH_CLIPPED_OI</c>, set for missiles).</summary>
    PathClipped = 0x8,

    /// <summary>The rotation is taken from the end position at once instead of being slerped per step (retail <c>FREE_ROTATE_OI</c>).</summary>
    FreeRotate = 0x10,

    /// <summary>Retail <c>PERFECT_CLIP_OI</c>.</summary>
    PerfectClip = 0x40,

    /// <summary>Retail <c>IS_IMPENETRABLE</c> (from the weenie).</summary>
    IsImpenetrable = 0x80,

    /// <summary>Retail <c>IS_PLAYER</c> (from the weenie).</summary>
    IsPlayer = 0x100,

    /// <summary>The object slides along edges and cliffs instead of walking off them (retail <c>EDGE_SLIDE</c>, from <c>EDGE_SLIDE_PS</c>).</summary>
    EdgeSlide = 0x200,

    /// <summary>Retail <c>IGNORE_CREATURES</c>.</summary>
    IgnoreCreatures = 0x400,

    /// <summary>Retail <c>IS_PK</c> (from the weenie).</summary>
    IsPK = 0x800,

    /// <summary>Retail <c>IS_PKLITE</c> (from the weenie).</summary>
    IsPKLite = 0x1000,
}
