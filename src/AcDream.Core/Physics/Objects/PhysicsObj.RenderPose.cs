// PhysicsObj — render interpolation: the two last committed poses and the blend between them (not retail; no retail function).
using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Objects;

// Render interpolation: the two last physics poses the world tick committed and the blended pose between them. A library
// addition, not retail (retail's renderer drew m_position as it stood). Recording copies two positions per visit; nothing
// here is read by the physics, so the simulation is bit-identical with or without it.
public sealed partial class PhysicsObj
{
    // The pose the object's last update by the world tick began from, compact (cell, origin, quaternion: 32 bytes; the
    // cached matrix is rebuilt on read), and the times of that pose and of the update's end. The pose the update ended with
    // is Position itself unless the object was placed since (_poseCut).
    private uint _posePrevCell;
    private Vector3 _posePrevOrigin;
    private Quaternion _posePrevRotation;
    private double _posePrevTime;
    private double _poseCurrTime;

    // A placement (teleport, blip, set frame, enter world, lost cell, a client's commit) since the last recorded pose: the
    // object is drawn at Position, not blended, until its next update records a new pair.
    private bool _poseCut = true;

    /// <summary>
    /// The object's physics pose as its last update by the world tick began (library addition for render interpolation; no
    /// retail symbol); the pose that update ended with is <see cref="Position"/>. Equal to it when that update placed the object
    /// (a teleport or blip), which is drawn without blending.
    /// </summary>
    public Position PreviousPose
    {
        get
        {
            Frame f = Frame.Identity;
            f.Origin = _posePrevOrigin;
            Quaternion q = _posePrevRotation;
            f.SetQuaternionRaw(q.W, q.X, q.Y, q.Z);
            f.Cache();
            return new Position(_posePrevCell, f);
        }
    }

    /// <summary>The client-clock time <see cref="PreviousPose"/> belongs to, seconds: the object's <see cref="UpdateTime"/> as
    /// its last update by the world tick began (library addition).</summary>
    public double PreviousPoseTime => _posePrevTime;

    /// <summary>The client-clock time the pose of the object's last update by the world tick belongs to, seconds: its
    /// <see cref="UpdateTime"/> as that update ended (library addition). That pose is <see cref="Position"/> unless
    /// <see cref="IsPlacedSinceLastUpdate"/>.</summary>
    public double CurrentPoseTime => _poseCurrTime;

    /// <summary>True when the object was placed since its last update by the world tick recorded its poses (a teleport,
    /// <see cref="SetPosition"/>, <see cref="EnterWorld"/>, <see cref="SetFrame"/>, <see cref="CommitTransition"/>...; also
    /// before its first update) or is attached to a parent: <see cref="GetRenderPose"/> then answers <see cref="Position"/>,
    /// not a blend (library addition).</summary>
    public bool IsPlacedSinceLastUpdate => _poseCut || Parent is not null;

    /// <summary>
    /// The pose to draw at <paramref name="renderTime"/> (library addition for render interpolation; no retail symbol): the
    /// blend of <see cref="PreviousPose"/> and <see cref="Position"/> at the fraction of their times
    /// (<see cref="PreviousPoseTime"/>, <see cref="CurrentPoseTime"/>) that <paramref name="renderTime"/> reaches — the origin
    /// interpolated linearly, the rotation spherically (shortest arc), both in <see cref="Position"/>'s landblock frame (the
    /// previous pose is moved into it first, so a landblock crossing blends straight across the edge), and the cell the
    /// outdoor cell under the blended origin (indoor: the nearer pose's cell). Draw every object at
    /// <see cref="PhysicsWorld.RenderTime"/>.
    /// </summary>
    /// <param name="renderTime">The time to draw, seconds on the client clock: finite. At or before
    /// <see cref="PreviousPoseTime"/> it answers <see cref="PreviousPose"/>, from <see cref="CurrentPoseTime"/> on
    /// <see cref="Position"/> (no extrapolation).</param>
    /// <returns>The blended pose; <see cref="Position"/> itself when <see cref="IsPlacedSinceLastUpdate"/> (a teleport or blip is
    /// not blended). Reading it changes nothing.</returns>
    /// <exception cref="ArgumentException"><paramref name="renderTime"/> is NaN or infinite.</exception>
    public Position GetRenderPose(double renderTime)
    {
        if (!double.IsFinite(renderTime))
        {
            throw new ArgumentException("The render time must be finite (seconds on the client clock).", nameof(renderTime));
        }

        if (IsPlacedSinceLastUpdate)
        {
            return _position;
        }

        double t0 = _posePrevTime;
        double t1 = _poseCurrTime;
        if (!(renderTime < t1) || !(t1 > t0))
        {
            return _position;
        }

        if (!(renderTime > t0))
        {
            return PreviousPose;
        }

        return Blend(PreviousPose, _position, (renderTime - t0) / (t1 - t0));
    }

