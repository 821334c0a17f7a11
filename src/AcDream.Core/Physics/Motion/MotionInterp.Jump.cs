using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Motion;

public sealed partial class MotionInterp
{
    /// <summary>The launch speed of the charged jump, m/s upwards: 0 below a charge of EPSILON, else the weenie's
    /// <see cref="IMotionWeenie.InqJumpVelocity"/> of the charge clamped to 1 (0 when it refuses; 10 with no weenie). Retail
    /// <c>CMotionInterp::get_jump_v_z</c>.</summary>
    // retail: CMotionInterp::get_jump_v_z (acclient.c:343342)
    public double JumpVelocityZ
    {
        get
        {
            float extent = JumpExtent;
            if (extent < (double)PhysicsGlobals.Epsilon)
            {
                return 0.0;
            }

            if (extent > 1.0)
            {
                extent = 1.0f;
            }

            if (_weenieObj is null)
            {
                return NoWeenieJumpVelocity;
            }

            return _weenieObj.InqJumpVelocity(extent, out float vz) ? vz : 0.0;
        }
    }

    /// <summary>Whether a jump may be charged: <see cref="MotionError.CantJumpLoadedDown"/> when the weenie refuses the
    /// charge, <see cref="MotionError.YouCantJumpFromThisPosition"/> while fallen, crouching, sitting or sleeping, else
    /// <see cref="MotionError.None"/>.</summary>
    // retail: CMotionInterp::jump_charge_is_allowed (acclient.c:343317)
    public MotionError JumpChargeIsAllowed()
    {
        if (_weenieObj is not null && !_weenieObj.CanJump(JumpExtent))
        {
            return MotionError.CantJumpLoadedDown;
        }

        MotionCommand f = InterpretedState.ForwardCommand;
        return f == MotionCommand.Fallen || ((uint)f > 0x41000011u && f <= MotionCommand.Sleeping)
            ? MotionError.YouCantJumpFromThisPosition
            : MotionError.None;
    }

    /// <summary>
    /// Starts charging a jump (<see cref="JumpChargeIsAllowed"/>); charging while standing still on the ground starts a
    /// standing long jump.
    /// </summary>
    /// <returns><see cref="MotionError.None"/> on success, else the error.</returns>
    // retail: CMotionInterp::charge_jump (acclient.c:343844)
    public MotionError ChargeJump()
    {
        if (_weenieObj is not null && !_weenieObj.CanJump(JumpExtent))
        {
            return MotionError.CantJumpLoadedDown;
        }

        InterpretedMotionState s = InterpretedState;
        MotionCommand f = s.ForwardCommand;
        if (f == MotionCommand.Fallen || ((uint)f > 0x41000011u && f <= MotionCommand.Sleeping))
        {
            return MotionError.YouCantJumpFromThisPosition;
        }

        if (_physicsObj is not null && OnGround(_physicsObj) && f == MotionCommand.Ready && s.SidestepCommand == MotionCommand.None
            && s.TurnCommand == MotionCommand.None)
        {
            _physicsObj.Touch();
            StandingLongJump = true;
        }

        return MotionError.None;
    }

    /// <summary>True when the object may start <paramref name="motion"/> now: turns, Falling and Dead always; any motion
    /// for a non-creature or an object without gravity, or on the ground.</summary>
    // retail: CMotionInterp::contact_allows_move (acclient.c:343881)
    public bool ContactAllowsMove(MotionCommand motion)
    {
        PhysicsObj? obj = _physicsObj;
        if (obj is null)
        {
            return false;
        }

        if (motion > MotionCommand.Falling)
        {
            if (motion >= MotionCommand.TurnRight && motion <= MotionCommand.TurnLeft)
            {
                return true;
            }
        }
        else if (motion == MotionCommand.Falling || motion == MotionCommand.Dead)
        {
            return true;
        }

        if (_weenieObj is not null && !_weenieObj.IsCreature)
        {
            return true;
        }

        return !HasGravity(obj) || OnGround(obj);
    }

