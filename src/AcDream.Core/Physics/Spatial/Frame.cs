using System;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.Spatial;

/// <summary>
/// A rigid transform in retail's layout: an origin, a unit quaternion stored w, x, y, z, and the cached 3x3
/// local-to-global rotation matrix that retail keeps in step with the quaternion (<c>Frame</c>, PORTAL/cgeometry/CFrame.c).
/// Which is which: a <see cref="Frame"/> is a placed pose the engine computes with; an <see cref="AFrame"/> is the seven floats a
/// data file stores (no matrix); an <c>AnimFrame</c> (Animation) is one keyframe of an animation, an AFrame per part and its hooks.
/// </summary>
/// <remarks>
/// <para><b>Conventions.</b> +X east, +Y north, +Z up; headings are degrees clockwise from north (+Y), so heading 90 faces +X.</para>
/// <para><b>The cached matrix</b> is retail's <c>m_fl2gv[0..8]</c>, the local-to-global rotation, named here as
/// System.Numerics names a matrix for row vectors (<c>v' = v * M</c>): row r holds the global image of local axis r, so
/// M11, M12, M13 (<c>m_fl2gv[0..2]</c>) are the global x, y, z of the local X axis, M21..M23 (<c>[3..5]</c>) of local Y,
/// M31..M33 (<c>[6..8]</c>) of local Z; <c>m_fl2gv[3(r − 1) + (c − 1)]</c> = Mrc. A local point p maps to
/// <c>global = (M11, M12, M13) p.x + (M21, M22, M23) p.y + (M31, M32, M33) p.z + origin</c>. From the quaternion (w, x, y, z)
/// (the same entries as <see cref="Matrix4x4.CreateFromQuaternion"/>):
/// <code>
/// M11 = 1 - 2y² - 2z²   M21 = 2xy - 2wz       M31 = 2xz + 2wy
/// M12 = 2xy + 2wz       M22 = 1 - 2x² - 2z²   M32 = 2yz - 2wx
/// M13 = 2xz - 2wy       M23 = 2yz + 2wx       M33 = 1 - 2x² - 2y²
/// </code>
/// The engine reads the entries one by one (internal) in retail's operand order; the public reads them as
/// <see cref="RotationMatrix"/>.</para>
/// <para><b>Arithmetic.</b> Retail computed its intermediates on the x87 stack; this port evaluates them in double in retail's
/// operand order and rounds to float exactly where retail stored a float, so results are bit-for-bit repeatable.
/// No System.Numerics helper that may fuse multiply-add is used here.</para>
/// <para>The quaternion is changed only through <see cref="SetRotate(float, float, float, float)"/> and the operations that call it,
/// which renormalise and recache; <see cref="Origin"/> is a plain field that carries no validation (use <see cref="IsValid"/>).</para>
/// </remarks>
public partial struct Frame : IEquatable<Frame>
{
    private float _qw, _qx, _qy, _qz;
    private float _m11, _m12, _m13, _m21, _m22, _m23, _m31, _m32, _m33;

    /// <summary>The frame's origin, in the coordinates of its parent (for a position: local to its landblock), metres.</summary>
    public Vector3 Origin;

    /// <summary>The identity frame: origin zero, quaternion (1, 0, 0, 0), identity matrix.</summary>
    public static Frame Identity => s_identity;

    // Built once (quaternion (1, 0, 0, 0) and its cache); a readonly copy, never changed.
    private static readonly Frame s_identity = CreateIdentity();

    private static Frame CreateIdentity()
    {
        Frame f = default;
        f._qw = 1f;
        f.Cache();
        return f;
    }

    /// <summary>
    /// Creates a frame from an origin and a rotation. The rotation is normalised as <c>set_rotate</c> does.
    /// </summary>
    /// <exception cref="ArgumentException">The origin or the rotation has a NaN or infinite component, or the rotation is zero.</exception>
    public Frame(Vector3 origin, Quaternion rotation)
    {
        if (!VectorMath.IsFinite(origin))
        {
            throw new ArgumentException("Frame origin must be finite.", nameof(origin));
        }

        if (!VectorMath.IsFinite(rotation))
        {
            throw new ArgumentException("Frame rotation must be finite.", nameof(rotation));
        }

        this = Identity;
        Origin = origin;
        if (!IsValidRotation(rotation) || !SetRotate(rotation.W, rotation.X, rotation.Y, rotation.Z))
        {
            throw new ArgumentException("Frame rotation must be a non-zero quaternion.", nameof(rotation));
        }
    }

