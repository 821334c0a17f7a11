using System;
using System.Numerics;

namespace AcDream.Core.Physics.Spatial;

/// <summary>
/// A place in the world: the id of the cell that contains it and a <see cref="Frame"/> local to that cell's landblock
/// (x and y in 0..192 m for an outdoor position). Ported from retail's <c>Position</c> (PORTAL/geometry/Position.c).
/// </summary>
/// <remarks>Every operation between two positions is block-offset aware: the other position is first moved into this
/// position's landblock with <see cref="LandDefs.GetBlockOffset"/>.</remarks>
public struct Position : IEquatable<Position>
{
    /// <summary>The id of the cell that contains the position (0xXXYYCCCC).</summary>
    public uint ObjCellId;

    /// <summary>The frame, local to the landblock of <see cref="ObjCellId"/>.</summary>
    public Frame Frame;

    /// <summary>Creates a position from a cell id and a frame.</summary>
    public Position(uint objCellId, in Frame frame)
    {
        ObjCellId = objCellId;
        Frame = frame;
    }

    /// <summary>Creates a position at <paramref name="origin"/> in <paramref name="objCellId"/> with the identity rotation (facing north).</summary>
    /// <exception cref="ArgumentException">The origin has a NaN or infinite component.</exception>
    public Position(uint objCellId, Vector3 origin)
    {
        if (!VectorMath.IsFinite(origin))
        {
            throw new ArgumentException("Position origin must be finite.", nameof(origin));
        }

        ObjCellId = objCellId;
        Frame = Frame.Identity;
        Frame.Origin = origin;
    }

    /// <summary>True when the cell id is a valid in-world id and the frame is valid.</summary>
    // retail: Position::IsValid (acclient.c:467018)
    public readonly bool IsValid() => LandDefs.InboundValidCellId(ObjCellId) && Frame.IsValid();

    /// <summary>The vector from this position's origin to <paramref name="p"/>'s origin, in this position's landblock.</summary>
    // retail: Position::get_offset (acclient.c:311690)
    public readonly Vector3 GetOffset(in Position p)
    {
        Vector3 b = LandDefs.GetBlockOffset(ObjCellId, p.ObjCellId);
        // As retail's x87 code: the x sum stays in a register (double); the y and z sums are spilled to floats.
        double x = (double)b.X + p.Frame.Origin.X;
        float y = b.Y + p.Frame.Origin.Y;
        float z = b.Z + p.Frame.Origin.Z;
        return new Vector3((float)(x - Frame.Origin.X), y - Frame.Origin.Y, z - Frame.Origin.Z);
    }

    /// <summary>The vector from this origin to the point <paramref name="v"/> local to <paramref name="p"/>'s frame.</summary>
    // retail: Position::get_offset (acclient.c:314676)
    public readonly Vector3 GetOffset(in Position p, Vector3 v)
    {
        Vector3 b = LandDefs.GetBlockOffset(ObjCellId, p.ObjCellId);
        Vector3 g = p.Frame.LocalToGlobal(v);
        float x = b.X + g.X;
        float z = b.Z + g.Z;
        return new Vector3(x - Frame.Origin.X, (float)((double)b.Y + g.Y - Frame.Origin.Y), z - Frame.Origin.Z);
    }

    /// <summary>Straight-line distance to <paramref name="p"/>, in metres (retail <c>Position::distance</c>, rounded to
    /// float).</summary>
    public readonly float Distance(in Position p) => (float)DistanceInDouble(p);

    /// <summary><c>Position::distance</c> as retail evaluates it: the block-aware offset, then the square root of the sum of
    /// squares in double (an x87 temporary), not rounded to float, because the managers compare the double.</summary>
    // retail: Position::distance (acclient.c:467031)
    internal readonly double DistanceInDouble(in Position p) => VectorMath.Magnitude(GetOffset(p));

    /// <summary>Horizontal (x, y) distance to <paramref name="p"/>, in metres.</summary>
    // retail: Position::xy_distance (acclient.c:467041)
    public readonly float XYDistance(in Position p)
    {
        Vector3 v = GetOffset(p);
        return (float)Math.Sqrt((double)v.Y * v.Y + (double)v.X * v.X);
    }

    /// <summary>Compass heading (degrees clockwise from north) from this position to <paramref name="p"/>; 0 when they coincide in x, y.</summary>
    /// <remarks>Retail <c>Position::heading</c>.</remarks>
    // retail: Position::heading (acclient.c:467050)
    public readonly double HeadingTo(in Position p)
    {
        Vector3 d = GetOffset(p);
        d.Z = 0f;
        if (VectorMath.NormalizeCheckSmall(ref d))
        {
            return 0.0;
        }

        return HeadingMath.CompassFromAtan2(Math.Atan2(d.Y, d.X));
    }

    /// <summary>The compass heading this position's frame faces, degrees clockwise from north in [0, 360)
    /// (<see cref="Frame.Heading"/>; retail <c>Frame::get_heading</c> of <c>frame</c>).</summary>
    public readonly double Heading => Frame.Heading;

    /// <summary>The point <paramref name="v"/> local to <paramref name="p"/>'s frame, expressed in this position's local frame.</summary>
    // retail: Position::localtolocal (acclient.c:143794)
    public readonly Vector3 LocalToLocal(in Position p, Vector3 v)
    {
        Vector3 g = p.Frame.LocalToGlobal(v);
        Vector3 b = LandDefs.GetBlockOffset(ObjCellId, p.ObjCellId);
        var inBlock = new Vector3(b.X + g.X, b.Y + g.Y, b.Z + g.Z);
        return Frame.GlobalToLocal(inBlock);
    }

