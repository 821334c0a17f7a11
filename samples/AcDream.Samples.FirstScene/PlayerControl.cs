using System;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;

namespace AcDream.Samples.FirstScene;

/// <summary>
/// The player's controls, all in one place: what a client's input code does when keys go down and up. Keys become motion
/// commands for retail's motion interpreter (<see cref="MovementManager.DoMotion"/> / <see cref="MovementManager.StopMotion"/>,
/// the run key through <see cref="MotionInterp.SetHoldRun"/>, the jump key through <see cref="MotionInterp.ChargeJump"/> and
/// <see cref="MotionInterp.Jump"/>); the interpreter plays them on the part array's motion table, whose velocity and omega move
/// the body each tick (root motion, only on walkable ground), and launches the jump when the player leaves the ground.
/// </summary>
internal sealed class PlayerControl
{
    /// <summary>The character: run skill 45 gives a run rate of (45 / 245 × 11 + 4) / 4 = 1.505 (running 6.02 m/s), jump skill
    /// 100 at extent 0.5 a jump of (100 / 1400 × 22.2 + 0.05) × 0.5 = 0.818 m (v_z = √(19.6 × 0.818) = 4.00 m/s).</summary>
    public static PlayerWeenie Character() => new() { RunSkill = 45, JumpSkill = 100, Strength = 100, Burden = 0 };

    /// <summary>Jump charge released at the jump: half of a full charge.</summary>
    public const float JumpExtent = 0.5f;

    private readonly MovementManager _mm;
    private readonly MotionInterp _mi;
    private bool _forward;
    private bool _turnRight;
    private bool _turnLeft;
    private bool _run;
    private bool _charging;
    private bool _jumped;

    /// <summary>Prepares <paramref name="player"/> (already the world's player, its weenie set, its part array's motion table
    /// <paramref name="body"/>'s): its movement manager and motion interpreter.</summary>
    public PlayerControl(PhysicsObj player, SimplePartArray body)
    {
        ArgumentNullException.ThrowIfNull(player);
        ArgumentNullException.ThrowIfNull(body);
        if (body.MotionTable is null)
        {
            throw new ArgumentException("The player's part array needs a motion table.", nameof(body));
        }

        _mm = MovementManager.Of(player);
        _mi = _mm.GetOrCreateMotionInterpreter();
    }

    /// <summary>The commanded velocity in the player's local axes (+Y forward), m/s.</summary>
    public System.Numerics.Vector3 CommandedVelocity => _mi.GetStateVelocity();

    /// <summary>Sets the keys of the scripted walk at script time <paramref name="t"/> seconds (a real client does this from its
    /// input events).</summary>
    /// <returns>The name of the current command, for the console.</returns>
    public string Drive(double t)
    {
        if (t < 4.0)
        {
            Keys(forward: true, run: false, turnRight: false, turnLeft: false);
            return "walk north";
        }

        if (t < 5.0)
        {
            Keys(forward: true, run: false, turnRight: true, turnLeft: false);   // 1 s at pi/2 rad/s: a quarter turn, now east
            return "walk, turning right";
        }

        if (t < 6.0)
        {
            Keys(forward: true, run: false, turnRight: false, turnLeft: false);
            return "walk east";
        }

        if (t < 10.0)
        {
            Keys(forward: true, run: true, turnRight: false, turnLeft: false);
            if (t >= 9.5 && !_charging && !_jumped)
            {
                _charging = true;
                _mi.ChargeJump();                                 // jump key down: the charge builds
            }

            return _charging ? "run east, charging a jump" : "run east";
        }

        if (!_jumped)
        {
            _jumped = true;
            MotionError err = _mi.Jump(JumpExtent, out _);        // jump key up: None = jumped, the launch comes at LeaveGround
            return err == MotionError.None ? "jump" : $"jump refused ({err})";
        }

        if (t < 12.5)
        {
            Keys(forward: true, run: true, turnRight: false, turnLeft: false);
            return "run east (jump)";
        }

        if (t < 13.25)
        {
            Keys(forward: true, run: false, turnRight: false, turnLeft: true);   // 0.75 s at pi/2 rad/s: 67.5 degrees, now NNE
            return "walk, turning left";
        }

        if (t < 20.0)
        {
            Keys(forward: true, run: false, turnRight: false, turnLeft: false);
            return "walk NNE (into the hut)";
        }

        Keys(forward: false, run: false, turnRight: false, turnLeft: false);
        return "stand";
    }

    // Key transitions become motion commands; a held key is not re-sent (retail's input layer sends changes only).
    private void Keys(bool forward, bool run, bool turnRight, bool turnLeft)
    {
        if (run != _run)
        {
            _run = run;
            _mi.SetHoldRun(run, cancelMoveToOnChange: false);
        }

        Key(ref _forward, forward, MotionCommand.WalkForward);
        Key(ref _turnRight, turnRight, MotionCommand.TurnRight);
        Key(ref _turnLeft, turnLeft, MotionCommand.TurnLeft);
    }

    private void Key(ref bool down, bool wanted, MotionCommand command)
    {
        if (down == wanted)
        {
            return;
        }

        down = wanted;
        var p = new MovementParameters { HoldKeyToApply = _run ? HoldKey.Run : HoldKey.None };
        if (wanted)
        {
            _mm.DoMotion(command, p);
        }
        else
        {
            _mm.StopMotion(command, p);
        }
    }
}