    /// <summary>Creates a frame at <paramref name="origin"/> facing <paramref name="headingDegrees"/> (clockwise from north).</summary>
    /// <param name="origin">The origin: finite.</param>
    /// <param name="headingDegrees">Compass heading, degrees (rounded to float, as <see cref="SetHeading"/>).</param>
    /// <exception cref="ArgumentException">The origin or heading is NaN or infinite (the heading also when its float rounding
    /// is).</exception>
    public static Frame FromHeading(Vector3 origin, double headingDegrees)
    {
        if (!VectorMath.IsFinite(origin))
        {
            throw new ArgumentException("Frame origin must be finite.", nameof(origin));
        }

        if (!float.IsFinite((float)headingDegrees))
        {
            throw new ArgumentException("Heading must be finite.", nameof(headingDegrees));
        }

        Frame f = Identity;
        f.Origin = origin;
        f.SetHeading(headingDegrees);
        return f;
    }

    /// <summary>Quaternion w (scalar part).</summary>
    public readonly float Qw => _qw;

    /// <summary>Quaternion x.</summary>
    public readonly float Qx => _qx;

    /// <summary>Quaternion y.</summary>
    public readonly float Qy => _qy;

    /// <summary>Quaternion z.</summary>
    public readonly float Qz => _qz;

    /// <summary>The rotation as a System.Numerics quaternion (its X, Y, Z, W are retail's qx, qy, qz, qw).</summary>
    public readonly Quaternion Rotation => new(_qx, _qy, _qz, _qw);

    /// <summary>
    /// The cached local-to-global rotation (retail <c>m_fl2gv</c>) as a System.Numerics matrix for row vectors: rows 1..3
    /// are the global images of the local X, Y and Z axes (<c>Vector3.TransformNormal(v, RotationMatrix)</c> turns a local
    /// direction into global axes, up to rounding); the fourth row and column are those of the identity.
    /// </summary>
    public readonly Matrix4x4 RotationMatrix => new(
        _m11, _m12, _m13, 0f,
        _m21, _m22, _m23, 0f,
        _m31, _m32, _m33, 0f,
        0f, 0f, 0f, 1f);

    /// <summary>Cached matrix row 1, column 1 (retail <c>m_fl2gv[0]</c>): global x of the local X axis.</summary>
    internal readonly float M11 => _m11;

    /// <summary>Cached matrix row 1, column 2 (retail <c>m_fl2gv[1]</c>): global y of the local X axis.</summary>
    internal readonly float M12 => _m12;

    /// <summary>Cached matrix row 1, column 3 (retail <c>m_fl2gv[2]</c>): global z of the local X axis.</summary>
    internal readonly float M13 => _m13;

    /// <summary>Cached matrix row 2, column 1 (retail <c>m_fl2gv[3]</c>): global x of the local Y axis.</summary>
    internal readonly float M21 => _m21;

    /// <summary>Cached matrix row 2, column 2 (retail <c>m_fl2gv[4]</c>): global y of the local Y axis.</summary>
    internal readonly float M22 => _m22;

    /// <summary>Cached matrix row 2, column 3 (retail <c>m_fl2gv[5]</c>): global z of the local Y axis.</summary>
    internal readonly float M23 => _m23;

    /// <summary>Cached matrix row 3, column 1 (retail <c>m_fl2gv[6]</c>): global x of the local Z axis.</summary>
    internal readonly float M31 => _m31;

    /// <summary>Cached matrix row 3, column 2 (retail <c>m_fl2gv[7]</c>): global y of the local Z axis.</summary>
    internal readonly float M32 => _m32;

    /// <summary>Cached matrix row 3, column 3 (retail <c>m_fl2gv[8]</c>): global z of the local Z axis.</summary>
    internal readonly float M33 => _m33;

    /// <summary>Rebuilds the cached matrix from the quaternion (intermediates in double, as retail's x87 code).</summary>
    // retail: Frame::cache (acclient.c:356983)
    public void Cache() => CacheFrom(_qw, _qx, _qy, _qz);

