using System;
using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;

namespace AcDream.Samples.FirstScene;

/// <summary>
/// The player's controls, all in one place: what a client's input and motion code does each frame. Walking, running and
/// turning are root motion (the part array's sequence velocity and omega, in the player's local axes: +Y forward, +Z up;
/// the physics applies them only while the player stands on walkable ground); a jump is a velocity with an upward component
/// (<see cref="PhysicsObj.SetLocalVelocity"/>), after which gravity takes over until the player lands.
/// </summary>
/// <remarks>When the port of retail's motion interpreter (CMotionInterp) and movement manager lands, this class is the one to
/// replace: the commands below become motion-interpreter calls, which set the same sequence velocity and jump velocity.</remarks>
internal static class PlayerControl
{
    /// <summary>Retail's walk speed, m/s (the human walk-forward animation's velocity).</summary>
    public const float WalkSpeed = 3.12f;

    /// <summary>Run speed, m/s: retail's run-forward velocity 4 m/s times a run rate (from the run skill; 1.5 here).</summary>
    public const float RunSpeed = 4.0f * 1.5f;

    /// <summary>Turn rate, rad/s (positive turns left, counter-clockwise seen from above).</summary>
    public const float TurnRate = MathF.PI / 4f;

    /// <summary>Upward speed of the jump, m/s: a hop of v² / 2g = 16 / 19.6 = 0.82 m of free flight (plus the first step,
    /// taken while still on the ground, without gravity).</summary>
    public const float JumpSpeed = 4.0f;

    /// <summary>Sets this frame's commands of the scripted walk at script time <paramref name="t"/> seconds.</summary>
    /// <returns>The name of the current command, for the console.</returns>
    public static string Drive(PhysicsObj player, SimplePartArray body, double t, ref bool jumped)
    {
        ArgumentNullException.ThrowIfNull(player);
        ArgumentNullException.ThrowIfNull(body);
        if (t < 4.0)
        {
            return Move(body, WalkSpeed, 0f, "walk north");
        }

        if (t < 6.0)
        {
            return Move(body, WalkSpeed, -TurnRate, "walk, turning right");   // 2 s at pi/4 rad/s: a quarter turn, now east
        }

        if (t < 10.0)
        {
            return Move(body, RunSpeed, 0f, "run east");
        }

        if (!jumped)
        {
            // The jump keeps the run's forward speed: root motion stops while airborne, the velocity carries the player.
            jumped = true;
            player.SetLocalVelocity(new Vector3(0f, RunSpeed, JumpSpeed));
            return Move(body, RunSpeed, 0f, "jump");
        }

        if (t < 11.5)
        {
            return Move(body, RunSpeed, 0f, "jump");
        }

        if (t < 13.5)
        {
            return Move(body, WalkSpeed, TurnRate / 2f, "walk, turning left");  // 2 s at pi/8: 45 degrees, now north-east
        }

        if (t < 20.0)
        {
            return Move(body, WalkSpeed, 0f, "walk north-east (into the hut)");
        }

        return Move(body, 0f, 0f, "stand");
    }

    private static string Move(SimplePartArray body, float forward, float turn, string name)
    {
        body.SequenceVelocity = new Vector3(0f, forward, 0f);
        body.SequenceOmega = new Vector3(0f, 0f, turn);
        return name;
    }
}
