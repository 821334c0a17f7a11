using System;
using System.Numerics;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// The closed-form references of the accuracy report and its error measures. Continuous physics, in double: what the
/// simulation approximates. Also compiled into the test project, where each formula is checked on a hand-computed case.
/// </summary>
internal static class ClosedForms
{
    /// <summary>Height after falling from rest for <paramref name="t"/> s under <paramref name="g"/> (negative, m/s²) with
    /// retail's 50 m/s speed clamp: z0 + g t²/2 until |v| = 50 at t_c = 50 / |g|, then 50 m/s.</summary>
    public static double FreeFallZ(double z0, double g, double t)
    {
        double tc = 50.0 / Math.Abs(g);
        return t <= tc ? z0 + 0.5 * g * t * t : z0 + 0.5 * g * tc * tc - 50.0 * (t - tc);
    }

    /// <summary>Speed of a body sliding on level ground with friction f after t s: v0 (1 - f)^t (retail's per-step factor
    /// (1 - f)^q compounds to exactly this).</summary>
    public static double FrictionSpeed(double v0, double f, double t) => v0 * Math.Pow(1.0 - f, t);

    /// <summary>Distance slid after t s: the integral of <see cref="FrictionSpeed"/>, v0 (1 - e^(-λt)) / λ with λ = -ln(1 - f).</summary>
    public static double FrictionDistance(double v0, double f, double t)
    {
        double lambda = -Math.Log(1.0 - f);
        return v0 * (1.0 - Math.Exp(-lambda * t)) / lambda;
    }

    /// <summary>Position of a projectile launched from <paramref name="p0"/> at <paramref name="v0"/> under gravity
    /// <paramref name="g"/> (z only), after t s (no clamp: the arc's speed stays below 50 m/s).</summary>
    public static (double X, double Y, double Z) Projectile(Vector3 p0, Vector3 v0, double g, double t) =>
        (p0.X + (double)v0.X * t, p0.Y + (double)v0.Y * t, p0.Z + (double)v0.Z * t + 0.5 * g * t * t);

    /// <summary>Rotation after spinning at <paramref name="omegaZ"/> rad/s about +Z for t s from identity, as (w, x, y, z).</summary>
    public static (double W, double X, double Y, double Z) SpinAboutZ(double omegaZ, double t) =>
        (Math.Cos(omegaZ * t / 2.0), 0.0, 0.0, Math.Sin(omegaZ * t / 2.0));

    /// <summary>Angle in degrees of the rotation between two quaternions (each normalised first): 2 acos(|a·b| / (|a| |b|)).</summary>
    public static double AngleDegrees((double W, double X, double Y, double Z) a, (double W, double X, double Y, double Z) b)
    {
        double na = Math.Sqrt(a.W * a.W + a.X * a.X + a.Y * a.Y + a.Z * a.Z);
        double nb = Math.Sqrt(b.W * b.W + b.X * b.X + b.Y * b.Y + b.Z * b.Z);
        double dot = Math.Abs(a.W * b.W + a.X * b.X + a.Y * b.Y + a.Z * b.Z) / (na * nb);
        return 2.0 * Math.Acos(Math.Min(1.0, dot)) * 180.0 / Math.PI;
    }

    /// <summary>Euclidean distance between a simulated point and a reference point, metres.</summary>
    public static double Distance(Vector3 a, (double X, double Y, double Z) b)
    {
        double dx = a.X - b.X, dy = a.Y - b.Y, dz = a.Z - b.Z;
        return Math.Sqrt(dx * dx + dy * dy + dz * dz);
    }
}
