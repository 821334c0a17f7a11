using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Tests.Support;

/// <summary>
/// The Frame arithmetic as it stood before the performance restructuring (combine, set_rotate, cache, IsValid, grotate, rotate,
/// set_heading, set_vector_heading, euler_set_rotate, localtoglobal, globaltolocal), kept verbatim as a test-only reference: the randomised comparisons
/// check that the restructured <see cref="Frame"/> gives the same bits.
/// </summary>
internal struct ReferenceFrame
{
    public float Qw, Qx, Qy, Qz;
    public float M11, M12, M13, M21, M22, M23, M31, M32, M33;
    public Vector3 Origin;

    /// <summary>Copies every field of <paramref name="f"/>.</summary>
    public static ReferenceFrame From(in Frame f) => new()
    {
        Qw = f.Qw, Qx = f.Qx, Qy = f.Qy, Qz = f.Qz,
        M11 = f.M11, M12 = f.M12, M13 = f.M13, M21 = f.M21, M22 = f.M22, M23 = f.M23, M31 = f.M31, M32 = f.M32, M33 = f.M33,
        Origin = f.Origin,
    };

    /// <summary>True when every field has the same bits as <paramref name="f"/>'s.</summary>
    public readonly bool SameBits(in Frame f) =>
        B(Qw) == B(f.Qw) && B(Qx) == B(f.Qx) && B(Qy) == B(f.Qy) && B(Qz) == B(f.Qz)
        && B(M11) == B(f.M11) && B(M12) == B(f.M12) && B(M13) == B(f.M13) && B(M21) == B(f.M21) && B(M22) == B(f.M22)
        && B(M23) == B(f.M23) && B(M31) == B(f.M31) && B(M32) == B(f.M32) && B(M33) == B(f.M33)
        && B(Origin.X) == B(f.Origin.X) && B(Origin.Y) == B(f.Origin.Y) && B(Origin.Z) == B(f.Origin.Z);

    private static int B(float x) => System.BitConverter.SingleToInt32Bits(x);

    public void Cache()
        {
            double b2 = (double)Qx + Qx;
            double c2 = (double)Qy + Qy;
            double d2 = (double)Qz + Qz;
            double wb = Qw * b2;
            double wc = Qw * c2;
            double wd = Qw * d2;
            double xb = Qx * b2;
            double xc = Qx * c2;
            double xd = Qx * d2;
            double yc = Qy * c2;
            double yd = Qy * d2;
            double zd = Qz * d2;
            M11 = (float)(1.0 - yc - zd);
            M12 = (float)(xc + wd);
            M13 = (float)(xd - wc);
            M21 = (float)(xc - wd);
            double oneMinusXb = 1.0 - xb;
            M22 = (float)(oneMinusXb - zd);
            M23 = (float)(yd + wb);
            M31 = (float)(xd + wc);
            M32 = (float)(yd - wb);
            M33 = (float)(oneMinusXb - yc);
        }

    public readonly bool IsValid()
        {
            bool ok = !(float.IsNaN(Origin.X) || float.IsNaN(Origin.Y) || float.IsNaN(Origin.Z)
                        || float.IsNaN(Qw) || float.IsNaN(Qx) || float.IsNaN(Qy) || float.IsNaN(Qz));
            float norm = Qz * Qz + Qy * Qy + Qx * Qx + Qw * Qw;
            if (float.IsNaN(norm) || (double)PhysicsGlobals.Epsilon * 5.0 < Math.Abs(norm - 1.0))
            {
                return false;
            }

            return ok;
        }

    public bool SetRotate(float qw, float qx, float qy, float qz)
        {
            float oldW = Qw, oldX = Qx, oldY = Qy, oldZ = Qz;
            double inv = 1.0 / Math.Sqrt((double)qw * qw + (double)qx * qx + (double)qy * qy + (double)qz * qz);
            Qw = (float)(qw * inv);
            Qx = (float)(qx * inv);
            Qy = (float)(qy * inv);
            Qz = (float)(inv * qz);
            if (IsValid())
            {
                Cache();
                return true;
            }

            Qw = oldW;
            Qx = oldX;
            Qy = oldY;
            Qz = oldZ;
            return false;
        }