    // Frame::cache's arithmetic on a quaternion held in registers (set_rotate calls it before the fields are read back).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void CacheFrom(float qw, float qx, float qy, float qz)
    {
        double b2 = (double)qx + qx;
        double c2 = (double)qy + qy;
        double d2 = (double)qz + qz;
        double wb = qw * b2;
        double wc = qw * c2;
        double wd = qw * d2;
        double xb = qx * b2;
        double xc = qx * c2;
        double xd = qx * d2;
        double yc = qy * c2;
        double yd = qy * d2;
        double zd = qz * d2;
        _m11 = (float)(1.0 - yc - zd);
        _m12 = (float)(xc + wd);
        _m13 = (float)(xd - wc);
        _m21 = (float)(xc - wd);
        double oneMinusXb = 1.0 - xb;
        _m22 = (float)(oneMinusXb - zd);
        _m23 = (float)(yd + wb);
        _m31 = (float)(xd + wc);
        _m32 = (float)(yd - wb);
        _m33 = (float)(oneMinusXb - yc);
    }

    /// <summary>
    /// True when no component is NaN and the quaternion's squared norm is within 5 * EPSILON of 1.
    /// </summary>
    // retail: Frame::IsValid (acclient.c:357024)
    public readonly bool IsValid() => IsValidWith(_qw, _qx, _qy, _qz);

    // Frame::IsValid for this origin and the quaternion (qw, qx, qy, qz). A NaN component makes the norm NaN, which fails
    // the tolerance test, so retail's separate NaN tests of the quaternion are implied by it.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private readonly bool IsValidWith(float qw, float qx, float qy, float qz)
    {
        float norm = qz * qz + qy * qy + qx * qx + qw * qw;
        return Math.Abs(norm - 1.0) <= ValidNormTolerance
               && !float.IsNaN(Origin.X) && !float.IsNaN(Origin.Y) && !float.IsNaN(Origin.Z);
    }

    // IsValid's tolerance on |q|² - 1: 5 * EPSILON in double.
    private const double ValidNormTolerance = (double)PhysicsGlobals.Epsilon * 5.0;

    /// <summary>
    /// Retail's test used by <c>set_frame</c> to recover a frame whose origin is good but whose quaternion is not:
    /// true when the origin has no NaN and at least one quaternion component is NaN.
    /// </summary>
    /// <remarks>The decompilation reads literally this way (acclient.c:357050) and its one caller, <c>set_frame</c>, zeroes the
    /// quaternion when the frame is invalid and this returns true. We reproduce it as written.</remarks>
    // retail: Frame::IsValidExceptForHeading (acclient.c:357050)
    public readonly bool IsValidExceptForHeading()
    {
        return !float.IsNaN(Origin.X) && !float.IsNaN(Origin.Y) && !float.IsNaN(Origin.Z)
               && (float.IsNaN(_qw) || float.IsNaN(_qx) || float.IsNaN(_qy) || float.IsNaN(_qz));
    }

    /// <summary>
    /// Sets the rotation: normalises (w, x, y, z) and recaches the matrix; when the normalised quaternion is not valid
    /// (zero, NaN or infinite input) the previous quaternion is restored and the cache is left as it was.
    /// </summary>
    /// <returns>True when the new rotation was accepted.</returns>
    // retail: Frame::set_rotate (acclient.c:357062)
    public bool SetRotate(float qw, float qx, float qy, float qz) => SetRotateInlined(qw, qx, qy, qz);

    // set_rotate's body, inlined into the frame operations of the tick (combine, grotate, rotate, set_heading, ...) so that
    // they pay no call, no argument moves and no spills around it (#38); the public SetRotate is the same body behind a call.
    // Retail stores the normalised quaternion, tests IsValid and restores the old one on failure; testing the new values
    // before storing them is the same, so the rejected path has nothing to undo: it only returns false.
    // retail: Frame::set_rotate (acclient.c:357062)
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal bool SetRotateInlined(float qw, float qx, float qy, float qz)
    {
        double inv = 1.0 / Math.Sqrt((double)qw * qw + (double)qx * qx + (double)qy * qy + (double)qz * qz);
        float w = (float)(qw * inv);
        float x = (float)(qx * inv);
        float y = (float)(qy * inv);
        float z = (float)(inv * qz);
        if (!IsValidWith(w, x, y, z))
        {
            return false;
        }

        _qw = w;
        _qx = x;
        _qy = y;
        _qz = z;
        CacheFrom(w, x, y, z);
        return true;
    }

    /// <summary>Sets the rotation from a System.Numerics quaternion (W is retail's qw); see <see cref="SetRotate(float, float, float, float)"/>.</summary>
    public bool SetRotate(Quaternion q) => SetRotate(q.W, q.X, q.Y, q.Z);

    /// <summary>
    /// Writes raw quaternion components without normalising or recaching, as retail's member-wise copies do
    /// (used by <c>set_frame</c>'s recovery, which zeroes the quaternion). Internal: it breaks the cache invariant.
    /// </summary>
    internal void SetQuaternionRaw(float qw, float qx, float qy, float qz)
    {
        _qw = qw;
        _qx = qx;
        _qy = qy;
        _qz = qz;
    }

