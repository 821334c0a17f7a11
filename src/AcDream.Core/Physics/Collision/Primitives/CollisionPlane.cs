using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Collision.Primitives;

/// <summary>
/// A plane <c>N·p + d = 0</c> with a unit normal <see cref="N"/>, ported from retail's <c>Plane</c> (acclient.h:30682,
/// PORTAL/geometry/Plane.c and helpers elsewhere).
/// </summary>
/// <remarks>All evaluations follow retail's operand order (z, y, x, then d) in double, so no fused multiply-add can change
/// a result; values retail stored as float are rounded to float at the same place.</remarks>
public struct CollisionPlane : IEquatable<CollisionPlane>
{
    /// <summary>The unit normal. Retail: <c>N</c>.</summary>
    public Vector3 N;

    /// <summary>The signed distance term: points on the plane satisfy <c>N·p + d = 0</c>. Retail: <c>d</c>.</summary>
    public float D;

    /// <summary>Creates a plane from its normal and distance term (no normalisation).</summary>
    public CollisionPlane(Vector3 n, float d)
    {
        N = n;
        D = d;
    }

    /// <summary>A plane: normal x, y, z then d (retail <c>Plane::UnPack</c> order, as <c>BSPNODE::UnPack</c> inlines it); a
    /// NaN or infinity is a format error.</summary>
    internal static CollisionPlane UnPack(ref RetailDataReader reader, string what)
    {
        Vector3 n = reader.ReadFiniteVector3(what);
        float d = reader.ReadFiniteSingle(what);
        return new CollisionPlane(n, d);
    }

    /// <summary>The signed distance of <paramref name="v"/> from the plane (for a unit normal): <c>N·v + d</c> in double,
    /// evaluated z, y, x then d as retail's <c>which_side</c> does.</summary>
    public readonly double DotProduct(Vector3 v) => (double)v.Z * N.Z + (double)v.Y * N.Y + (double)v.X * N.X + D;

    /// <summary>
    /// The side of the plane <paramref name="v"/> lies on: <see cref="Sidedness.Positive"/> when <c>N·v + d &gt; epsilon</c>,
    /// <see cref="Sidedness.Negative"/> when it is below <c>-epsilon</c>, otherwise <see cref="Sidedness.InPlane"/>.
    /// </summary>
    // retail: Plane::which_side (acclient.c:128608)
    public readonly Sidedness WhichSide(Vector3 v, float epsilon)
    {
        double dp = DotProduct(v);
        if (dp > epsilon)
        {
            return Sidedness.Positive;
        }

        return dp >= -epsilon ? Sidedness.InPlane : Sidedness.Negative;
    }

    /// <summary>
    /// The side of the plane the axis-aligned box <paramref name="min"/>–<paramref name="max"/> lies on: the low corner
    /// decides (<see cref="Sidedness.Positive"/> beyond EPSILON, <see cref="Sidedness.Negative"/> below -EPSILON), and
    /// <see cref="Sidedness.Crossing"/> when that corner is within EPSILON of the plane or any other corner's
    /// <see cref="WhichSide"/> differs.
    /// </summary>
    // retail: Plane::intersect_box (acclient.c:467717)
    internal readonly Sidedness IntersectBox(Vector3 min, Vector3 max)
    {
        double d = DotProduct(min);
        Sidedness side;
        if (d <= PhysicsGlobals.Epsilon)
        {
            if (d >= -PhysicsGlobals.Epsilon)
            {
                return Sidedness.Crossing;
            }

            side = Sidedness.Negative;
        }
        else
        {
            side = Sidedness.Positive;
        }

        if (side != WhichSide(max, PhysicsGlobals.Epsilon)
            || side != WhichSide(new Vector3(max.X, min.Y, min.Z), PhysicsGlobals.Epsilon)
            || side != WhichSide(new Vector3(min.X, max.Y, min.Z), PhysicsGlobals.Epsilon)
            || side != WhichSide(new Vector3(min.X, min.Y, max.Z), PhysicsGlobals.Epsilon)
            || side != WhichSide(new Vector3(max.X, max.Y, min.Z), PhysicsGlobals.Epsilon)
            || side != WhichSide(new Vector3(max.X, min.Y, max.Z), PhysicsGlobals.Epsilon)
            || side != WhichSide(new Vector3(min.X, max.Y, max.Z), PhysicsGlobals.Epsilon))
        {
            return Sidedness.Crossing;
        }

        return side;
    }

    /// <summary>
    /// The parameter <paramref name="time"/> at which the ray <c>pt + t·dir</c> meets the plane. Returns false when the ray
    /// is parallel within EPSILON (<c>|dir·N| &lt; 0.0002</c>) or the hit lies behind the start (<c>t &lt; 0</c>);
    /// <paramref name="time"/> is still written in the second case, as retail does.
    /// </summary>
    // retail: Plane::compute_time_of_intersection (acclient.c:359592)
    public readonly bool ComputeTimeOfIntersection(Vector3 pt, Vector3 dir, out double time)
    {
        double den = (double)dir.Z * N.Z + (double)dir.Y * N.Y + (double)dir.X * N.X;
        time = 0.0;
        if (Math.Abs(den) < PhysicsGlobals.Epsilon)
        {
            return false;
        }

        time = ((double)pt.Z * N.Z + (double)pt.Y * N.Y + (double)pt.X * N.X + D) * (-1.0 / den);
        return time >= 0.0;
    }

    /// <summary>
    /// Drops (or raises) <paramref name="v"/> onto the plane along z: <c>z = -(y·N.y + x·N.x + d) / N.z</c>. Returns false
    /// and leaves <paramref name="v"/> unchanged when the plane is vertical within EPSILON (<c>|N.z| &lt;= 0.0002</c>).
    /// This is retail's terrain height query (used after <c>find_terrain_poly</c>).
    /// </summary>
    // retail: Plane::set_height (acclient.c:351337)
    public readonly bool SetHeight(ref Vector3 v)
    {
        if (Math.Abs(N.Z) <= PhysicsGlobals.Epsilon)
        {
            return false;
        }

        v.Z = (float)-(((double)v.Y * N.Y + (double)v.X * N.X + D) / N.Z);
        return true;
    }

    /// <inheritdoc />
    public readonly bool Equals(CollisionPlane other) => N.Equals(other.N) && D.Equals(other.D);

    /// <inheritdoc />
    public override readonly bool Equals(object? obj) => obj is Plane p && Equals(p);

    /// <inheritdoc />
    public override readonly int GetHashCode() => HashCode.Combine(N, D);

    /// <summary>Bitwise equality of normal and distance.</summary>
    public static bool operator ==(CollisionPlane left, CollisionPlane right) => left.Equals(right);

    /// <summary>Bitwise inequality of normal and distance.</summary>
    public static bool operator !=(CollisionPlane left, CollisionPlane right) => !left.Equals(right);

    /// <inheritdoc />
    public override readonly string ToString() =>
        string.Create(System.Globalization.CultureInfo.InvariantCulture, $"N=({N.X}, {N.Y}, {N.Z}) d={D}");
}
