using System;
using System.Numerics;

namespace AcDream.Core.Physics.Spatial;

/// <summary>
/// Retail's small vector helpers (<c>AC1Legacy::Vector3</c>), written component by component in retail's order with
/// double intermediates, so that no fused multiply-add can change a result.
/// </summary>
internal static class VectorMath
{
    /// <summary>True when no component is NaN or infinite.</summary>
    public static bool IsFinite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);

    /// <summary>True when no component is NaN or infinite.</summary>
    public static bool IsFinite(Quaternion q) =>
        float.IsFinite(q.X) && float.IsFinite(q.Y) && float.IsFinite(q.Z) && float.IsFinite(q.W);

    /// <summary>Squared length x² + y² + z², evaluated in double and rounded to float.</summary>
    public static float LengthSquared(Vector3 v) => (float)((double)v.X * v.X + (double)v.Y * v.Y + (double)v.Z * v.Z);

    /// <summary>Length sqrt(x² + y² + z²), evaluated in double and rounded to float.</summary>
    public static float Length(Vector3 v) => (float)Math.Sqrt((double)v.X * v.X + (double)v.Y * v.Y + (double)v.Z * v.Z);

    /// <summary>Length sqrt(x² + y² + z²) in double, not rounded to float (retail <c>AC1Legacy::Vector3::magnitude</c> as
    /// its callers use the x87 result).</summary>
    // retail: AC1Legacy::Vector3::magnitude (acclient.c:143594)
    public static double Magnitude(Vector3 v) => Math.Sqrt((double)v.X * v.X + (double)v.Y * v.Y + (double)v.Z * v.Z);

    /// <summary>Dot product a·b, evaluated in double (x, y, z order) and rounded to float.</summary>
    public static float Dot(Vector3 a, Vector3 b) => (float)((double)a.X * b.X + (double)a.Y * b.Y + (double)a.Z * b.Z);

    /// <summary>Cross product a × b, each component in double and rounded to float.</summary>
    public static Vector3 Cross(Vector3 a, Vector3 b) => new(
        (float)((double)a.Y * b.Z - (double)a.Z * b.Y),
        (float)((double)a.Z * b.X - (double)a.X * b.Z),
        (float)((double)a.X * b.Y - (double)a.Y * b.X));

    /// <summary>
    /// Normalises <paramref name="v"/> in place unless its length is below EPSILON. Returns true when the vector was too
    /// small (and is left unchanged), false when it was normalised. Zero and denormal vectors never become NaN.
    /// </summary>
    // retail: AC1Legacy::Vector3::normalize_check_small (acclient.c:143621)
    public static bool NormalizeCheckSmall(ref Vector3 v)
    {
        double len = Math.Sqrt((double)v.X * v.X + (double)v.Y * v.Y + (double)v.Z * v.Z);
        if (len >= PhysicsGlobals.Epsilon)
        {
            double inv = 1.0 / len;
            v = new Vector3((float)(inv * v.X), (float)(inv * v.Y), (float)(inv * v.Z));
            return false;
        }

        return true;
    }

    /// <summary>Normalises without a size check (retail's plain <c>normalize</c>); a zero vector becomes NaN as in retail.</summary>
    // retail: AC1Legacy::Vector3::normalize (acclient.c:143600)
    public static Vector3 Normalize(Vector3 v)
    {
        double len = Math.Sqrt((double)v.X * v.X + (double)v.Y * v.Y + (double)v.Z * v.Z);
        float x = (float)(1.0 / len * v.X);
        float y = (float)(1.0 / len * v.Y);
        float z = (float)(1.0 / len * v.Z);
        return new Vector3(x, y, z);
    }

    /// <summary>True when every component's magnitude is below EPSILON.</summary>
    // retail: AC1Legacy::Vector3::is_zero (acclient.c:315576)
    public static bool IsZero(Vector3 v) =>
        Math.Abs(v.X) < PhysicsGlobals.Epsilon
        && Math.Abs(v.Y) < PhysicsGlobals.Epsilon
        && Math.Abs(v.Z) < PhysicsGlobals.Epsilon;

    /// <summary>True when a and b agree within <paramref name="epsilon"/> on every axis (inclusive).</summary>
    // retail: Vector3Math::AreEqual (acclient.c:96721)
    public static bool AreEqual(Vector3 a, Vector3 b, float epsilon) =>
        Math.Abs(a.X - b.X) <= epsilon
        && Math.Abs(a.Y - b.Y) <= epsilon
        && Math.Abs(a.Z - b.Z) <= epsilon;
}