    /// <summary>Sets this frame to <paramref name="f1"/> ∘ <paramref name="f2"/>: <paramref name="f2"/> expressed in
    /// <paramref name="f1"/>'s local space, lifted to <paramref name="f1"/>'s parent space.</summary>
    /// <remarks>origin = f1.localtoglobal(f2.origin); q = f1.q * f2.q, renormalised by set_rotate.</remarks>
    // retail: Frame::combine (acclient.c:319448)
    public void Combine(in Frame f1, in Frame f2)
    {
        // f1 or f2 may be this frame: everything is read before anything is written. The origin is stored a component at a
        // time (not packed into a Vector3 and stored as one), before set_rotate, whose validity test reads it.
        CombineProduct(f1, f2, out float ox, out float oy, out float oz, out float nw, out float nx, out float ny, out float nz);
        Origin.X = ox;
        Origin.Y = oy;
        Origin.Z = oz;
        SetRotateInlined(nw, nx, ny, nz);
    }

    /// <summary>combine's arithmetic: f2's origin lifted by f1, and the quaternion product f1.q * f2.q (not normalised).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void CombineProduct(in Frame f1, in Frame f2, out float ox, out float oy, out float oz,
        out float nw, out float nx, out float ny, out float nz)
    {
        double px = f2.Origin.X, py = f2.Origin.Y, pz = f2.Origin.Z;
        double gx = f1._m31 * pz + f1._m11 * px + f1._m21 * py + f1.Origin.X;
        double gy = f1._m32 * pz + f1._m12 * px + f1._m22 * py + f1.Origin.Y;
        double gz = f1._m33 * pz + f1._m13 * px + f1._m23 * py + f1.Origin.Z;
        double aw = f1._qw, ax = f1._qx, ay = f1._qy, az = f1._qz;
        double bw = f2._qw, bx = f2._qx, by = f2._qy, bz = f2._qz;
        nz = (float)(by * ax + bz * aw - ay * bx + az * bw);
        ny = (float)(by * aw - bz * ax + az * bx + ay * bw);
        nx = (float)(aw * bx + bz * ay + bw * ax - by * az);
        nw = (float)(aw * bw - bx * ax - by * ay - bz * az);
        ox = (float)gx;
        oy = (float)gy;
        oz = (float)gz;
    }

    /// <summary>Returns <paramref name="f1"/> ∘ <paramref name="f2"/>; see <see cref="Combine(in Frame, in Frame)"/>.</summary>
    public static Frame Combined(in Frame f1, in Frame f2)
    {
        Frame r = f1;
        r.Combine(f1, f2);
        return r;
    }

    /// <summary>
    /// Sets this frame to the reference frame R that <paramref name="local"/> is placed in to give
    /// <paramref name="combined"/>: <c>R ∘ local = combined</c>, the inverse of <see cref="Combine"/> on the right (if
    /// A = B ∘ C then SetToReference(A, C) gives B). q = combined.q * conj(local.q), origin = combined.origin + R(q) *
    /// (-local.origin). Retail <c>Frame::subtract1</c>.
    /// </summary>
    // retail: Frame::subtract1 (acclient.c:357321)
    public void SetToReference(in Frame combined, in Frame local)
    {
        float nz = (float)((double)combined._qz * local._qw - ((double)combined._qw * local._qz + (double)local._qy * combined._qx) + (double)combined._qy * local._qx);
        float ny = (float)((double)combined._qy * local._qw - (double)combined._qw * local._qy + (double)local._qz * combined._qx - (double)local._qx * combined._qz);
        float nx = (float)((double)combined._qx * local._qw - (double)local._qx * combined._qw - (double)combined._qy * local._qz + (double)combined._qz * local._qy);
        float nw = (float)((double)combined._qy * local._qy + (double)local._qx * combined._qx + (double)combined._qw * local._qw + (double)local._qz * combined._qz);
        Vector3 combinedOrigin = combined.Origin;
        Vector3 localOrigin = local.Origin;
        SetRotate(nw, nx, ny, nz);
        double vx = -localOrigin.X;
        double vy = -localOrigin.Y;
        double vz = -localOrigin.Z;
        float gx = (float)(vz * _m31 + vx * _m11 + vy * _m21);
        float gy = (float)(vz * _m32 + vx * _m12 + vy * _m22);
        double gz = vz * _m33 + vx * _m13 + vy * _m23;
        Origin = new Vector3((float)(gx + (double)combinedOrigin.X), (float)(gy + (double)combinedOrigin.Y), (float)(gz + combinedOrigin.Z));
    }

    /// <summary>
    /// Sets this frame to <paramref name="frame"/> expressed in <paramref name="reference"/>'s local space:
    /// origin = reference.globaltolocal(frame.origin), q = conj(reference.q) * frame.q. The inverse of <see cref="Combine"/>
    /// on the left: if A = B ∘ C then SetToRelative(A, B) gives C. Retail <c>Frame::subtract2</c>.
    /// </summary>
    // retail: Frame::subtract2 (acclient.c:357364)
    public void SetToRelative(in Frame frame, in Frame reference)
    {
        Vector3 local = reference.GlobalToLocal(frame.Origin);
        float nz = (float)((double)frame._qz * reference._qw - (double)frame._qy * reference._qx + (double)frame._qx * reference._qy - (double)frame._qw * reference._qz);
        float ny = (float)((double)frame._qz * reference._qx + (double)reference._qw * frame._qy - (double)reference._qy * frame._qw - (double)frame._qx * reference._qz);
        float nx = (float)((double)frame._qx * reference._qw - (double)frame._qw * reference._qx - (double)reference._qy * frame._qz + (double)frame._qy * reference._qz);
        float nw = (float)((double)frame._qw * reference._qw + (double)reference._qy * frame._qy + (double)frame._qx * reference._qx + (double)frame._qz * reference._qz);
        Origin = local;
        SetRotate(nw, nx, ny, nz);
    }

    /// <summary>True when origins agree within EPSILON per axis (inclusive) and quaternion components within EPSILON (exclusive).</summary>
    /// <remarks>Unlike ACE, orientation is compared. q and -q (the same rotation) are not equal here, as in retail.</remarks>
    // retail: Frame::is_equal (acclient.c:96699), Frame::is_quaternion_equal (acclient.c:96712)
    public readonly bool IsEqual(in Frame rhs)
    {
        const float eps = PhysicsGlobals.Epsilon;
        bool originEqual = Math.Abs(Origin.X - rhs.Origin.X) <= eps
                           && Math.Abs(Origin.Y - rhs.Origin.Y) <= eps
                           && Math.Abs(Origin.Z - rhs.Origin.Z) <= eps;
        return originEqual
               && Math.Abs(_qw - rhs._qw) < eps
               && Math.Abs(_qx - rhs._qx) < eps
               && Math.Abs(_qy - rhs._qy) < eps
               && Math.Abs(_qz - rhs._qz) < eps;
    }

    /// <summary>Exact component-wise equality of origin, quaternion and cache (float equality: -0 equals +0 and NaN equals NaN;
    /// compare bit patterns for determinism checks; use <see cref="IsEqual"/> for retail's tolerance).</summary>
    public readonly bool Equals(Frame other) =>
        Origin.Equals(other.Origin)
        && _qw.Equals(other._qw) && _qx.Equals(other._qx) && _qy.Equals(other._qy) && _qz.Equals(other._qz)
        && _m11.Equals(other._m11) && _m12.Equals(other._m12) && _m13.Equals(other._m13)
        && _m21.Equals(other._m21) && _m22.Equals(other._m22) && _m23.Equals(other._m23)
        && _m31.Equals(other._m31) && _m32.Equals(other._m32) && _m33.Equals(other._m33);

    /// <inheritdoc />
    public override readonly bool Equals(object? obj) => obj is Frame f && Equals(f);

    /// <inheritdoc />
    public override readonly int GetHashCode() => HashCode.Combine(Origin, _qw, _qx, _qy, _qz);

    /// <summary>Exact equality; see <see cref="Equals(Frame)"/>.</summary>
    public static bool operator ==(Frame left, Frame right) => left.Equals(right);

    /// <summary>Exact inequality; see <see cref="Equals(Frame)"/>.</summary>
    public static bool operator !=(Frame left, Frame right) => !left.Equals(right);

    /// <inheritdoc />
    public override readonly string ToString() =>
        string.Create(System.Globalization.CultureInfo.InvariantCulture,
            $"[{Origin.X} {Origin.Y} {Origin.Z}] {_qw} {_qx} {_qy} {_qz}");

    private static bool IsValidRotation(Quaternion q) =>
        ((double)q.W * q.W + (double)q.X * q.X + (double)q.Y * q.Y + (double)q.Z * q.Z) > 0.0;
}
