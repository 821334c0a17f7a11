using AcDream.Core.Physics.Objects.Seams;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// The character questions the motion interpreter asks (retail: virtual functions of the object's <c>CWeenieObject</c>,
/// answered on the client by <c>ACCWeenieObject</c> from the character's qualities). Set it as the object's
/// <see cref="Objects.PhysicsObj.Weenie"/> before the movement manager is created; an object without one moves at retail's
/// no-weenie rates (run rate 1). Called inside the tick: implementations must not allocate.
/// </summary>
public interface IMotionWeenie : IWeenieObject
{
    /// <summary>The object is this client's own player (retail <c>IsThePlayer</c>, vtable slot 5): its raw commands are
    /// interpreted here; everyone else's arrive interpreted.</summary>
    bool IsThePlayer { get; }

    /// <summary>The run rate, the speed multiplier of a run (retail <c>InqRunRate</c>, slot 13); false when the object
    /// cannot say (the interpreter then uses the rate last received).</summary>
    bool InqRunRate(out float rate);

    /// <summary>The launch speed of a jump of charge <paramref name="extent"/> (0..1), m/s upwards (retail
    /// <c>InqJumpVelocity</c>, slot 12); false when the object cannot jump.</summary>
    bool InqJumpVelocity(float extent, out float vz);

    /// <summary>The object may charge a jump of <paramref name="extent"/> (retail <c>CanJump</c>, slot 15).</summary>
    bool CanJump(float extent);

    /// <summary>The stamina a jump of <paramref name="extent"/> costs (retail <c>JumpStaminaCost</c>, slot 16); false
    /// refuses the jump.</summary>
    bool JumpStaminaCost(float extent, out int cost);
}
