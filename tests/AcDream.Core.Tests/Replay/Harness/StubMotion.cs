using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Seams;

namespace AcDream.Core.Tests.Replay.Harness;

/// <summary>A movement manager whose motion interpreter reports fixed speeds (or none).</summary>
public sealed class StubMotion : IMovementManager, IMotionInterpreter, IMovementManagerFactory
{
    /// <summary>Creates a stub; <paramref name="hasInterpreter"/> false makes <see cref="MotionInterpreter"/> null.</summary>
    public StubMotion(double maxSpeed, double adjustedMaxSpeed, bool hasInterpreter = true)
    {
        MaxSpeed = maxSpeed;
        AdjustedMaxSpeed = adjustedMaxSpeed;
        HasInterpreter = hasInterpreter;
    }

    /// <summary>get_max_speed result, m/s (the seam's <see cref="IMotionInterpreter.MaxSpeed"/>).</summary>
    public double MaxSpeed { get; set; }

    /// <summary>get_adjusted_max_speed result, m/s (the seam's <see cref="IMotionInterpreter.AdjustedMaxSpeed"/>).</summary>
    public double AdjustedMaxSpeed { get; set; }

    /// <summary>Whether an interpreter exists.</summary>
    public bool HasInterpreter { get; }

    /// <summary>IsMovingTo result.</summary>
    public bool MovingTo { get; set; }

    /// <summary>Error code of the last CancelMoveTo, or 0.</summary>
    public MotionError LastCancel { get; private set; }

    /// <inheritdoc />
    public void CancelMoveTo(MotionError error) => LastCancel = error;

    /// <inheritdoc />
    public IMotionInterpreter? MotionInterpreter => HasInterpreter ? this : null;

    /// <inheritdoc />
    public IMovementManager Create(PhysicsObj obj) => this;

    /// <inheritdoc />
    public bool IsMovingTo() => MovingTo;

    /// <inheritdoc />
    public void UseTime()
    {
    }

    /// <inheritdoc />
    public void LeaveGround()
    {
    }

    /// <inheritdoc />
    public void HitGround()
    {
    }

    /// <inheritdoc />
    public void HandleEnterWorld()
    {
    }
}
