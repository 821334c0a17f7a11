using System;
using System.Numerics;

namespace AcDream.Core.Tests.Replay.Harness;

/// <summary>One leg of a scripted creature path: how long, how fast forward / sideways, how fast it turns, whether it jumps
/// at the start, and an optional instant displacement (a teleport) at the start.</summary>
/// <param name="Duration">Seconds.</param>
/// <param name="Forward">Forward speed, m/s.</param>
/// <param name="Strafe">Sideways speed (+ right), m/s.</param>
/// <param name="TurnRate">Degrees per second, clockwise.</param>
/// <param name="Jump">Jump at the start of the leg (vertical launch speed <see cref="TruthPath.JumpSpeed"/>).</param>
/// <param name="Teleport">Instant displacement at the start of the leg, metres (landblock axes).</param>
public readonly record struct MotionLeg(double Duration, float Forward, float Strafe = 0f, float TurnRate = 0f, bool Jump = false, Vector3 Teleport = default);

/// <summary>The true path of a scripted creature, sampled every millisecond from its legs.</summary>
public sealed class TruthPath
{
    /// <summary>Sample spacing, seconds.</summary>
    public const double Step = 0.001;

    /// <summary>Vertical launch speed of a jump, m/s (0.82 m high, 0.82 s in the air under 9.8 m/s²).</summary>
    public const float JumpSpeed = 4.0f;

    private readonly Vector3[] _pos;
    private readonly float[] _heading;
    private readonly Vector3[] _localVel;
    private readonly Vector3[] _worldVel;
    private readonly bool[] _air;

    private TruthPath(int n)
    {
        _pos = new Vector3[n];
        _heading = new float[n];
        _localVel = new Vector3[n];
        _worldVel = new Vector3[n];
        _air = new bool[n];
    }

    /// <summary>Total duration, seconds.</summary>
    public double Duration => (_pos.Length - 1) * Step;

    /// <summary>Builds the path from <paramref name="start"/> facing <paramref name="heading"/> degrees.</summary>
    public static TruthPath Build(Vector3 start, float heading, params MotionLeg[] legs)
    {
        double total = 0;
        foreach (MotionLeg l in legs)
        {
            total += l.Duration;
        }

        int n = (int)Math.Round(total / Step) + 1;
        var t = new TruthPath(n);
        Vector3 p = start;
        double h = heading;
        float vz = 0f;
        bool air = false;
        int i = 0;
        foreach (MotionLeg leg in legs)
        {
            int steps = (int)Math.Round(leg.Duration / Step);
            p += leg.Teleport;
            if (leg.Jump)
            {
                vz = JumpSpeed;
                air = true;
            }

            for (int k = 0; k < steps && i < n; k++, i++)
            {
                double r = h * Math.PI / 180.0;
                var fwd = new Vector3((float)Math.Sin(r), (float)Math.Cos(r), 0f);
                var right = new Vector3((float)Math.Cos(r), (float)-Math.Sin(r), 0f);
                Vector3 v = (fwd * leg.Forward) + (right * leg.Strafe);
                t.Record(i, p, (float)h, new Vector3(leg.Strafe, leg.Forward, 0f), v + new Vector3(0f, 0f, vz), air);
                p += v * (float)Step;
                if (air)
                {
                    vz -= 9.8f * (float)Step;
                    p.Z += vz * (float)Step;
                    if (p.Z <= 0f)
                    {
                        p.Z = 0f;
                        vz = 0f;
                        air = false;
                    }
                }

                h = (h + (leg.TurnRate * Step)) % 360.0;
                if (h < 0)
                {
                    h += 360.0;
                }
            }
        }

        for (; i < n; i++)
        {
            t.Record(i, p, (float)h, Vector3.Zero, Vector3.Zero, air);
        }

        return t;
    }

    /// <summary>Position at time <paramref name="time"/> (landblock 0x7F7F axes), clamped to the path.</summary>
    public Vector3 PositionAt(double time) => _pos[Index(time)];

    /// <summary>Heading at <paramref name="time"/>, degrees.</summary>
    public float HeadingAt(double time) => _heading[Index(time)];

    /// <summary>The motion state at <paramref name="time"/>: (strafe, forward, 0) m/s in local axes.</summary>
    public Vector3 LocalVelocityAt(double time) => _localVel[Index(time)];

    /// <summary>World velocity at <paramref name="time"/> including the vertical component, m/s.</summary>
    public Vector3 WorldVelocityAt(double time) => _worldVel[Index(time)];

    /// <summary>True while airborne at <paramref name="time"/>.</summary>
    public bool AirborneAt(double time) => _air[Index(time)];

    private int Index(double time)
    {
        int i = (int)Math.Floor((time / Step) + 1e-9);
        return Math.Clamp(i, 0, _pos.Length - 1);
    }

    private void Record(int i, Vector3 p, float h, Vector3 local, Vector3 world, bool air)
    {
        _pos[i] = p;
        _heading[i] = h;
        _localVel[i] = local;
        _worldVel[i] = world;
        _air[i] = air;
    }
}
