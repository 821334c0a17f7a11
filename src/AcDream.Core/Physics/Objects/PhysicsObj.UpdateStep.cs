using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects.Parts;

namespace AcDream.Core.Physics.Objects;

// The step's shortcuts that keep retail's bits: the rotation of a repeated omega·dt, the store of the step's frame, and the
// direct calls into the built-in part array.
public sealed partial class PhysicsObj
{
    // The rotation (Frame::grotate's axis-angle quaternion) of the last omega·dt this object turned by, keyed by its bits:
    // with constant omega and step the displacement repeats, and the square root, division, sine and cosine are skipped.
    // The rotation is a function of the displacement's bits alone, so a hit gives what recomputing would.
    private int _rotationKeyX, _rotationKeyY, _rotationKeyZ;
    private bool _rotationKnown;
    private AxisAngle _rotation;

    /// <summary>The rotation of <paramref name="w"/> (|w|² at least EPSILON²), from the one-entry cache when w repeats.</summary>
    internal ref readonly AxisAngle StepRotation(Vector3 w)
    {
        int x = BitConverter.SingleToInt32Bits(w.X);
        int y = BitConverter.SingleToInt32Bits(w.Y);
        int z = BitConverter.SingleToInt32Bits(w.Z);
        if (!_rotationKnown || x != _rotationKeyX || y != _rotationKeyY || z != _rotationKeyZ)
        {
            _rotationKnown = AxisAngle.TryCreate(w, out _rotation);
            _rotationKeyX = x;
            _rotationKeyY = y;
            _rotationKeyZ = z;
        }

        return ref _rotation;
    }

    /// <summary>
    /// <see cref="SetFrame"/> for the frame a step has just built (the object is awake: <see cref="UpdateObject"/> touched
    /// it): the same checks, repair and stores, without the wake test and the extra copies, and with the built-in part
    /// array's store called directly.
    /// </summary>
    /// <exception cref="ArgumentException">The origin is NaN or infinite (state unchanged), as <see cref="SetFrame"/>.</exception>
    // retail: CPhysicsObj::set_frame (acclient.c:321327), from UpdateObjectInternal (acclient.c:322718)
    internal void StoreStepFrame(ref Frame frame)
    {
        ThrowIfNotFinite(frame.Origin, nameof(frame));
        if (!frame.IsValid() && frame.IsValidExceptForHeading())
        {
            frame.SetQuaternionRaw(0f, 0f, 0f, 0f);
        }

        _position.Frame = frame;
        if ((_state & PhysicsState.ParticleEmitter) == 0)
        {
            IPartArray? parts = _partArray;
            if (parts is SimplePartArray simple)
            {
                simple.StoreCheckedFrame(frame);
            }
            else
            {
                parts?.SetFrame(frame);
            }
        }

        UpdateChildrenInternal();
    }

    /// <summary>The part array's root motion for a step (the built-in part array called directly).</summary>
    private void UpdatePartArray(float quantum, ref Frame offset)
    {
        IPartArray? parts = _partArray;
        if (parts is SimplePartArray simple)
        {
            simple.Update(quantum, ref offset);
        }
        else
        {
            parts?.Update(quantum, ref offset);
        }
    }

    /// <summary>The part array's movement notification for a step (the built-in part array called directly).</summary>
    private void HandlePartArrayMovement()
    {
        IPartArray? parts = _partArray;
        if (parts is SimplePartArray simple)
        {
            simple.HandleMovement();
        }
        else
        {
            parts?.HandleMovement();
        }
    }
}