    public void Combine(in ReferenceFrame f1, in ReferenceFrame f2)
        {
            CombineProduct(f1, f2, out Vector3 origin, out float nw, out float nx, out float ny, out float nz);
            Origin = origin;
            SetRotate(nw, nx, ny, nz);
        }

    private static void CombineProduct(in ReferenceFrame f1, in ReferenceFrame f2, out Vector3 origin, out float nw, out float nx, out float ny, out float nz)
        {
            double ox = (double)f1.M31 * f2.Origin.Z + (double)f1.M11 * f2.Origin.X + (double)f1.M21 * f2.Origin.Y + f1.Origin.X;
            double oy = (double)f1.M32 * f2.Origin.Z + (double)f1.M12 * f2.Origin.X + (double)f1.M22 * f2.Origin.Y + f1.Origin.Y;
            double oz = (double)f1.M33 * f2.Origin.Z + (double)f1.M13 * f2.Origin.X + (double)f1.M23 * f2.Origin.Y + f1.Origin.Z;
            nz = (float)((double)f2.Qy * f1.Qx + (double)f2.Qz * f1.Qw - (double)f1.Qy * f2.Qx + (double)f1.Qz * f2.Qw);
            ny = (float)((double)f2.Qy * f1.Qw - (double)f2.Qz * f1.Qx + (double)f1.Qz * f2.Qx + (double)f1.Qy * f2.Qw);
            nx = (float)((double)f1.Qw * f2.Qx + (double)f2.Qz * f1.Qy + (double)f2.Qw * f1.Qx - (double)f2.Qy * f1.Qz);
            nw = (float)((double)f1.Qw * f2.Qw - (double)f2.Qx * f1.Qx - (double)f2.Qy * f1.Qy - (double)f2.Qz * f1.Qz);
            origin = new Vector3((float)ox, (float)oy, (float)oz);
        }

    public void Rotate(Vector3 w)
        {
            float gx = (float)((double)M31 * w.Z + (double)M11 * w.X + (double)M21 * w.Y);
            float gy = (float)((double)M32 * w.Z + (double)M12 * w.X + (double)M22 * w.Y);
            float gz = (float)((double)M33 * w.Z + (double)M13 * w.X + (double)M23 * w.Y);
            GRotate(new Vector3(gx, gy, gz));
        }

    public void GRotate(Vector3 w)
        {
            if (GRotateProduct(w, out float nw, out float nx, out float ny, out float nz))
            {
                SetRotate(nw, nx, ny, nz);
            }
        }

    private readonly bool GRotateProduct(Vector3 w, out float nw, out float nx, out float ny, out float nz)
        {
            double mag2 = (double)w.X * w.X + (double)w.Y * w.Y + (double)w.Z * w.Z;
            if (mag2 < (double)PhysicsGlobals.Epsilon * PhysicsGlobals.Epsilon)
            {
                nw = nx = ny = nz = 0f;
                return false;
            }

            double theta = Math.Sqrt(mag2);
            float thetaInv = (float)(1.0 / theta);
            double half = theta * 0.5;
            double s = Math.Sin(half);
            float c = (float)Math.Cos(half);
            float f = (float)(s * w.X * thetaInv);
            float g = (float)(thetaInv * s * w.Y);
            double h = s * thetaInv * w.Z;
            nz = (float)((double)f * Qy + (double)c * Qz - (double)g * Qx + h * Qw);
            ny = (float)((double)c * Qy - (double)f * Qz + h * Qx + (double)g * Qw);
            nx = (float)((double)c * Qx + (double)g * Qz + (double)f * Qw - h * Qy);
            nw = (float)((double)c * Qw - (double)f * Qx - (double)g * Qy - h * Qz);
            return true;
        }

