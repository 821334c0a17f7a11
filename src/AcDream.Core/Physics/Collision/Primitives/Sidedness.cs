namespace AcDream.Core.Physics.Collision.Primitives;

/// <summary>
/// Which side of a plane a point lies on, or which face of a polygon a test uses. Retail: <c>enum Sidedness</c>
/// (acclient.h:2527).
/// </summary>
public enum Sidedness
{
    /// <summary>In front of the plane (the side the normal points to). Retail: <c>POSITIVE = 0</c>.</summary>
    Positive = 0,

    /// <summary>Behind the plane. Retail: <c>NEGATIVE = 1</c>.</summary>
    Negative = 1,

    /// <summary>Within the tolerance of the plane. Retail: <c>IN_PLANE = 2</c>.</summary>
    InPlane = 2,

    /// <summary>Straddling the plane. Retail: <c>CROSSING = 3</c>.</summary>
    Crossing = 3,
}
