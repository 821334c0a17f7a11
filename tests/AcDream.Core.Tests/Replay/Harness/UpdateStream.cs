using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Tests.Replay.Harness;

/// <summary>One server position report as the client receives it.</summary>
public struct ServerUpdate
{
    /// <summary>Server sequence (retail's position timestamp): the client drops any report not newer than the last applied.</summary>
    public int Sequence;

    /// <summary>Server time the report describes, seconds.</summary>
    public double SendTime;

    /// <summary>Client time it arrives, seconds.</summary>
    public double ArriveTime;

    /// <summary>Reported position.</summary>
    public Position Position;

    /// <summary>Reported ground contact.</summary>
    public bool HasContact;

    /// <summary>Motion state (local velocity: strafe, forward) that arrives with it.</summary>
    public Vector3 LocalVelocity;

    /// <summary>World velocity at send time (used for a jump's launch).</summary>
    public Vector3 WorldVelocity;
}

/// <summary>How the server sends and the network delivers: intervals, latency, jitter, loss, duplication, reordering, cut-off.</summary>
/// <param name="MinInterval">Shortest gap between reports, s (10 Hz).</param>
/// <param name="MaxInterval">Longest gap, s (5 Hz).</param>
/// <param name="Latency">Base one-way delay, s.</param>
/// <param name="Jitter">Extra uniform delay 0..Jitter, s.</param>
/// <param name="Loss">Probability a report is lost.</param>
/// <param name="Duplicate">Probability a report arrives twice.</param>
/// <param name="Reorder">Probability a report is held back 0.15-0.3 s (arriving after later ones).</param>
/// <param name="StopAt">Server time after which nothing more is sent, s.</param>
public sealed record NetworkModel(
    double MinInterval = 0.1,
    double MaxInterval = 0.2,
    double Latency = 0.1,
    double Jitter = 0.08,
    double Loss = 0.02,
    double Duplicate = 0.02,
    double Reorder = 0.02,
    double StopAt = double.PositiveInfinity)
{
    /// <summary>Generates the arrival-ordered stream for <paramref name="truth"/> with a seeded generator.</summary>
    public ServerUpdate[] Generate(TruthPath truth, int seed)
    {
        var rng = new Random(seed);
        var list = new List<ServerUpdate>();
        int seq = 0;
        double t = 0.05;
        while (t <= truth.Duration && t <= StopAt)
        {
            seq++;
            bool lost = rng.NextDouble() < Loss;
            bool dup = rng.NextDouble() < Duplicate;
            bool held = rng.NextDouble() < Reorder;
            double delay = Latency + (rng.NextDouble() * Jitter) + (held ? 0.15 + (rng.NextDouble() * 0.15) : 0.0);
            double dupDelay = rng.NextDouble() * 0.05;
            double gap = MinInterval + (rng.NextDouble() * (MaxInterval - MinInterval));
            if (!lost)
            {
                var u = new ServerUpdate
                {
                    Sequence = seq,
                    SendTime = t,
                    ArriveTime = t + delay,
                    Position = ManagerScene.At(truth.PositionAt(t), truth.HeadingAt(t)),
                    HasContact = !truth.AirborneAt(t),
                    LocalVelocity = truth.LocalVelocityAt(t),
                    WorldVelocity = truth.WorldVelocityAt(t),
                };
                list.Add(u);
                if (dup)
                {
                    u.ArriveTime += dupDelay;
                    list.Add(u);
                }
            }

            t += gap;
        }

        list.Sort((a, b) => a.ArriveTime.CompareTo(b.ArriveTime));
        return list.ToArray();
    }
}
