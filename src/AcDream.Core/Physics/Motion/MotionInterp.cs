using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Seams;

namespace AcDream.Core.Physics.Motion;

/// <summary>
/// The motion interpreter (retail <c>CMotionInterp</c>, PORTAL/canim/CMotionInterp.c): turns motion commands into the
/// motion the object performs, decides jumps and their launch velocity, and reacts to landing and leaving the ground.
/// It keeps two states: <see cref="RawState"/> (the commands as given) and <see cref="InterpretedState"/> (after the
/// hold-key, backwards, side-step and turn conversions), and sends the interpreted motion to the part array's motion table
/// (<see cref="Objects.Parts.IPartArray.MotionPlayer"/>), which moves the body.
/// </summary>
/// <remarks>
/// <para>Created by <see cref="MovementManager"/>. The player's commands go in through <see cref="DoMotion"/> /
/// <see cref="StopMotion"/> (raw); a remote object's state arrives whole through <see cref="MoveToInterpretedState"/>
/// (what a MovementEvent applies). Speeds: walk 3.12 m/s, run 4 m/s times the run rate, side-step 1.25 m/s, all
/// clamped by <see cref="StateVelocity"/> to 4 times the run rate.</para>
/// <para>The retail arithmetic is x87: products of floats are evaluated in double and rounded where retail stores a float.</para>
/// </remarks>
public sealed partial class MotionInterp : IMotionInterpreter
{
    /// <summary>Forward speed of the run cycle at speed 1, m/s: 4.0 (acclient.c:343538).</summary>
    public const double RunAnimSpeed = 4.0;

    /// <summary>Forward speed of the walk cycle at speed 1, m/s: 3.12 as a float (bits 0x4047AE14; acclient.c:343538).</summary>
    public const float WalkAnimSpeed = 3.12f;

    /// <summary>Speed of the side-step at speed 1, m/s: 1.25 (acclient.c:343538).</summary>
    public const double SidestepAnimSpeed = 1.25;

    /// <summary>Speed factor of walking backwards: 0.65 as a float (bits 0x3F266666; the command becomes a walk forward at
    /// -0.65 times its speed; acclient.c:343745).</summary>
    public const float BackwardsFactor = 0.65f;

    /// <summary>Factor of a side-step's speed: 0.5, applied with the walk-to-side-step ratio (acclient.c:343745).</summary>
    public const double SidestepFactor = 0.5;

    /// <summary>Largest side-step speed when running: 3.0 (acclient.c:343438).</summary>
    public const double MaxSidestepAnimRate = 3.0;

    /// <summary>Turn speed factor when running: 1.5 (acclient.c:343438).</summary>
    public const double RunTurnFactor = 1.5;

    /// <summary>Launch speed of a jump with no weenie, m/s: 10 (acclient.c:343342).</summary>
    public const double NoWeenieJumpVelocity = 10.0;

    /// <summary>The speed a side-step command is multiplied by: <c>3.12f / 1.25 * 0.5</c> evaluated in double
    /// (1.2479999542236328), as the decompilation writes it (acclient.c:343745).</summary>
    public static readonly double SidestepSpeedRatio = (double)WalkAnimSpeed / SidestepAnimSpeed * SidestepFactor;

    private PhysicsObj? _physicsObj;
    private IMotionWeenie? _weenieObj;

    private MotionInterp()
    {
    }

    /// <summary>True once <see cref="EnterDefaultState"/> has run (retail <c>initted</c>): only then do state changes reach
    /// the motion table.</summary>
    public bool Initted { get; private set; }

    /// <summary>The object moved.</summary>
    public PhysicsObj? PhysicsObj => _physicsObj;

    /// <summary>The character the interpreter asks (retail <c>weenie_obj</c>), or null.</summary>
    public IMotionWeenie? WeenieObj => _weenieObj;

    /// <summary>The commands as given.</summary>
    public RawMotionState RawState { get; } = new();

    /// <summary>The motion performed.</summary>
    public InterpretedMotionState InterpretedState { get; } = new();

    /// <summary>Divisor of a run's forward speed in <see cref="AdjustedMaxSpeed"/> (retail <c>current_speed_factor</c>,
    /// 1 at creation).</summary>
    /// <exception cref="System.ArgumentException">The value is not finite and positive (state unchanged).</exception>
    public float CurrentSpeedFactor
    {
        get => _currentSpeedFactor;
        set => _currentSpeedFactor = float.IsFinite(value) && value > 0f
            ? value
            : throw new System.ArgumentException("The speed factor must be finite and positive.", nameof(value));
    }

    private float _currentSpeedFactor = 1f;

    /// <summary>A jump is being charged from standing still: forward and side-step commands are recorded but not played
    /// until the jump (retail <c>standing_longjump</c>).</summary>
    public bool StandingLongJump { get; internal set; }

    /// <summary>Charge of the current jump, 0..1 (retail <c>jump_extent</c>).</summary>
    public float JumpExtent { get; internal set; }

