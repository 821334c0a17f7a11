using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Tests.Replay.Harness;

/// <summary>A named replay: the creature's true path and the network that reports it.</summary>
/// <param name="Name">Row name.</param>
/// <param name="Truth">The true path.</param>
/// <param name="Network">Send/delivery model.</param>
/// <param name="StopTime">Time at which the truth comes to a final stop (for convergence), or NaN.</param>
/// <param name="TeleportTime">Time of a teleport in the truth, or NaN.</param>
/// <param name="PlayerAt">Where the (idle) player stands; objects beyond 96 m of it are not simulated, as in retail.</param>
public sealed record ReplayScenario(string Name, TruthPath Truth, NetworkModel Network, double StopTime = double.NaN, double TeleportTime = double.NaN, Vector3? PlayerAt = null);

/// <summary>Client frame pacing.</summary>
public enum FrameMode
{
    /// <summary>A frame every 1/30 s.</summary>
    Fixed30Hz,

    /// <summary>Frame times drawn uniformly between 1/144 s and 1/15 s (seeded).</summary>
    Variable15To144,
}

/// <summary>What one replay measured against the true path.</summary>
public sealed class ReplayResult
{
    /// <summary>Scenario name.</summary>
    public required string Name { get; init; }

    /// <summary>Frame pacing.</summary>
    public required FrameMode Mode { get; init; }

    /// <summary>Mean distance body-to-truth after the first second, metres.</summary>
    public double MeanError { get; set; }

    /// <summary>Time shift of the truth that best matches the body (least mean squared distance), seconds.</summary>
    public double Lag { get; set; }

    /// <summary>Largest move in one frame that was not a placement, metres.</summary>
    public double MaxStep { get; set; }

    /// <summary>Largest non-placement move divided by (2 × max speed + the body's own horizontal speed) × the frame's simulated
    /// time: ≤ 1 under retail's rules (the interpolation offset is capped; UpdatePhysicsInternal adds velocity × dt on top).</summary>
    public double MaxStepOverCap { get; set; }

    /// <summary>Largest lead of the body ahead of the truth along its direction of travel, metres.</summary>
    public double Overshoot { get; set; }

    /// <summary>Number of placements (blips and snaps) after the first frame.</summary>
    public int Blips { get; set; }

    /// <summary>Seconds from the final stop of the truth until the body stays within 0.06 m of it; NaN when not applicable or
    /// never.</summary>
    public double ConvergeTime { get; set; } = double.NaN;

    /// <summary>Physics ticks of the creature from the first post-teleport report's delivery until the body is within 0.1 m
    /// of it (or was placed); -1 when not applicable or never.</summary>
    public int TeleportBlipFrames { get; set; } = -1;

    /// <summary>Distance from the body's position when the last report was applied to its final position, metres.</summary>
    public double TravelAfterLastReport { get; set; }

    /// <summary>Reports applied / delivered.</summary>
    public int Applied { get; set; }

    /// <summary>Reports delivered (including duplicates and stale ones, which are dropped).</summary>
    public int Delivered { get; set; }

    /// <summary>(time, error) per frame, for plots.</summary>
    public List<(double X, double Y)> ErrorSeries { get; } = new();
}

/// <summary>
/// Replays a scenario through a real <see cref="PhysicsWorld"/>: reports are delivered at their arrival times through
/// <see cref="PhysicsObj.HandleReceivedPosition"/> (whose position timestamp drops duplicates and late reports), the
/// motion state sets the creature's root-motion velocity, a jump report launches it, and the world ticks at each frame.
/// </summary>
public static class ReplayRunner
{
    /// <summary>Catch-up speed cap of the scene's creature: 2 × 4 m/s (default movement manager, no weenie).</summary>
    public const double SpeedCap = 8.0;

