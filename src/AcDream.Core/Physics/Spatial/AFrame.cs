using System;
using System.Numerics;

namespace AcDream.Core.Physics.Spatial;

/// <summary>
/// An origin and a rotation quaternion as a data file stores them, without the cached matrix of a <see cref="Frame"/>
/// (retail <c>AFrame</c>): an animation's root-motion step (<c>pos_frames</c>) and each part's frame of an
/// <c>AnimFrame</c> (Animation). The quaternion is kept exactly as read (not renormalised), as retail keeps it.
/// </summary>
public readonly struct AFrame : IEquatable<AFrame>
{
    /// <summary>Creates an AFrame from an origin and a quaternion, stored as given (retail does not renormalise one).</summary>
    /// <param name="origin">The origin, metres: finite.</param>
    /// <param name="rotation">The rotation: finite, |q|² within 5 × EPSILON (0.001) of 1 (retail <c>AFrame::IsValid</c>).</param>
    /// <exception cref="ArgumentException">A component is NaN or infinite, or the quaternion is not a unit one.</exception>
    public AFrame(Vector3 origin, Quaternion rotation)
    {
        if (!VectorMath.IsFinite(origin))
        {
            throw new ArgumentException("AFrame origin must be finite.", nameof(origin));
        }

        if (!VectorMath.IsFinite(rotation) || !IsUnit(rotation.W, rotation.X, rotation.Y, rotation.Z))
        {
            throw new ArgumentException("AFrame rotation must be a finite unit quaternion (|q|² within 0.001 of 1).", nameof(rotation));
        }

        Origin = origin;
        Qw = rotation.W;
        Qx = rotation.X;
        Qy = rotation.Y;
        Qz = rotation.Z;
    }

    // The reader's constructor: the values are checked by the caller (Format.RetailDataReader.ReadAFrame).
    private AFrame(Vector3 origin, float qw, float qx, float qy, float qz)
    {
        Origin = origin;
        Qw = qw;
        Qx = qx;
        Qy = qy;
        Qz = qz;
    }

    /// <summary>The identity: origin zero, quaternion (1, 0, 0, 0) (retail <c>AFrame::AFrame</c>).</summary>
    // retail: AFrame::AFrame (acclient.c:333664)
    public static AFrame Identity => new(Vector3.Zero, 1f, 0f, 0f, 0f);

    /// <summary>The origin, metres (retail <c>m_fOrigin</c>).</summary>
    public Vector3 Origin { get; }

    /// <summary>Quaternion w (retail <c>qw</c>).</summary>
    public float Qw { get; }

    /// <summary>Quaternion x (retail <c>qx</c>).</summary>
    public float Qx { get; }

    /// <summary>Quaternion y (retail <c>qy</c>).</summary>
    public float Qy { get; }

    /// <summary>Quaternion z (retail <c>qz</c>).</summary>
    public float Qz { get; }

    /// <summary>The rotation as a System.Numerics quaternion (W is retail's qw).</summary>
    public Quaternion Rotation => new(Qx, Qy, Qz, Qw);

    /// <summary>The frame as a <see cref="Frame"/> (its rotation normalised and cached by <see cref="Frame.SetRotate(float, float, float, float)"/>).</summary>
    public Frame ToFrame()
    {
        Frame f = Frame.Identity;
        f.Origin = Origin;
        f.SetRotate(Qw, Qx, Qy, Qz);
        return f;
    }

    // The reader's door (Format.RetailDataReader.ReadAFrame, retail AFrame::UnPack): values already checked.
    internal static AFrame FromChecked(Vector3 origin, float qw, float qx, float qy, float qz) => new(origin, qw, qx, qy, qz);

    // AFrame::IsValid's norm test (acclient.c:467555): |q|² summed z, y, x, w on the x87 stack (double: each float product is
    // exact there) and stored to the float `norm`, then within 5 × EPSILON (the float 0.0002f widened) of 1 in double.
    internal static bool IsUnit(float w, float x, float y, float z)
    {
        float norm = (float)((double)z * z + (double)y * y + (double)x * x + (double)w * w);
        return !((double)PhysicsGlobals.Epsilon * 5.0 < Math.Abs(norm - 1.0)) && !float.IsNaN(norm);
    }

    /// <summary>Sets <paramref name="frame"/> to <paramref name="frame"/> ∘ <paramref name="f2"/> (f2 expressed in frame's local
    /// space), the quaternion renormalised by <c>set_rotate</c>. CSequence's own copy of <c>Frame::combine</c> for an AFrame,
    /// whose x term sums in its own order (<see cref="Frame.Combine"/> ports the Frame-Frame one, acclient.c:319448).</summary>
    // retail: Frame::combine (acclient.c:340419)
    internal static void Combine(ref Frame frame, in AFrame f2)
    {
        double px = f2.Origin.X, py = f2.Origin.Y, pz = f2.Origin.Z;
        float ox = (float)(frame.M31 * pz + frame.M11 * px + frame.M21 * py + frame.Origin.X);
        float oy = (float)(frame.M32 * pz + frame.M12 * px + frame.M22 * py + frame.Origin.Y);
        float oz = (float)(frame.M33 * pz + frame.M13 * px + frame.M23 * py + frame.Origin.Z);
        double aw = frame.Qw, ax = frame.Qx, ay = frame.Qy, az = frame.Qz;
        double bw = f2.Qw, bx = f2.Qx, by = f2.Qy, bz = f2.Qz;
        float nz = (float)(ax * by + bz * aw - ay * bx + az * bw);
        float ny = (float)(by * aw - ax * bz + az * bx + ay * bw);
        float nx = (float)(ax * bw + aw * bx + bz * ay - by * az);
        float nw = (float)(aw * bw - ax * bx - by * ay - bz * az);
        frame.Origin.X = ox; // by component, not packed into a Vector3 (#38); before set_rotate, whose test reads it
        frame.Origin.Y = oy;
        frame.Origin.Z = oz;
        frame.SetRotateInlined(nw, nx, ny, nz);
    }

    /// <summary>Sets <paramref name="frame"/> to the frame R with R ∘ <paramref name="f2"/> = frame (the inverse of
    /// <see cref="Combine"/>): retail <c>Frame::subtract1</c> with an AFrame operand, the arithmetic of
    /// <see cref="Frame.SetToReference"/>.</summary>
    // retail: Frame::subtract1 (acclient.c:357321)
    internal static void Subtract1(ref Frame frame, in AFrame f2)
    {
        double cw = frame.Qw, cx = frame.Qx, cy = frame.Qy, cz = frame.Qz;
        double lw = f2.Qw, lx = f2.Qx, ly = f2.Qy, lz = f2.Qz;
        float nz = (float)(cz * lw - (cw * lz + ly * cx) + cy * lx);
        float ny = (float)(cy * lw - cw * ly + lz * cx - lx * cz);
        float nx = (float)(cx * lw - lx * cw - cy * lz + cz * ly);
        float nw = (float)(cy * ly + lx * cx + cw * lw + lz * cz);
        Vector3 combinedOrigin = frame.Origin;
        frame.SetRotate(nw, nx, ny, nz);
        double vx = -f2.Origin.X;
        double vy = -f2.Origin.Y;
        double vz = -f2.Origin.Z;
        float gx = (float)(vz * frame.M31 + vx * frame.M11 + vy * frame.M21);
        float gy = (float)(vz * frame.M32 + vx * frame.M12 + vy * frame.M22);
        double gz = vz * frame.M33 + vx * frame.M13 + vy * frame.M23;
        frame.Origin.X = (float)(gx + (double)combinedOrigin.X);
        frame.Origin.Y = (float)(gy + (double)combinedOrigin.Y);
        frame.Origin.Z = (float)(gz + combinedOrigin.Z);
    }

    /// <summary>Exact component equality (float equality).</summary>
    public bool Equals(AFrame other) =>
        Origin.Equals(other.Origin) && Qw.Equals(other.Qw) && Qx.Equals(other.Qx) && Qy.Equals(other.Qy) && Qz.Equals(other.Qz);

    /// <inheritdoc />
    public override bool Equals(object? obj) => obj is AFrame other && Equals(other);

    /// <inheritdoc />
    public override int GetHashCode() => HashCode.Combine(Origin, Qw, Qx, Qy, Qz);

    /// <summary>Exact component equality.</summary>
    public static bool operator ==(AFrame left, AFrame right) => left.Equals(right);

    /// <summary>Exact component inequality.</summary>
    public static bool operator !=(AFrame left, AFrame right) => !left.Equals(right);
}