    /// <summary>
    /// Whether a jump of charge <paramref name="extent"/> may start: <see cref="MotionError.YouCantJumpWhileInTheAir"/> in
    /// the air, <see cref="MotionError.GeneralMovementFailure"/> fully constrained, the jump
    /// error of the oldest unfinished motion, <see cref="JumpChargeIsAllowed"/>, <see cref="MotionAllowsJump"/> of the
    /// forward motion, <see cref="MotionError.GeneralMovementFailure"/> when the weenie refuses the stamina cost; else
    /// <see cref="MotionError.None"/> with the cost in
    /// <paramref name="staminaCost"/> (0 with no weenie).
    /// </summary>
    /// <param name="extent">The jump's charge, 0..1 (the power bar's level).</param>
    /// <param name="staminaCost">The stamina the jump costs (the weenie's <see cref="IMotionWeenie.JumpStaminaCost"/>).</param>
    /// <exception cref="System.ArgumentException"><paramref name="extent"/> is NaN or infinite.</exception>
    /// <exception cref="System.ArgumentOutOfRangeException"><paramref name="extent"/> is outside [0, 1].</exception>
    // retail: CMotionInterp::jump_is_allowed (acclient.c:343921)
    public MotionError JumpIsAllowed(float extent, out int staminaCost)
    {
        CheckJumpExtent(extent);
        staminaCost = 0;
        PhysicsObj? obj = _physicsObj;
        if (obj is null
            || !((_weenieObj is not null && !_weenieObj.IsCreature) || !HasGravity(obj) || OnGround(obj)))
        {
            return MotionError.YouCantJumpWhileInTheAir;
        }

        if (obj.IsFullyConstrained)
        {
            return MotionError.GeneralMovementFailure;
        }

        if (PendingMotions.Count != 0 && PendingMotions.Head.JumpErrorCode != MotionError.None)
        {
            return PendingMotions.Head.JumpErrorCode;
        }

        MotionError result = JumpChargeIsAllowed();
        if (result != MotionError.None)
        {
            return result;
        }

        MotionError motionError = MotionAllowsJump(InterpretedState.ForwardCommand);
        if (motionError != MotionError.None || _weenieObj is null)
        {
            return motionError;
        }

        return _weenieObj.JumpStaminaCost(extent, out staminaCost) ? motionError : MotionError.GeneralMovementFailure;
    }

    /// <summary>
    /// Jumps with charge <paramref name="extent"/> (0..1): when <see cref="JumpIsAllowed"/>, records the charge and takes
    /// the object off the ground (ON_WALKABLE cleared, so <see cref="LeaveGround"/> gives it the launch velocity);
    /// otherwise ends a standing long jump.
    /// </summary>
    /// <returns><see cref="MotionError.None"/> on success, else the error.</returns>
    /// <param name="extent">The jump's charge, 0..1: the power bar's level, as retail's only caller
    /// (<c>ClientCombatSystem::DoJump</c>) passes it. The launch speed (<see cref="JumpVelocityZ"/>) and the stamina cost
    /// (<see cref="IMotionWeenie.JumpStaminaCost"/>) both come from it.</param>
    /// <param name="staminaCost">The stamina the jump costs (0 with no weenie or when refused).</param>
    /// <exception cref="System.ArgumentException"><paramref name="extent"/> is NaN or infinite (nothing changes).</exception>
    /// <exception cref="System.ArgumentOutOfRangeException"><paramref name="extent"/> is outside [0, 1] (nothing changes):
    /// retail's launch speed clamps the extent to 1 but its stamina cost does not, so a larger extent would jump as 1 and
    /// cost more.</exception>
    // retail: CMotionInterp::jump (acclient.c:344223)
    public MotionError Jump(float extent, out int staminaCost)
    {
        CheckJumpExtent(extent);

        staminaCost = 0;
        PhysicsObj? obj = _physicsObj;
        if (obj is null)
        {
            return MotionError.NoPhysicsObject;
        }

        obj.Touch();
        obj.CancelMoveTo();
        MotionError result = JumpIsAllowed(extent, out staminaCost);
        if (result != MotionError.None)
        {
            StandingLongJump = false;
            return result;
        }

        JumpExtent = extent;
        obj.SetOnWalkable(false);
        return result;
    }