    public void SetHeading(float degrees)
        {
            float dz = (float)(((double)M33 + M13) * 0.0 + M23);
            double rad = degrees * HeadingMath.DegToRad;
            var direction = new Vector3((float)Math.Sin(rad), (float)Math.Cos(rad), dz);
            SetVectorHeading(direction);
        }

    public void SetVectorHeading(Vector3 heading)
        {
            Vector3 n = heading;
            if (VectorMath.NormalizeCheckSmall(ref n))
            {
                return;
            }

            float yaw = (float)(-HeadingMath.CompassFromAtan2(Math.Atan2(n.Y, n.X)) * HeadingMath.DegToRad);
            // Divergence: retail passes n.z straight to asin; a normalised z one ulp past ±1 would give NaN there and set_rotate
            // would silently keep the old rotation. We clamp to [-1, 1] so such a vector still sets the heading.
            double sinPitch = Math.Clamp((double)n.Z, -1.0, 1.0);
            float pitch = (float)(Math.Asin(sinPitch) * HeadingMath.RadToDeg * HeadingMath.DegToRad);
            EulerSetRotate(pitch, 0f, yaw, 0);
        }

    public void EulerSetRotate(float x, float y, float z, int order)
        {
            // Shoemake's order decoding: EulSafe = {0,1,2,0}, EulNext = {1,2,0,1}.
            int f = order & 1;
            int s = (order >> 1) & 1;
            int n = (order >> 2) & 1;
            int i = (order >> 3 & 3) switch { 0 => 0, 1 => 1, 2 => 2, _ => 0 };
            int j = Next(i + n);
            int k = Next(i + 1 - n);

            double zv;
            if (f == 1)
            {
                zv = x;
                x = z;
            }
            else
            {
                zv = z;
            }

            if (n == 1)
            {
                y = -y;
            }

            double ti = x * 0.5;
            double tj = y * 0.5;
            float th = (float)(zv * 0.5);
            float ci = (float)Math.Cos(ti);
            float cj = (float)Math.Cos(tj);
            float ch = (float)Math.Cos(th);
            float si = (float)Math.Sin(ti);
            double sj = Math.Sin(tj);
            double sh = Math.Sin(th);
            float cc = ch * ci;
            float cs = (float)(ci * sh);
            float sc = si * ch;
            float ss = (float)(sh * si);

            float a0 = 0f, a1 = 0f, a2 = 0f;
            float w;
            float ai, aj, ak;
            if (s == 1)
            {
                ai = (float)(((double)sc + cs) * cj);
                aj = (float)(((double)ss + cc) * sj);
                ak = (float)(((double)cs - sc) * sj);
                w = (float)(((double)cc - ss) * cj);
            }
            else
            {
                ai = (float)((double)sc * cj - cs * sj);
                aj = (float)(cc * sj + (double)ss * cj);
                ak = (float)((double)cs * cj - sc * sj);
                w = (float)(ss * sj + (double)cc * cj);
            }

            if (n == 1)
            {
                aj = -aj;
            }

            Set(ref a0, ref a1, ref a2, i, ai);
            Set(ref a0, ref a1, ref a2, j, aj);
            Set(ref a0, ref a1, ref a2, k, ak);
            SetRotate(w, a0, a1, a2);

            static int Next(int idx) => idx switch { 0 => 1, 1 => 2, 2 => 0, _ => 1 };

            static void Set(ref float v0, ref float v1, ref float v2, int index, float value)
            {
                switch (index)
                {
                    case 0: v0 = value; break;
                    case 1: v1 = value; break;
                    default: v2 = value; break;
                }
            }
        }

