using System;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Managers;

/// <summary>Retail-order helpers shared by the position managers.</summary>
internal static class ManagerMath
{
    /// <summary>
    /// <c>Position::distance</c> as retail evaluates it (acclient.c:467031): the block-aware offset, then the square root of
    /// the sum of squares in double (an x87 temporary), NOT rounded to float, because every caller compares the double.
    /// </summary>
    // retail: Position::distance (acclient.c:467031)
    public static double Distance(in Position from, in Position to)
    {
        System.Numerics.Vector3 o = from.GetOffset(to);
        return Math.Sqrt((double)o.X * o.X + (double)o.Y * o.Y + (double)o.Z * o.Z);
    }

    /// <summary><c>AC1Legacy::Vector3::magnitude</c> in double (acclient.c:143594).</summary>
    // retail: AC1Legacy::Vector3::magnitude (acclient.c:143594)
    public static double Magnitude(System.Numerics.Vector3 v) =>
        Math.Sqrt((double)v.X * v.X + (double)v.Y * v.Y + (double)v.Z * v.Z);

    /// <summary>True when the position can be queued or stored: a valid unit quaternion and an origin in the position domain
    /// (<see cref="InputLimits"/>).</summary>
    public static bool IsUsable(in Position p) => InputLimits.IsPositionInDomain(p);
}
