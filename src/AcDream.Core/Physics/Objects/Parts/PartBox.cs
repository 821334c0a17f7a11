using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Objects.Parts;

/// <summary>
/// What a static object's cell list needs of one of its parts (retail <c>CPhysicsPart</c>'s <c>gfxobj[0]</c> bounding box,
/// its placement frame and <c>Always2D</c>): the part's frame relative to the object, the GfxObj's bounding box
/// (<c>gfx_bound_box</c>, from its vertices, part-local and unscaled), whether it is drawn as a 2-D sprite, and the radius
/// used then (the physics sphere's, else the drawing sphere's).
/// </summary>
/// <param name="LocalFrame">The part's frame relative to the object (the setup's placement frame).</param>
/// <param name="Min">The bounding box's low corner, part-local.</param>
/// <param name="Max">The bounding box's high corner, part-local.</param>
/// <param name="Always2D">Retail <c>CPhysicsPart::Always2D</c>: the part's first level of detail is not a 3-D mesh.</param>
/// <param name="Radius">The physics sphere's radius (else the drawing sphere's), for a 2-D part.</param>
internal readonly record struct PartBox(Frame LocalFrame, Vector3 Min, Vector3 Max, bool Always2D, float Radius);

/// <summary>One part of a static object placed in its landblock: its position, its GfxObj's bounding box (part-local),
/// whether it is drawn as a 2-D sprite and its sphere's radius then (retail <c>CPhysicsPart</c>: <c>pos</c>,
/// <c>GetBoundingBox</c>, <c>Always2D</c>).</summary>
internal readonly record struct PlacedPartBox(Position Pos, Vector3 Min, Vector3 Max, bool Always2D, float Radius);

