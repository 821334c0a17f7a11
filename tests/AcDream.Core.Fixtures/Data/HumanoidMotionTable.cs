using System;
using System.Numerics;

namespace AcDream.Core.Fixtures.Data;

/// <summary>
/// A humanoid-like motion table's bytes (type 0x09), for driving a player through the real table path: the NonCombat style
/// (default substate Ready) with the Ready, WalkForward and RunForward cycles carrying the velocities the stand-in
/// <c>RetailSpeedMotionTable</c> uses (walk 3.12 m/s, run 4 m/s forward), and the style-wide SideStepRight (1.25 m/s to the
/// right) and TurnRight (1.5 rad/s clockwise: omega z = −1.5) modifiers. Each cycle plays one animation at framerate 0 (a
/// held pose), so the sequence moves the body by velocity and omega over the whole quantum, as the stand-in does
/// (<c>CSequence::update_internal</c>, acclient.c:339892, applies physics over the quantum when no frame is crossed).
/// No links: every motion is done as soon as it starts (num_anims = 0 + 1 − 1).
/// </summary>
/// <remarks>Animation ids <see cref="ReadyAnim"/>, <see cref="WalkAnim"/>, <see cref="RunAnim"/> (0x03000101..103); a
/// client needs the clips too (any one-frame animation per id) or the sequence drops them and the cycles hold no
/// animation — which moves the body the same way.</remarks>
public static class HumanoidMotionTable
{
    public const uint NonCombat = 0x8000003Du, Ready = 0x41000003u, WalkForward = 0x45000005u, RunForward = 0x44000007u;
    public const uint TurnRight = 0x6500000Du, SideStepRight = 0x6500000Fu;
    public const uint ReadyAnim = 0x03000101u, WalkAnim = 0x03000102u, RunAnim = 0x03000103u;

    /// <summary>The table's builder (add links or actions before <see cref="MotionTableBytes.ToArray"/>).</summary>
    public static MotionTableBytes Builder() => new MotionTableBytes { Id = 0x09000001, DefaultStyle = NonCombat }
        .StyleDefault(NonCombat, Ready)
        .Cycle(NonCombat, Ready, MotionDataSpec.One(ReadyAnim, 0, 0, 0f))
        .Cycle(NonCombat, WalkForward, MotionDataSpec.One(WalkAnim, 0, 0, 0f, velocity: new Vector3(0f, 3.12f, 0f)))
        .Cycle(NonCombat, RunForward, MotionDataSpec.One(RunAnim, 0, 0, 0f, velocity: new Vector3(0f, 4f, 0f)))
        .Modifier(0, SideStepRight, new MotionDataSpec(Array.Empty<(uint, int, int, float)>(), Velocity: new Vector3(1.25f, 0f, 0f)))
        .Modifier(0, TurnRight, new MotionDataSpec(Array.Empty<(uint, int, int, float)>(), Omega: new Vector3(0f, 0f, -1.5f)));

    /// <summary>The table's bytes.</summary>
    public static byte[] Bytes() => Builder().ToArray();
}