    /// <summary><paramref name="p"/>'s origin expressed in this position's landblock.</summary>
    // retail: Position::localtoglobal (acclient.c:143817)
    public readonly Vector3 LocalToGlobal(in Position p)
    {
        Vector3 b = LandDefs.GetBlockOffset(ObjCellId, p.ObjCellId);
        return new Vector3(b.X + p.Frame.Origin.X, b.Y + p.Frame.Origin.Y, b.Z + p.Frame.Origin.Z);
    }

    /// <summary>The point <paramref name="v"/> local to <paramref name="p"/>'s frame, expressed in this position's landblock.</summary>
    // retail: Position::localtoglobal (acclient.c:147140)
    public readonly Vector3 LocalToGlobal(in Position p, Vector3 v)
    {
        Vector3 g = p.Frame.LocalToGlobal(v);
        Vector3 b = LandDefs.GetBlockOffset(ObjCellId, p.ObjCellId);
        return new Vector3(b.X + g.X, b.Y + g.Y, b.Z + g.Z);
    }

    /// <summary>A direction local to this frame, in landblock axes.</summary>
    // retail: Position::localtoglobalvec (acclient.c:147164)
    public readonly Vector3 LocalToGlobalVec(Vector3 v) => Frame.LocalToGlobalVec(v);

    /// <summary>A direction in landblock axes, in this frame's local axes.</summary>
    // retail: Position::globaltolocalvec (acclient.c:313494)
    public readonly Vector3 GlobalToLocalVec(Vector3 v) => Frame.GlobalToLocalVec(v);

    /// <summary>
    /// Returns <paramref name="position"/>'s frame expressed in <paramref name="reference"/>'s local frame, across landblocks:
    /// <paramref name="position"/>'s origin is first moved into <paramref name="reference"/>'s landblock, then
    /// <see cref="Frame.SetToRelative"/>. Retail <c>Position::subtract2</c>.
    /// </summary>
    // retail: Position::subtract2 (acclient.c:388972)
    public static Frame RelativeFrame(in Position position, in Position reference)
    {
        Frame f = position.Frame;
        f.Origin = reference.LocalToGlobal(position);
        Frame r = Frame.Identity;
        r.SetToRelative(f, reference.Frame);
        return r;
    }

    /// <summary>
    /// Re-homes this position into the outdoor cell that contains its origin (retail semantics: on failure the cell id
    /// becomes 0 and the origin may have been snapped to exact zero). See <see cref="TryAdjustToOutside"/>.
    /// </summary>
    // retail: Position::adjust_to_outside (acclient.c:306312)
    public bool AdjustToOutside() => LandDefs.AdjustToOutside(ref ObjCellId, ref Frame.Origin);

    /// <summary>
    /// Re-homes this position into the outdoor cell that contains its origin; when that cell would lie past the world edge
    /// (or the id is not a cell id) returns false and leaves the position exactly as it was.
    /// </summary>
    public bool TryAdjustToOutside()
    {
        uint id = ObjCellId;
        Vector3 o = Frame.Origin;
        if (!LandDefs.AdjustToOutside(ref id, ref o))
        {
            return false;
        }

        ObjCellId = id;
        Frame.Origin = o;
        return true;
    }

    /// <summary>
    /// Distance between two upright cylinders (radius, height, base at the position): negative when they overlap.
    /// </summary>
    // retail: Position::cylinder_distance (acclient.c:467220)
    public static float CylinderDistance(float r1, float h1, in Position p1, float r2, float h2, in Position p2)
    {
        Vector3 off = p1.GetOffset(p2);
        float radial = (float)(VectorMath.Magnitude(off) - ((double)r1 + r2));
        double top, bottom;
        if (p1.Frame.Origin.Z <= p2.Frame.Origin.Z)
        {
            top = p2.Frame.Origin.Z;
            bottom = (double)p1.Frame.Origin.Z + h1;
        }
        else
        {
            top = p1.Frame.Origin.Z;
            bottom = (double)p2.Frame.Origin.Z + h2;
        }

        double vertical = top - bottom;
        if (vertical <= 0.0)
        {
            // The height ranges overlap.
            return radial <= 0f ? (float)-Math.Sqrt(vertical * vertical + (double)radial * radial) : radial;
        }

        return radial > 0f ? (float)Math.Sqrt(vertical * vertical + (double)radial * radial) : (float)vertical;
    }

    /// <summary>Distance between two spheres' surfaces ignoring height: |offset| - (r1 + r2).</summary>
    // retail: Position::cylinder_distance_no_z (acclient.c:467268)
    public static float CylinderDistanceNoZ(float r1, in Position p1, float r2, in Position p2)
    {
        Vector3 off = p1.GetOffset(p2);
        return (float)(VectorMath.Magnitude(off) - ((double)r1 + r2));
    }

    /// <inheritdoc />
    public readonly bool Equals(Position other) => ObjCellId == other.ObjCellId && Frame.Equals(other.Frame);

    /// <inheritdoc />
    public override readonly bool Equals(object? obj) => obj is Position p && Equals(p);

    /// <inheritdoc />
    public override readonly int GetHashCode() => HashCode.Combine(ObjCellId, Frame);

    /// <summary>Exact equality of cell id and frame (see <see cref="Frame.Equals(Frame)"/>).</summary>
    public static bool operator ==(Position left, Position right) => left.Equals(right);

    /// <summary>Exact inequality of cell id and frame.</summary>
    public static bool operator !=(Position left, Position right) => !left.Equals(right);

    /// <inheritdoc />
    public override readonly string ToString() =>
        string.Create(System.Globalization.CultureInfo.InvariantCulture, $"0x{ObjCellId:X8} {Frame}");
}
