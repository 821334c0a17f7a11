namespace AcDream.Core.Physics.Collision.Primitives;

public partial struct Sphere
{
    /// <summary>
    /// True when the two spheres overlap: the squared distance of the centres is below the squared sum of the radii
    /// (touching spheres do not intersect).
    /// </summary>
    /// <remarks>Retail ambiguity (the decompiler lost the compare, it shows only the C0|C2 flags): read as the strict
    /// "less than" of <c>|Δ|²</c> against <c>(r1 + r2)²</c>, computed in double. See docs/divergences.md (BSP-B2).</remarks>
    // retail: CSphere::intersects (acclient.c:356340)
    public readonly bool Intersects(in Sphere s)
    {
        double dx = (double)Center.X - s.Center.X;
        double dy = (double)Center.Y - s.Center.Y;
        double dz = (double)Center.Z - s.Center.Z;
        double r = (double)s.Radius + Radius;
        return dx * dx + dy * dy + dz * dz < r * r;
    }
}
