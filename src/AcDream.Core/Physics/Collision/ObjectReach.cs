using System;
using AcDream.Core.Physics.Collision.Primitives;

namespace AcDream.Core.Physics.Collision;

/// <summary>
/// The axis-aligned box, in the check position's landblock, that holds a transition's check spheres
/// (<see cref="SpherePath.GlobalSphere"/>). An obstacle sphere that lies wholly outside it (by more than
/// <see cref="Margin"/>) cannot overlap a check sphere, and every test of an obstacle sphere against a transition
/// answers OK without side effects unless it overlaps one (<c>CSphere::intersects_sphere</c>: each branch that acts
/// starts with <c>collides_with_sphere</c> against check sphere 0 or 1). The cell's object loop uses the box to skip such
/// obstacles (<see cref="Cells.ObjCell"/>, ObjCell.Shadows.cs).
/// </summary>
// non-retail: an exact early-out (same results, same side effects); retail tests every shadowed object's spheres
internal readonly struct ObjectReach
{
    /// <summary>Slack, in metres, added to every distance before an obstacle is skipped (covers float rounding of the
    /// obstacle's placed sphere centre, of the radius sum and of the box, many times over).</summary>
    public const double Margin = 0.05;

    /// <summary>Relative slack: an extra 1e-4 of the coordinates' size (rounding grows with the magnitude).</summary>
    public const double RelativeMargin = 1e-4;

    /// <summary>Box lower corner.</summary>
    public readonly double MinX, MinY, MinZ;

    /// <summary>Box upper corner.</summary>
    public readonly double MaxX, MaxY, MaxZ;

    /// <summary>The check position's cell id (the box's landblock).</summary>
    public readonly uint CellId;

    /// <summary>The box around <paramref name="path"/>'s check spheres.</summary>
    public ObjectReach(SpherePath path)
    {
        CellId = path.CheckPos.ObjCellId;
        Sphere[] g = path.GlobalSphere;
        Sphere s = g[0];
        MinX = (double)s.Center.X - s.Radius;
        MinY = (double)s.Center.Y - s.Radius;
        MinZ = (double)s.Center.Z - s.Radius;
        MaxX = (double)s.Center.X + s.Radius;
        MaxY = (double)s.Center.Y + s.Radius;
        MaxZ = (double)s.Center.Z + s.Radius;
        for (int i = 1; i < path.NumSphere; i++)
        {
            s = g[i];
            MinX = Math.Min(MinX, (double)s.Center.X - s.Radius);
            MinY = Math.Min(MinY, (double)s.Center.Y - s.Radius);
            MinZ = Math.Min(MinZ, (double)s.Center.Z - s.Radius);
            MaxX = Math.Max(MaxX, (double)s.Center.X + s.Radius);
            MaxY = Math.Max(MaxY, (double)s.Center.Y + s.Radius);
            MaxZ = Math.Max(MaxZ, (double)s.Center.Z + s.Radius);
        }
    }

    /// <summary>
    /// True when a sphere of radius <paramref name="reach"/> around (<paramref name="x"/>, <paramref name="y"/>,
    /// <paramref name="z"/>) (box landblock) lies outside the box by more than the margins on some axis. NaN never
    /// excludes.
    /// </summary>
    public bool Excludes(double x, double y, double z, double reach)
    {
        double m = reach + Margin + RelativeMargin * (Math.Abs(x) + Math.Abs(y) + Math.Abs(z) + reach);
        return x + m < MinX || x - m > MaxX || y + m < MinY || y - m > MaxY || z + m < MinZ || z - m > MaxZ;
    }
}
