using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Managers;

/// <summary>Kind of an <see cref="InterpolationNode"/> (retail <c>InterpolationNode::type</c>, acclient.h:58208).</summary>
internal enum InterpolationNodeType : uint
{
    /// <summary>No node (retail's constructor value); never queued.</summary>
    None = 0,

    /// <summary>Move to <see cref="InterpolationNode.Position"/> (the only type retail 11.4186 ever creates).</summary>
    Position = 1,

    /// <summary>A jump marker: completes at once in <c>UseTime</c>; a blip to it restores the velocity.</summary>
    Jump = 2,

    /// <summary>A velocity marker: <c>UseTime</c> sets the object's velocity to <see cref="InterpolationNode.Velocity"/>.</summary>
    Velocity = 3,
}

/// <summary>
/// One queued target of the <see cref="InterpolationManager"/> (retail <c>InterpolationNode</c>, acclient.h:58208, 0x60 bytes):
/// a type, a position, a velocity and a jump extent. Stored by value in the manager's fixed ring.
/// </summary>
internal struct InterpolationNode
{
    /// <summary>What the node asks for (retail <c>type</c>).</summary>
    public InterpolationNodeType Type;

    /// <summary>Target position (retail <c>p</c>).</summary>
    public Position Position;

    /// <summary>Velocity carried by Jump and Velocity nodes, m/s in world axes (retail <c>v</c>).</summary>
    public Vector3 Velocity;

    /// <summary>Jump extent (retail <c>extent</c>); carried, never read by the managers.</summary>
    public float Extent;
}
