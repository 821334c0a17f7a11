using System;
using AcDream.Core.Physics.Input;
using AcDream.Core.Physics.Motion;

namespace AcDream.Samples.FirstScene;

/// <summary>
/// The player's scripted keyboard: which movement keys are held at each script time. A real client reads its keyboard instead
/// and hands the keys to <see cref="PlayerInput"/> the same way (<see cref="PlayerInput.SetHeldKeys"/> each frame, or
/// <see cref="PlayerInput.KeyDown"/> / <see cref="PlayerInput.KeyUp"/> from its key events).
/// </summary>
internal static class KeyScript
{
    /// <summary>The script's last event: the player stands from 20 s; the creature's fade ends at 22 s; 2 s more to settle.</summary>
    public const double Seconds = 24.0;

    /// <summary>The end of the walk out: from 24 s the player turns south and runs across the landblock's south edge
    /// (from the hut's wall, about 64 m: 11 s at 6 m/s), and stands from the next block on.</summary>
    public const double WalkOutSeconds = 40.0;

    /// <summary>The keys of the walk out, steered by the player's heading as a client's auto-run would: turn right until it
    /// faces south (heading 180°, within 5°), then run; stand once in the block to the south.</summary>
    public static (MovementKeys Keys, string Label) WalkOut(AcDream.Core.Physics.Objects.PhysicsObj player)
    {
        if ((player.Position.ObjCellId >> 16) != ((Scene.CentreBlock >> 16) - 1))
        {
            double off = player.Position.Frame.Heading - 180.0;
            return Math.Abs(off) > 5.0
                ? (MovementKeys.TurnRight, "turn to face south")
                : (MovementKeys.Forward | MovementKeys.Run, "run south, out of the block");
        }

        return (MovementKeys.None, "stand (in the next block)");
    }

    /// <summary>The character: run skill 45 gives a run rate of (45 / 245 × 11 + 4) / 4 = 1.505 (running 6.02 m/s), jump skill
    /// 100 at extent 0.5 a jump of (100 / 1400 × 22.2 + 0.05) × 0.5 = 0.818 m (v_z = √(19.6 × 0.818) = 4.00 m/s).</summary>
    public static PlayerWeenie Character() => new() { RunSkill = 45, JumpSkill = 100, Strength = 100, Burden = 0 };

    /// <summary>The keys held at script time <paramref name="t"/> seconds, and what the player is doing, for the console.</summary>
    public static (MovementKeys Keys, string Label) At(double t)
    {
        const MovementKeys walk = MovementKeys.Forward;
        const MovementKeys run = MovementKeys.Forward | MovementKeys.Run;
        return t switch
        {
            < 4.0 => (walk, "walk north"),
            < 5.0 => (walk | MovementKeys.TurnRight, "walk, turning right"),    // 1 s at the turn rate: about a quarter turn
            < 6.0 => (walk, "walk east"),
            < 9.5 => (run, "run east"),
            < 10.0 => (run | MovementKeys.Jump, "run east, charging a jump"),   // jump key held 0.5 s: extent 0.5
            < 12.5 => (run, "run east (jump)"),                                 // jump key up at 10 s: the jump
            < 13.25 => (walk | MovementKeys.TurnLeft, "walk, turning left"),
            < 20.0 => (walk, "walk NNE (into the hut)"),
            _ => (MovementKeys.None, "stand"),
        };
    }
}
