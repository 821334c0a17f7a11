using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Collision.Primitives;

/// <summary>
/// A collision sphere: a centre and a radius, in metres. Retail: <c>CSphere</c> (acclient.h:31107,
/// PORTAL/cgeometry/CSphere.c). Objects sweep up to two of them (the sweep's sphere path, retail <c>SPHEREPATH</c>).
/// </summary>
public partial struct Sphere : IEquatable<Sphere>
{
    /// <summary>The centre, in the coordinates of whatever owns the sphere (object-local, or landblock-local once cached).</summary>
    public Vector3 Center;

    /// <summary>The radius, in metres.</summary>
    public float Radius;

    /// <summary>Creates a sphere.</summary>
    public Sphere(Vector3 center, float radius)
    {
        Center = center;
        Radius = radius;
    }

    /// <summary>Retail <c>CSphere::UnPack</c> (acclient.c:334267): centre x, y, z then radius; a NaN or infinity is a format
    /// error (the library's queries take finite spheres).</summary>
    // retail: CSphere::UnPack (acclient.c:334267)
    internal static Sphere UnPack(ref RetailDataReader reader, string what)
    {
        Vector3 c = reader.ReadFiniteVector3(what);
        float r = reader.ReadFiniteSingle(what);
        return new Sphere(c, r);
    }

    /// <summary>True when this is a sphere the sweep can handle: finite centre, positive radius and |centre| + radius &lt;=
    /// <see cref="InputLimits.MaxShapeReach"/> (computed in double).</summary>
    internal readonly bool IsInDomain =>
        VectorMath.IsFinite(Center) && Radius > 0f && VectorMath.Magnitude(Center) + Radius <= InputLimits.MaxShapeReach; // also NaN and ∞ radii

    /// <summary>Throws when a sphere of <paramref name="spheres"/> is outside <see cref="IsInDomain"/>.</summary>
    /// <exception cref="ArgumentException">A sphere is outside the domain (the message names its index).</exception>
    internal static void ThrowIfAnyOutside(ReadOnlySpan<Sphere> spheres, string paramName)
    {
        for (int i = 0; i < spheres.Length; i++)
        {
            if (!spheres[i].IsInDomain)
            {
                throw new ArgumentException(string.Create(System.Globalization.CultureInfo.InvariantCulture,
                    $"Sphere {i} needs a finite centre and a positive radius with |centre| + radius at most 192 m (InputLimits.MaxShapeReach)."),
                    paramName);
            }
        }
    }

    /// <summary>
    /// The sphere retail sweeps for an object without collision spheres: radius <see cref="PhysicsGlobals.DummySphereRadius"/>
    /// (0.1 m), resting on the origin (centre (0, 0, 0.1)). Retail: <c>dummy_sphere</c> (static initialiser acclient.c:784575).
    /// </summary>
    public static Sphere Dummy => new(new Vector3(0f, 0f, PhysicsGlobals.DummySphereRadius), PhysicsGlobals.DummySphereRadius);

    /// <inheritdoc />
    public readonly bool Equals(Sphere other) => Center.Equals(other.Center) && Radius.Equals(other.Radius);

    /// <inheritdoc />
    public override readonly bool Equals(object? obj) => obj is Sphere s && Equals(s);

    /// <inheritdoc />
    public override readonly int GetHashCode() => HashCode.Combine(Center, Radius);

    /// <summary>Bitwise equality of centre and radius.</summary>
    public static bool operator ==(Sphere left, Sphere right) => left.Equals(right);

    /// <summary>Bitwise inequality of centre and radius.</summary>
    public static bool operator !=(Sphere left, Sphere right) => !left.Equals(right);

    /// <inheritdoc />
    public override readonly string ToString() =>
        string.Create(System.Globalization.CultureInfo.InvariantCulture, $"({Center.X}, {Center.Y}, {Center.Z}) r={Radius}");

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