    /// <summary>Starts an update's pose record: the placements from here on cut it.</summary>
    /// <returns>Whether the object was placed since the last record (the mark this clears; <see cref="EndPoseRecord"/> puts it
    /// back when the update records no pair).</returns>
    private bool BeginPoseRecord()
    {
        bool placed = _poseCut;
        _poseCut = false;
        return placed;
    }

    /// <summary>Records the pose pair of the update that began at <paramref name="start"/> (time <paramref name="startTime"/>)
    /// and ended now, at <see cref="UpdateTime"/>; a placement during the update makes the pair the end pose twice.</summary>
    private void EndPoseRecord(in Position start, double startTime, bool placedBefore)
    {
        double end = _scene.UpdateTime;
        if (!_poseCut && !(end > startTime))
        {
            // No time consumed (a dt at or below EPSILON, or one the ACE profile accumulates): no step ran and nothing placed
            // the object during the update, so the pair recorded before still describes its path — unless the object was
            // placed before the update (then there is no such pair: it stays drawn at its position, and PreviousPose, never
            // recorded, is not read as one).
            _poseCut = placedBefore;
            return;
        }

        _poseCurrTime = end;
        if (_poseCut)
        {
            _poseCut = false;
            StorePreviousPose(_position);
            _posePrevTime = end;
        }
        else
        {
            StorePreviousPose(start);
            _posePrevTime = startTime;
        }
    }

    private void StorePreviousPose(in Position p)
    {
        _posePrevCell = p.ObjCellId;
        _posePrevOrigin = p.Frame.Origin;
        _posePrevRotation = new Quaternion(p.Frame.Qx, p.Frame.Qy, p.Frame.Qz, p.Frame.Qw);
    }

    /// <summary>Marks a placement: the object is drawn at its position, not blended, until its next update's record.</summary>
    private void CutPose() => _poseCut = true;

    // The blend of two poses at fraction a in (0, 1), in b's landblock frame.
    private static Position Blend(in Position a, in Position b, double f)
    {
        Vector3 pa = b.LocalToGlobal(a);
        Vector3 pb = b.Frame.Origin;
        var origin = new Vector3(
            (float)(pa.X + (pb.X - (double)pa.X) * f),
            (float)(pa.Y + (pb.Y - (double)pa.Y) * f),
            (float)(pa.Z + (pb.Z - (double)pa.Z) * f));
        Frame frame = Frame.Identity;
        frame.Origin = origin;
        Slerp(a.Frame, b.Frame, f, out double w, out double x, out double y, out double z);
        frame.SetRotate((float)w, (float)x, (float)y, (float)z);

        uint cell = b.ObjCellId;
        if (LandDefs.IsOutdoorCell(a.ObjCellId) && LandDefs.IsOutdoorCell(b.ObjCellId))
        {
            uint id = cell;
            Vector3 o = origin;
            if (LandDefs.AdjustToOutside(ref id, ref o))
            {
                cell = id;
                frame.Origin = o;
            }
        }
        else if (f < 0.5 && a.ObjCellId != b.ObjCellId)
        {
            // Indoor: the nearer pose's cell; the origin moves into that cell's landblock.
            Vector3 off = LandDefs.GetBlockOffset(a.ObjCellId, b.ObjCellId);
            cell = a.ObjCellId;
            frame.Origin = new Vector3(origin.X + off.X, origin.Y + off.Y, origin.Z + off.Z);
        }

        return new Position(cell, frame);
    }

    // Spherical interpolation of two unit quaternions along the shorter arc, in double; a normalised linear blend when they
    // are nearly equal (the spherical formula divides by sin of a tiny angle).
    private static void Slerp(in Frame a, in Frame b, double f, out double w, out double x, out double y, out double z)
    {
        double aw = a.Qw, ax = a.Qx, ay = a.Qy, az = a.Qz;
        double bw = b.Qw, bx = b.Qx, by = b.Qy, bz = b.Qz;
        double dot = aw * bw + ax * bx + ay * by + az * bz;
        if (dot < 0.0)
        {
            dot = -dot;
            bw = -bw;
            bx = -bx;
            by = -by;
            bz = -bz;
        }

        double ka, kb;
        if (dot > 0.9995)
        {
            ka = 1.0 - f;
            kb = f;
        }
        else
        {
            double theta = Math.Acos(Math.Min(dot, 1.0));
            double s = Math.Sin(theta);
            ka = Math.Sin((1.0 - f) * theta) / s;
            kb = Math.Sin(f * theta) / s;
        }

        w = ka * aw + kb * bw;
        x = ka * ax + kb * bx;
        y = ka * ay + kb * by;
        z = ka * az + kb * bz;
        double n = Math.Sqrt(w * w + x * x + y * y + z * z);
        w /= n;
        x /= n;
        y /= n;
        z /= n;
    }
}
