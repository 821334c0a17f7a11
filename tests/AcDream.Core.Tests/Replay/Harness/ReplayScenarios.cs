using System.Numerics;

namespace AcDream.Core.Tests.Replay.Harness;

/// <summary>The replay set: what the server sends for a creature walking, running, turning, stopping, strafing, jumping, over a
/// lossy / duplicating / reordering network, teleporting 150 m, and going silent.</summary>
public static class ReplayScenarios
{
    /// <summary>Walking speed, m/s.</summary>
    public const float Walk = 1.25f;

    /// <summary>Running speed, m/s (AC run animation speed 4.0 at run rate 1).</summary>
    public const float Run = 4.0f;

    /// <summary>Seconds the server stays silent-free in <c>stream-stops</c> before going quiet.</summary>
    public const double SilenceAfter = 3.0;

    /// <summary>Every scenario, in table order.</summary>
    public static ReplayScenario[] All()
    {
        var start = new Vector3(60f, 40f, 0f);
        var typical = new NetworkModel();
        return
        [
            new("walk", TruthPath.Build(start, 0f, new MotionLeg(8, Walk), new MotionLeg(3, 0f)), typical, StopTime: 8),
            new("run", TruthPath.Build(start, 0f, new MotionLeg(8, Run), new MotionLeg(3, 0f)), typical, StopTime: 8),
            new("turn", TruthPath.Build(start, 0f, new MotionLeg(8, Run, TurnRate: 45f), new MotionLeg(3, 0f)), typical, StopTime: 8),
            new("stop-and-go", TruthPath.Build(start, 0f, new MotionLeg(3, Run), new MotionLeg(2, 0f), new MotionLeg(3, Run), new MotionLeg(3, 0f)), typical, StopTime: 8),
            new("strafe", TruthPath.Build(start, 0f, new MotionLeg(4, 0f, Strafe: 2f), new MotionLeg(4, 0f, Strafe: -2f), new MotionLeg(3, 0f)), typical, StopTime: 8),
            new("jump", TruthPath.Build(start, 0f, new MotionLeg(3, Run), new MotionLeg(3, Run, Jump: true), new MotionLeg(3, 0f)), typical, StopTime: 6),
            new("lossy 30 %", TruthPath.Build(start, 0f, new MotionLeg(8, Run), new MotionLeg(3, 0f)), typical with { Loss = 0.3 }, StopTime: 8),
            new("dup + reorder 20 %", TruthPath.Build(start, 0f, new MotionLeg(8, Run), new MotionLeg(3, 0f)), typical with { Duplicate = 0.2, Reorder = 0.2 }, StopTime: 8),
            new("teleport 150 m", TruthPath.Build(new Vector3(40f, 96f, 0f), 90f, new MotionLeg(3, Run), new MotionLeg(2, Run, Teleport: new Vector3(150f, 0f, 0f)), new MotionLeg(3, 0f)), typical, StopTime: 5, TeleportTime: 3, PlayerAt: new Vector3(126f, 96f, 0f)),
            new("stream stops", TruthPath.Build(start, 0f, new MotionLeg(20, Run)), typical with { StopAt = SilenceAfter }),
        ];
    }
}