    /// <summary>Runs <paramref name="sc"/> with frames paced by <paramref name="mode"/>.</summary>
    public static ReplayResult Run(ReplayScenario sc, FrameMode mode, int seed)
    {
        TruthPath truth = sc.Truth;
        ServerUpdate[] stream = sc.Network.Generate(truth, seed);
        var scene = new ManagerScene(truth.PositionAt(0), truth.HeadingAt(0), 0.0, sc.PlayerAt);
        PhysicsObj c = scene.Creature;
        var rng = new Random(seed ^ 0x5EED);
        var result = new ReplayResult { Name = sc.Name, Mode = mode };
        int next = 0;
        int lastSeq = 0;
        double now = 0;
        int placements0 = scene.Ground.PlacementCount;
        Vector3 prev = ManagerScene.GlobalOf(c.Position);
        double prevUpdateTime = c.UpdateTime;
        double errSum = 0;
        int errN = 0;
        var times = new List<double>();
        var bodies = new List<Vector3>();
        Vector3 atLastReport = prev;
        Vector3 lastDir = new(0f, 1f, 0f);
        double convergedSince = double.NaN;
        int teleportFrames = -1;
        bool teleportSeen = false;
        Vector3 teleportTarget = default;
        while (now < truth.Duration)
        {
            now += mode == FrameMode.Fixed30Hz ? 1.0 / 30.0 : 1.0 / (15.0 + (rng.NextDouble() * (144.0 - 15.0)));
            while (next < stream.Length && stream[next].ArriveTime <= now)
            {
                ServerUpdate u = stream[next++];
                result.Delivered++;
                if (u.Sequence <= lastSeq)
                {
                    // Retail drops it too (position timestamp); skipping here keeps the motion state in step.
                    c.HandleReceivedPosition(u.Position, (ushort)u.Sequence, 0, u.HasContact);
                    continue;
                }

                lastSeq = u.Sequence;
                scene.CreatureParts.SequenceVelocity = u.LocalVelocity;
                if (!u.HasContact && (c.TransientState & TransientState.Contact) != 0 && u.WorldVelocity.Z > 0f)
                {
                    // The jump itself reaches retail through the motion layer (CMotionInterp -> set_velocity).
                    c.SetVelocity(u.WorldVelocity);
                }

                if (c.HandleReceivedPosition(u.Position, (ushort)u.Sequence, 0, u.HasContact) >= ReceivedPositionResult.Interpolating)
                {
                    result.Applied++;
                    atLastReport = ManagerScene.GlobalOf(c.Position);
                }

                if (!teleportSeen && !double.IsNaN(sc.TeleportTime) && u.SendTime >= sc.TeleportTime)
                {
                    teleportSeen = true;
                    teleportTarget = ManagerScene.GlobalOf(u.Position);
                    teleportFrames = 0;
                }
            }

            int placementsBefore = scene.Ground.PlacementCount;
            Vector3 vBefore = c.Velocity;
            scene.World.Tick(now);
            Vector3 vAfter = c.Velocity;
            double physical = Math.Max(HorizontalSpeed(vBefore), HorizontalSpeed(vAfter));
            bool placed = scene.Ground.PlacementCount != placementsBefore;
            Vector3 body = ManagerScene.GlobalOf(c.Position);
            double simulated = c.UpdateTime - prevUpdateTime;
            prevUpdateTime = c.UpdateTime;
            Vector3 d = body - prev;
            double step = Math.Sqrt((double)d.X * d.X + (double)d.Y * d.Y);
            if (!placed)
            {
                result.MaxStep = Math.Max(result.MaxStep, step);
                if (simulated > 0)
                {
                    result.MaxStepOverCap = Math.Max(result.MaxStepOverCap, step / ((SpeedCap + physical) * simulated));
                }
            }

            prev = body;
            Vector3 tp = truth.PositionAt(now);
            Vector3 e = body - tp;
            double err = Math.Sqrt((double)e.X * e.X + (double)e.Y * e.Y + (double)e.Z * e.Z);
            result.ErrorSeries.Add((now, err));
            if (now > 1.0)
            {
                errSum += err;
                errN++;
            }

            Vector3 tv = truth.WorldVelocityAt(now);
            var hv = new Vector2(tv.X, tv.Y);
            if (hv.LengthSquared() > 1e-6f)
            {
                Vector2 n = Vector2.Normalize(hv);
                lastDir = new Vector3(n.X, n.Y, 0f);
            }

            if (now > 1.0)
            {
                double lead = (double)e.X * lastDir.X + (double)e.Y * lastDir.Y;
                result.Overshoot = Math.Max(result.Overshoot, lead);
            }

            if (!double.IsNaN(sc.StopTime) && now >= sc.StopTime)
            {
                if (err < 0.06)
                {
                    if (double.IsNaN(convergedSince))
                    {
                        convergedSince = now;
                    }
                }
                else
                {
                    convergedSince = double.NaN;
                }
            }

            if (teleportFrames >= 0 && !double.IsNaN(sc.TeleportTime) && result.TeleportBlipFrames < 0 && simulated > 0)
            {
                teleportFrames++;
                Vector3 tg = body - teleportTarget;
                if (tg.Length() < 0.1f || placed)
                {
                    result.TeleportBlipFrames = teleportFrames;
                }
            }

            times.Add(now);
            bodies.Add(body);
        }

        result.Blips = scene.Ground.PlacementCount - placements0;
        result.MeanError = errN > 0 ? errSum / errN : 0;
        result.ConvergeTime = double.IsNaN(convergedSince) ? double.NaN : convergedSince - sc.StopTime;
        Vector3 travel = prev - atLastReport;
        result.TravelAfterLastReport = travel.Length();
        result.Lag = BestLag(truth, times, bodies);
        return result;
    }

    private static double HorizontalSpeed(Vector3 v) => Math.Sqrt((double)v.X * v.X + (double)v.Y * v.Y);

    private static double BestLag(TruthPath truth, List<double> times, List<Vector3> bodies)
    {
        double best = 0;
        double bestErr = double.MaxValue;
        for (int k = 0; k <= 300; k++)
        {
            double tau = k * 0.005;
            double sum = 0;
            int n = 0;
            for (int i = 0; i < times.Count; i++)
            {
                if (times[i] < 1.0)
                {
                    continue;
                }

                Vector3 e = bodies[i] - truth.PositionAt(times[i] - tau);
                sum += (double)e.X * e.X + (double)e.Y * e.Y;
                n++;
            }

            if (n > 0 && sum / n < bestErr)
            {
                bestErr = sum / n;
                best = tau;
            }
        }

        return best;
    }
}
