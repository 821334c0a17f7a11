namespace AcDream.Core.Physics.Objects.Seams;

/// <summary>
/// A stand-in movement manager with no motion interpreter: it answers retail's no-weenie speeds and ignores the ground
/// events. The world creates the retail <see cref="Motion.MovementManager"/> by default; a client or test that wants an
/// object without motion installs this one through an <see cref="IMovementManagerFactory"/> (or sets
/// <see cref="PhysicsObj.Movement"/>). The engine callbacks are implemented explicitly.
/// </summary>
public sealed class BasicMovementManager : IMovementManager, IMotionInterpreter
{
    /// <summary>Retail's speed with no weenie: <c>1.0 * 4.0</c> (CMotionInterp::get_max_speed, acclient.c:343485).</summary>
    public const double NoWeenieMaxSpeed = 1.0 * 4.0;

    /// <inheritdoc />
    public IMotionInterpreter? MotionInterpreter => this;

    /// <summary>Number of per-step updates the engine gave it (<see cref="IMovementManager.UseTime"/> calls).</summary>
    public int UseTimeCount { get; private set; }

    /// <inheritdoc />
    void IMovementManager.UseTime() => UseTimeCount++;

    /// <inheritdoc />
    void IMovementManager.LeaveGround()
    {
    }

    /// <inheritdoc />
    void IMovementManager.HitGround()
    {
    }

    /// <inheritdoc />
    public bool IsMovingTo() => false;

    /// <inheritdoc />
    void IMovementManager.HandleEnterWorld()
    {
    }

    /// <inheritdoc />
    // retail: CMotionInterp::get_max_speed (acclient.c:343485), weenie_obj == null branch
    public double MaxSpeed => NoWeenieMaxSpeed;

    /// <inheritdoc />
    // retail: CMotionInterp::get_adjusted_max_speed (acclient.c:343511), weenie_obj == null, not running
    public double AdjustedMaxSpeed => NoWeenieMaxSpeed;
}