    /// <summary>Stamp of the last server action applied (retail <c>server_action_stamp</c>).</summary>
    public uint ServerActionStamp { get; internal set; }

    /// <summary>The run rate last received (retail <c>my_run_rate</c>, 1 at creation): used when the weenie cannot say.</summary>
    /// <exception cref="System.ArgumentException">The value is not in (0, <see cref="InputLimits.MaxRunRate"/>] (state
    /// unchanged). Retail takes any float; at zero or below the state velocity's cap (4 × rate) is negative and a standing
    /// object's state velocity is 0 / 0 = NaN.</exception>
    public float MyRunRate
    {
        get => _myRunRate;
        set => _myRunRate = MotionChecks.RunRate(value);
    }

    private float _myRunRate = 1f;

    /// <summary>Started motions not yet finished.</summary>
    public PendingMotions PendingMotions { get; } = new();

    /// <summary>Creates an interpreter for <paramref name="physicsObj"/> and <paramref name="weenieObj"/>.</summary>
    // retail: CMotionInterp::Create (acclient.c:344525)
    public static MotionInterp Create(PhysicsObj? physicsObj, IMotionWeenie? weenieObj)
    {
        var m = new MotionInterp();
        m.SetWeenieObject(weenieObj);
        m.SetPhysicsObject(physicsObj);
        return m;
    }

    /// <summary>The error <paramref name="motion"/> gives a jump: <see cref="MotionError.YouCantJumpFromThisPosition"/> while crouching, sitting,
    /// sleeping, fallen or in the poses
    /// 0x4000001E..0x40000039, 0x40000016..0x40000018 and the actions 0x1000006F..0x10000078, 0x10000128..0x10000131;
    /// else <see cref="MotionError.None"/>.</summary>
    // retail: CMotionInterp::motion_allows_jump (acclient.c:343294)
    public static MotionError MotionAllowsJump(MotionCommand motion)
    {
        uint substate = (uint)motion;
        if (substate > 0x40000018u)
        {
            if (substate > 0x41000014u || (substate < 0x41000012u && (substate < 0x4000001Eu || substate > 0x40000039u)))
            {
                return MotionError.None;
            }
        }
        else if (substate < 0x40000016u)
        {
            if (substate > 0x10000131u)
            {
                if (substate != (uint)MotionCommand.Fallen)
                {
                    return MotionError.None;
                }
            }
            else if (substate < 0x10000128u && (substate < 0x1000006Fu || substate > 0x10000078u))
            {
                return MotionError.None;
            }
        }

        return MotionError.YouCantJumpFromThisPosition;
    }

    /// <summary>The current style.</summary>
    // retail: CMotionInterp::InqStyle (acclient.c:343366)
    public MotionCommand InqStyle() => InterpretedState.CurrentStyle;

    /// <summary>True while started motions are unfinished.</summary>
    // retail: CMotionInterp::motions_pending (acclient.c:343728)
    public bool MotionsPending() => PendingMotions.Count != 0;

    /// <summary>On the ground (CONTACT and ON_WALKABLE) with nothing moving.</summary>
    // retail: CMotionInterp::is_standing_still (acclient.c:343715)
    public bool IsStandingStill() =>
        _physicsObj is not null && OnGround(_physicsObj)
        && InterpretedState.ForwardCommand == MotionCommand.Ready
        && InterpretedState.SidestepCommand == MotionCommand.None
        && InterpretedState.TurnCommand == MotionCommand.None;

    /// <summary>The largest speed the character can run, m/s: 4 times the run rate (4 with no weenie). Retail
    /// <c>CMotionInterp::get_max_speed</c>.</summary>
    // retail: CMotionInterp::get_max_speed (acclient.c:343485)
    public double MaxSpeed
    {
        get
        {
            if (_weenieObj is null)
            {
                return 1.0 * RunAnimSpeed;
            }

            return _weenieObj.InqRunRate(out float rate) ? rate * RunAnimSpeed : MyRunRate * RunAnimSpeed;
        }
    }

    /// <summary>The largest speed for the current motion, m/s: while running, 4 times the run speed over
    /// <see cref="CurrentSpeedFactor"/>; otherwise <see cref="MaxSpeed"/>. Retail
    /// <c>CMotionInterp::get_adjusted_max_speed</c>.</summary>
    // retail: CMotionInterp::get_adjusted_max_speed (acclient.c:343511)
    public double AdjustedMaxSpeed
    {
        get
        {
            double rate = RunRate();
            if (InterpretedState.ForwardCommand == MotionCommand.RunForward)
            {
                rate = (double)InterpretedState.ForwardSpeed / CurrentSpeedFactor;
            }

            return rate * RunAnimSpeed;
        }
    }

