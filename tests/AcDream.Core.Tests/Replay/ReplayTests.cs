using System.Collections.Generic;
using System.Linq;
using AcDream.Core.Tests.Replay.Harness;
using Xunit;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Replay;

/// <summary>
/// Realistic update streams replayed through the world at 30 Hz and at 15-144 fps, with bounds derived from retail's rules.
/// </summary>
public class ReplayTests
{
    private const int Seed = 4186;
    private readonly ITestOutputHelper _out;

    public ReplayTests(ITestOutputHelper output) => _out = output;

    public static IEnumerable<object[]> Cases()
    {
        foreach (ReplayScenario sc in ReplayScenarios.All())
        {
            yield return new object[] { sc.Name, FrameMode.Fixed30Hz };
            yield return new object[] { sc.Name, FrameMode.Variable15To144 };
        }
    }

    private static ReplayResult Run(string name, FrameMode mode) =>
        ReplayRunner.Run(ReplayScenarios.All().Single(s => s.Name == name), mode, Seed);

    [Theory]
    [MemberData(nameof(Cases))]
    public void NoFrameMovesFasterThanTheSpeedCap_ExceptABlip(string name, FrameMode mode)
    {
        // Retail: the offset (interpolation step, else root motion) is at most 2 x max speed (8 m/s here) x the substep, the
        // constraint only shrinks it, and UpdatePhysicsInternal adds the body's own velocity x dt (a jump's 4 m/s) on top.
        // Only a placement may move farther.
        ReplayResult r = Run(name, mode);
        _out.WriteLine($"{name} {mode}: max step {r.MaxStep:F3} m, ratio {r.MaxStepOverCap:F3}, blips {r.Blips}, mean err {r.MeanError:F3}, lag {r.Lag:F3}");
        Assert.True(r.MaxStepOverCap <= 1.0 + 1e-4, $"ratio {r.MaxStepOverCap}");
    }

    [Theory]
    [MemberData(nameof(Cases))]
    public void OnlyTheTeleportBlips_LostDuplicatedOrLateUpdatesNever(string name, FrameMode mode)
    {
        // A lost report only lengthens the gap to the next near report: the body keeps closing at the cap, so the audit
        // (30 % of the cap) passes and nothing fails. Duplicates and late reports are dropped by the sequence test.
        ReplayResult r = Run(name, mode);
        Assert.Equal(name == "teleport 150 m" ? 1 : 0, r.Blips);
    }

    [Theory]
    [InlineData(FrameMode.Fixed30Hz)]
    [InlineData(FrameMode.Variable15To144)]
    public void Teleport_BlipsWithinOneTickOfTheReport(FrameMode mode)
    {
        // Far branch pre-arms the fail counter to 4; UseTime at the end of the next substep blips to the tail.
        ReplayResult r = Run("teleport 150 m", mode);
        Assert.InRange(r.TeleportBlipFrames, 1, 1);
    }

    [Theory]
    [InlineData(FrameMode.Fixed30Hz)]
    [InlineData(FrameMode.Variable15To144)]
    public void StreamStops_TheLeashStopsDeadReckoningWithinTheMaxConstraintDistance(FrameMode mode)
    {
        // After the last report the body keeps its root motion, but the constraint re-armed at that report counts its
        // travel and zeroes offsets from 50 m outdoors (GetMaxConstraintDistance): travel <= 50 m plus one step.
        ReplayResult r = Run("stream stops", mode);
        Assert.InRange(r.TravelAfterLastReport, 40.0, 50.0 + (ReplayRunner.SpeedCap * 0.2));
    }

    [Theory]
    [MemberData(nameof(Cases))]
    public void AfterTheFinalStop_TheBodyConvergesOnTheStopPointWithinASecond(string name, FrameMode mode)
    {
        // The last moving report is at most 0.2 s (interval) + 0.18 s (delay) + a held-back 0.3 s behind the stop; from at
        // most run speed x that lag (< 3 m) the body closes at 8 m/s, then completes the node within 0.05 m.
        ReplayScenario sc = ReplayScenarios.All().Single(s => s.Name == name);
        if (double.IsNaN(sc.StopTime))
        {
            return;
        }

        ReplayResult r = Run(name, mode);
        Assert.False(double.IsNaN(r.ConvergeTime), "never converged");
        Assert.InRange(r.ConvergeTime, 0.0, 1.0);
    }

    [Fact]
    public void Replay_IsDeterministic()
    {
        ReplayResult a = Run("dup + reorder 20 %", FrameMode.Variable15To144);
        ReplayResult b = Run("dup + reorder 20 %", FrameMode.Variable15To144);
        Assert.Equal(a.MeanError, b.MeanError);
        Assert.Equal(a.MaxStep, b.MaxStep);
        Assert.Equal(a.ErrorSeries.Count, b.ErrorSeries.Count);
    }
}
