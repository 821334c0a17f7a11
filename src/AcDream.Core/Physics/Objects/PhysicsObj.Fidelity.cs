// PhysicsObj — the non-retail fidelity paths of PhysicsProfile (Arithmetic, RenormaliseEvery); no retail function.
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Objects;

// The tick's fidelity switches (PhysicsProfile.Arithmetic, PhysicsProfile.RenormaliseEvery): the retail path is taken
// whenever the switches have their defaults; the other paths are NOT retail and exist to be measured
// (docs/accuracy-vs-cost.md).
public sealed partial class PhysicsObj
{
    private int _rotationChanges;

    // Counts a rotation change and says whether it renormalises (always under retail's RenormaliseEvery = 1).
    private bool RenormaliseThisChange(int every)
    {
        if (every == 1)
        {
            return true;
        }

        if (every == 0)
        {
            return false;
        }

        if (++_rotationChanges >= every)
        {
            _rotationChanges = 0;
            return true;
        }

        return false;
    }

    // Frame::combine of UpdatePositionInternal under the world's profile (retail: Combine).
    private void CombineForProfile(ref Frame newFrame, in Frame offset)
    {
        PhysicsProfile p = World.Profile;
        if (!RenormaliseThisChange(p.RenormaliseEvery))
        {
            newFrame.CombineNoRenormalise(_position.Frame, offset);
        }
        else if (p.Arithmetic == ArithmeticMode.Float32)
        {
            newFrame.CombineFloat32(_position.Frame, offset);
        }
        else
        {
            newFrame.Combine(_position.Frame, offset);
        }
    }

    // Frame::grotate of UpdatePhysicsInternal under the world's profile (retail: GRotate).
    private void RotateForProfile(ref Frame frame, Vector3 w)
    {
        PhysicsProfile p = World.Profile;
        if ((double)w.X * w.X + (double)w.Y * w.Y + (double)w.Z * w.Z < (double)PhysicsGlobals.Epsilon * PhysicsGlobals.Epsilon)
        {
            return; // no rotation change (grotate returns early): the renormalisation count does not move
        }

        if (!RenormaliseThisChange(p.RenormaliseEvery))
        {
            frame.GRotateNoRenormalise(w);
        }
        else if (p.Arithmetic == ArithmeticMode.Float32)
        {
            frame.GRotateFloat32(w);
        }
        else
        {
            frame.GRotate(StepRotation(w));
        }
    }

    /// <summary>
    /// <see cref="UpdatePhysicsInternal"/> in plain float32 (<see cref="ArithmeticMode.Float32"/>): same steps and order,
    /// every product and sum rounded to single precision, friction through <c>MathF.Pow</c>. Not retail.
    /// </summary>
    private void UpdatePhysicsInternalFloat32(float q, ref Frame frame)
    {
        Vector3 v = _velocity;
        float mag2 = v.X * v.X + v.Y * v.Y + v.Z * v.Z;
        if (mag2 <= 0.0f)
        {
            if (Movement is null && (_transientState & TransientState.OnWalkable) != 0)
            {
                _transientState &= ~TransientState.Active;
            }
        }
        else
        {
            if (mag2 > (float)PhysicsGlobals.MaxVelocitySquared)
            {
                float inv = 1f / System.MathF.Sqrt(mag2);
                mag2 = (float)PhysicsGlobals.MaxVelocitySquared;
                v = new Vector3(50f * (v.X * inv), 50f * (v.Y * inv), 50f * (v.Z * inv));
                _velocity = v;
            }

            CalcFrictionFloat32(q, mag2);
            if (mag2 - 0.25f * 0.25f < PhysicsGlobals.Epsilon)
            {
                _velocity = Vector3.Zero;
            }

            v = _velocity;
            Vector3 a = _acceleration;
            Vector3 o = frame.Origin;
            float ox = q * v.X + a.X * 0.5f * q * q + o.X;
            float oy = q * v.Y + a.Y * 0.5f * q * q + o.Y;
            float oz = q * v.Z + a.Z * 0.5f * q * q + o.Z;
            frame.Origin = new Vector3(ox, oy, oz);
        }

        Vector3 acc = _acceleration;
        Vector3 vel = _velocity;
        _velocity = new Vector3(q * acc.X + vel.X, q * acc.Y + vel.Y, q * acc.Z + vel.Z);
        Vector3 w = _omega;
        RotateForProfile(ref frame, new Vector3(q * w.X, q * w.Y, q * w.Z));
    }

    // calc_friction in plain float32 (not retail; see UpdatePhysicsInternalFloat32).
    private void CalcFrictionFloat32(float quantum, float velocityMag2)
    {
        if ((_transientState & TransientState.OnWalkable) == 0)
        {
            return;
        }

        Vector3 v = _velocity;
        Vector3 n = ContactPlaneNormal;
        float d = n.Z * v.Z + n.Y * v.Y + n.X * v.X;
        if (d >= 0.25f)
        {
            return;
        }

        v = new Vector3(v.X - d * n.X, v.Y - d * n.Y, v.Z - d * n.Z);
        float f = _friction;
        if ((_state & PhysicsState.Sledding) != 0)
        {
            f = velocityMag2 >= 1.5625f
                ? (velocityMag2 < 6.25f || (float)SleddingSteepCos <= n.Z ? _friction : 0.2f)
                : 1f;
        }

        float k = System.MathF.Pow(1f - f, quantum);
        _velocity = new Vector3(k * v.X, k * v.Y, k * v.Z);
    }
}