    /// <summary><c>SimplePartArray.Update</c> as it stood before its idle shortcut (CSequence::apply_physics with an empty
    /// animation list), on this frame as the offset.</summary>
    public void SequenceUpdate(float quantum, Vector3 sequenceVelocity, Vector3 sequenceOmega)
    {
        double s = Math.Abs((double)quantum);
        if (quantum < 0f)
        {
            s = -s;
        }

        Vector3 v = sequenceVelocity;
        Vector3 o = Origin;
        Origin = new Vector3((float)(s * v.X + o.X), (float)(s * v.Y + o.Y), (float)(s * v.Z + o.Z));
        Vector3 w = sequenceOmega;
        Rotate(new Vector3((float)(s * w.X), (float)(s * w.Y), (float)(s * w.Z)));
    }

    /// <summary><c>Frame::localtoglobal</c> as it stood before it was marked for inlining (#38).</summary>
    public readonly Vector3 LocalToGlobal(Vector3 p)
    {
        double z = (double)M33 * p.Z + (double)M13 * p.X + (double)M23 * p.Y + Origin.Z;
        double y = (double)M32 * p.Z + (double)M12 * p.X + (double)M22 * p.Y + Origin.Y;
        double x = (double)M31 * p.Z + (double)M11 * p.X + (double)M21 * p.Y + Origin.X;
        return new Vector3((float)x, (float)y, (float)z);
    }

    /// <summary><c>Frame::globaltolocal</c> as it stood before it was marked for inlining (#38).</summary>
    public readonly Vector3 GlobalToLocal(Vector3 p)
    {
        float dx = p.X - Origin.X;
        float dy = p.Y - Origin.Y;
        double dzWide = (double)p.Z - Origin.Z;
        float dz = (float)dzWide;
        double z = dzWide * M33 + (double)dx * M31 + (double)dy * M32;
        double y = (double)dz * M23 + (double)dx * M21 + (double)dy * M22;
        double x = (double)dz * M13 + (double)dx * M11 + (double)dy * M12;
        return new Vector3((float)x, (float)y, (float)z);
    }

    /// <summary><c>AFrame.Combine</c> (CSequence's Frame-AFrame combine) as it stood before #38 stored the origin by
    /// component and inlined set_rotate.</summary>
    public void CombineAFrame(in AFrame f2)
    {
        double px = f2.Origin.X, py = f2.Origin.Y, pz = f2.Origin.Z;
        float ox = (float)(M31 * pz + M11 * px + M21 * py + Origin.X);
        float oy = (float)(M32 * pz + M12 * px + M22 * py + Origin.Y);
        float oz = (float)(M33 * pz + M13 * px + M23 * py + Origin.Z);
        double aw = Qw, ax = Qx, ay = Qy, az = Qz;
        double bw = f2.Qw, bx = f2.Qx, by = f2.Qy, bz = f2.Qz;
        float nz = (float)(ax * by + bz * aw - ay * bx + az * bw);
        float ny = (float)(by * aw - ax * bz + az * bx + ay * bw);
        float nx = (float)(ax * bw + aw * bx + bz * ay - by * az);
        float nw = (float)(aw * bw - ax * bx - by * ay - bz * az);
        Origin = new Vector3(ox, oy, oz);
        SetRotate(nw, nx, ny, nz);
    }

    /// <summary><c>AnimSequence.ApplyPhysics</c> (CSequence::apply_physics) as it stood before #38 (the origin packed into a
    /// Vector3, omega·s handed to rotate as one), with rotate recomputing grotate's rotation.</summary>
    public void ApplyPhysics(double quantum, double sign, Vector3 velocity, Vector3 omega)
    {
        double s = Math.Abs(quantum);
        if (sign < 0.0)
        {
            s = -s;
        }

        Vector3 o = Origin;
        double dx = s * velocity.X;
        float dy = (float)(s * velocity.Y);
        float dz = (float)(s * velocity.Z);
        Origin = new Vector3((float)(dx + o.X), (float)((double)dy + o.Y), (float)((double)dz + o.Z));
        float wx = (float)(s * omega.X);
        float wy = (float)(s * omega.Y);
        float wz = (float)(s * omega.Z);
        Rotate(new Vector3(wx, wy, wz));
    }
}