    // non-retail: the extent is checked at the public entry. Retail's caller only passes the power bar's level (0..1);
    // get_jump_v_z clamps to 1 but JumpStaminaCost does not, so an extent above 1 would jump as 1 and cost as given.
    private static void CheckJumpExtent(float extent)
    {
        if (!float.IsFinite(extent))
        {
            throw new System.ArgumentException("The jump extent must be finite.", nameof(extent));
        }

        if (extent < 0f || extent > 1f)
        {
            throw new System.ArgumentOutOfRangeException(nameof(extent), extent,
                "The jump extent is the power bar's level, 0..1 (a larger extent would jump as 1 and cost stamina as given).");
        }
    }

    /// <summary>
    /// The velocity the object leaves the ground with, local axes: <see cref="StateVelocity"/> with z the jump's
    /// <see cref="JumpVelocityZ"/>; when all three are below EPSILON, the object's current velocity in local axes. Retail
    /// <c>CMotionInterp::get_leave_ground_velocity</c>.
    /// </summary>
    // retail: CMotionInterp::get_leave_ground_velocity (acclient.c:343805)
    public Vector3 LeaveGroundVelocity
    {
        get
        {
            Vector3 v = StateVelocity;
            float vz = (float)JumpVelocityZ;
            v.Z = vz;
            if (Math.Abs(v.X) < (double)PhysicsGlobals.Epsilon && Math.Abs(v.Y) < (double)PhysicsGlobals.Epsilon
                && Math.Abs(vz) < (double)PhysicsGlobals.Epsilon && _physicsObj is not null)
            {
                v = GlobalVelocityToLocal(_physicsObj);
            }

            return v;
        }
    }

    /// <summary>The object landed: a creature with gravity drops its link animations and re-applies its movement (so a
    /// run that was recorded in the air starts now).</summary>
    // retail: CMotionInterp::HitGround (acclient.c:344428)
    internal void HitGround()
    {
        PhysicsObj? obj = _physicsObj;
        if (obj is null || (_weenieObj is not null && !_weenieObj.IsCreature) || !HasGravity(obj))
        {
            return;
        }

        obj.RemoveLinkAnimations();
        ApplyCurrentMovement(false, false);
    }

    /// <summary>The object left the ground: a creature with gravity takes its leave-ground velocity (the jump), the jump
    /// charge and standing long jump end, and the movement is re-applied (Falling).</summary>
    // retail: CMotionInterp::LeaveGround (acclient.c:344456)
    internal void LeaveGround()
    {
        PhysicsObj? obj = _physicsObj;
        if (obj is null || (_weenieObj is not null && !_weenieObj.IsCreature) || !HasGravity(obj))
        {
            return;
        }

        Vector3 v = LeaveGroundVelocity;
        // non-retail: a non-finite leave-ground velocity is not applied (the velocity is kept). The API's domains keep the
        // interpreter's own values finite; only a client's weenie can still give one (a run rate of zero or below, a NaN jump
        // velocity), and set_local_velocity's refusal would have thrown out of SetPosition, MoveOrTeleport, Jump or a tick
        // after they had changed the object.
        if (VectorMath.IsFinite(v))
        {
            obj.SetLocalVelocity(v);
        }
        StandingLongJump = false;
        JumpExtent = 0f;
        obj.RemoveLinkAnimations();
        ApplyCurrentMovement(false, false);
    }

    /// <summary>Both states back to their defaults, the motion table initialised, a Ready queued, then
    /// <see cref="LeaveGround"/> (an object is created in the air until it lands).</summary>
    /// <exception cref="System.InvalidOperationException">The interpreter has no physics object.</exception>
    // retail: CMotionInterp::enter_default_state (acclient.c:344559)
    public void EnterDefaultState()
    {
        PhysicsObj obj = _physicsObj ?? throw new System.InvalidOperationException("The interpreter has no physics object.");
        obj.Touch();
        RawState.Reset();
        InterpretedState.Reset();
        obj.InitializeMotionTables();
        AddToQueue(0, MotionCommand.Ready, MotionError.None);
        Initted = true;
        LeaveGround();
    }
}