    /// <summary>
    /// The velocity the interpreted state asks for, in the object's local axes (m/s): x = 1.25 × side-step speed,
    /// y = 3.12 × walk speed or 4 × run speed, z = 0, scaled down to at most 4 × the run rate. Retail
    /// <c>CMotionInterp::get_state_velocity</c>.
    /// </summary>
    // retail: CMotionInterp::get_state_velocity (acclient.c:343538)
    public Vector3 StateVelocity
    {
        get
        {
            InterpretedMotionState s = InterpretedState;
            float x = s.SidestepCommand == MotionCommand.SideStepRight ? (float)(SidestepAnimSpeed * s.SidestepSpeed) : 0f;
            float y;
            if (s.ForwardCommand == MotionCommand.WalkForward)
            {
                y = (float)((double)WalkAnimSpeed * s.ForwardSpeed);
            }
            else if (s.ForwardCommand == MotionCommand.RunForward)
            {
                y = (float)(RunAnimSpeed * s.ForwardSpeed);
            }
            else
            {
                y = 0f;
            }

            float z = 0f;
            double max = RunRate() * RunAnimSpeed;
            double len = Math.Sqrt((double)x * x + (double)y * y + (double)z * z);
            if (len > max)
            {
                x = (float)(1.0 / len * x * max);
                y = (float)(1.0 / len * y * max);
                z = (float)(1.0 / len * z * max);
            }

            return new Vector3(x, y, z);
        }
    }

    /// <summary>The weenie's run rate, else <see cref="MyRunRate"/>; 1 with no weenie.</summary>
    private double RunRate()
    {
        if (_weenieObj is null)
        {
            return 1.0;
        }

        return _weenieObj.InqRunRate(out float rate) ? rate : MyRunRate;
    }

    /// <summary>Sets the character and re-applies the current movement (cancelling a move-to).</summary>
    // retail: CMotionInterp::SetWeenieObject (acclient.c:344334)
    public void SetWeenieObject(IMotionWeenie? weenieObj)
    {
        _weenieObj = weenieObj;
        if (_physicsObj is not null && Initted)
        {
            ReapplyForOwner(true, false);
        }
    }

    /// <summary>Sets the object and re-applies the current movement (cancelling a move-to).</summary>
    // retail: CMotionInterp::SetPhysicsObject (acclient.c:344353)
    public void SetPhysicsObject(PhysicsObj? physicsObj)
    {
        _physicsObj = physicsObj;
        if (physicsObj is not null && Initted)
        {
            ReapplyForOwner(true, false);
        }
    }

    /// <summary>Re-applies the current movement after the stamina ran out (or came back).</summary>
    // retail: CMotionInterp::ReportExhaustion (acclient.c:344317)
    public void ReportExhaustion()
    {
        if (_physicsObj is not null && Initted)
        {
            ReapplyForOwner(false, false);
        }
    }

    /// <summary>Re-sends the motion: the raw state for this client's own autonomous player (or an object with no weenie
    /// that moved autonomously), the interpreted state otherwise.</summary>
    // retail: CMotionInterp::apply_current_movement (acclient.c:344300)
    public void ApplyCurrentMovement(bool cancelMoveTo, bool disallowJump)
    {
        if (_physicsObj is not null && Initted)
        {
            ReapplyForOwner(cancelMoveTo, disallowJump);
        }
    }

    private void ReapplyForOwner(bool cancelMoveTo, bool disallowJump)
    {
        if ((_weenieObj is null || _weenieObj.IsThePlayer) && _physicsObj!.LastMoveWasAutonomous)
        {
            ApplyRawMovement(cancelMoveTo, disallowJump);
        }
        else
        {
            ApplyInterpretedMovement(cancelMoveTo, disallowJump);
        }
    }

    internal static bool OnGround(PhysicsObj obj) =>
        (obj.TransientState & (Objects.TransientState.Contact | Objects.TransientState.OnWalkable))
        == (Objects.TransientState.Contact | Objects.TransientState.OnWalkable);

    internal static bool HasGravity(PhysicsObj obj) => (obj.State & PhysicsState.Gravity) != 0;

    // retail: CMotionInterp::add_to_queue (acclient.c:343405)
    private void AddToQueue(uint contextId, MotionCommand motion, MotionError jumpErrorCode) =>
        PendingMotions.Add(new MotionNode(contextId, motion, jumpErrorCode));

    /// <summary>The local velocity of <paramref name="obj"/>'s global velocity, evaluated as retail's leave-ground branch
    /// does (rows of the cached matrix, y term first).</summary>
    private static Vector3 GlobalVelocityToLocal(PhysicsObj obj)
    {
        Frame f = obj.Position.Frame;
        Vector3 v = obj.Velocity;
        float x = (float)((double)f.M12 * v.Y + (double)f.M11 * v.X + (double)f.M13 * v.Z);
        float y = (float)((double)f.M22 * v.Y + (double)f.M21 * v.X + (double)f.M23 * v.Z);
        double zxy = (double)f.M32 * v.Y + (double)f.M31 * v.X;
        double zz = (double)f.M33 * v.Z;
        return new Vector3(x, y, (float)(zxy + zz));
    }
}
