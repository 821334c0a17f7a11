using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Tests.Replay.Harness;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>adjust_offset: the step, the speed cap, the audit (retail InterpolationManager::adjust_offset, acclient.c:389177).</summary>
public class InterpolationManagerStepTests
{
    private static readonly Vector3 Start = new(50f, 50f, 0f);

    private static Position North(float metres, float heading = 0f) => ManagerScene.At(new Vector3(50f, 50f + metres, 0f), heading);

    private static Frame Step(InterpolationManager im, double quantum)
    {
        Frame offset = Frame.Identity;
        im.AdjustOffset(ref offset, quantum);
        return offset;
    }

    [Fact]
    public void AdjustOffset_FarHead_StepsTwiceTheAdjustedMaxSpeedTimesQuantum()
    {
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(10f), false);
        Frame offset = Step(s.Interpolation!, 0.1);
        // No movement manager: get_minterp creates the default one, 4 m/s (1.0 * 4.0) -> my_max_speed = (float)(4 * 2.0) = 8.
        // progress = (float)(8f * 0.1); adjustment (0, 10, 0) scaled by (float)(progress / 10f).
        float progress = (float)(8f * 0.1);
        float rhs = progress / 10f;
        Assert.Equal(0f, offset.Origin.X, 5);
        Assert.Equal(10f * rhs, offset.Origin.Y, 5);
        Assert.Equal(0f, offset.Origin.Z, 5);
    }

    [Fact]
    public void AdjustOffset_SpeedIsTwiceAdjustedMaxSpeed_NotCappedAtSevenPointFive()
    {
        // Retail's 7.5 is a fallback below EPSILON (acclient.c:389239), not a min(): adjusted 6 m/s -> 12 m/s.
        var s = new ManagerScene(Start);
        s.Creature.Movement = new StubMotion(maxSpeed: 1.0, adjustedMaxSpeed: 6.0);
        s.Managers.InterpolateTo(North(10f), false);
        Frame offset = Step(s.Interpolation!, 0.1);
        float progress = (float)((float)(6.0 * 2.0) * 0.1);
        Assert.Equal(10f * (progress / 10f), offset.Origin.Y, 5);
    }

    [Theory]
    [InlineData(true, 0.0)]   // an interpreter reporting 0 m/s: 2 * 0 < EPSILON
    [InlineData(false, 4.0)]  // no interpreter at all: my_max_speed stays 0
    public void AdjustOffset_UnknownSpeed_FallsBackToSevenPointFive(bool hasInterpreter, double speed)
    {
        var s = new ManagerScene(Start);
        s.Creature.Movement = new StubMotion(speed, speed, hasInterpreter);
        s.Managers.InterpolateTo(North(10f), false);
        Frame offset = Step(s.Interpolation!, 0.1);
        float progress = (float)(7.5f * 0.1);
        Assert.Equal(10f * (progress / 10f), offset.Origin.Y, 5);
    }

    [Fact]
    public void AdjustOffset_HeadIsExpressedInTheBodysLocalFrame()
    {
        // Body faces east (90 degrees); a target 10 m east is straight ahead: local +Y.
        var s = new ManagerScene(Start, creatureHeading: 90f);
        s.Managers.InterpolateTo(ManagerScene.At(Start + new Vector3(10f, 0f, 0f), 90f), false);
        Frame offset = Step(s.Interpolation!, 0.1);
        Assert.Equal(0f, offset.Origin.X, 4);
        Assert.Equal(0.8f, offset.Origin.Y, 4);
    }

    [Fact]
    public void AdjustOffset_HeadInTheNextLandblock_UsesTheBlockOffset()
    {
        // Body at x = 191 in block 0x7F7F; target 2 m east is x = 1 in block 0x807F.
        var s = new ManagerScene(new Vector3(191f, 50f, 0f));
        Position target = ManagerScene.At(new Vector3(193f, 50f, 0f));
        Assert.NotEqual(s.Creature.Position.ObjCellId >> 16, target.ObjCellId >> 16);
        s.Managers.InterpolateTo(target, false);
        Frame offset = Step(s.Interpolation!, 0.1);
        Assert.Equal(0.8f, offset.Origin.X, 4);
        Assert.Equal(0f, offset.Origin.Y, 4);
    }

    [Fact]
    public void AdjustOffset_ReplacesTheOffsetIncludingRotation_UnlessKeepHeading()
    {
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(10f, heading: 90f), false);
        Frame offset = Frame.FromHeading(new Vector3(0f, 5f, 0f), 30f);
        s.Interpolation!.AdjustOffset(ref offset, 0.1);
        Assert.Equal(0.8f, offset.Origin.Y, 4);
        Assert.Equal(90.0, offset.Heading, 3);

        var k = new ManagerScene(Start);
        k.Managers.InterpolateTo(North(10f, heading: 90f), true);
        Frame kept = Frame.FromHeading(new Vector3(0f, 5f, 0f), 30f);
        k.Interpolation!.AdjustOffset(ref kept, 0.1);
        Assert.Equal(0.8f, kept.Origin.Y, 4);
        Assert.Equal(0.0, kept.Heading, 3);
    }

    [Fact]
    public void AdjustOffset_HeadWithinDesiredDistance_CompletesAndLeavesTheOffset()
    {
        var s = new ManagerScene(Start);
        PositionManager pm = s.Managers;
        InterpolationManager im = InterpolationManagerQueueTests.InterpolationOf(s);
        im.EnqueueNode(InterpolationNodeType.Position, North(0.03f), Vector3.Zero);
        im.EnqueueNode(InterpolationNodeType.Position, North(3f), Vector3.Zero);
        Frame offset = Step(im, 0.1);
        Assert.Equal(Vector3.Zero, offset.Origin);
        Assert.Equal(1, im.Count);
        // NodeCompleted (acclient.c:388917): the next Position head sets original_distance = (float)distance(body, head) = 3.
        Assert.Equal(3f, im.OriginalDistance);
        Assert.NotNull(pm);
    }

    [Fact]
    public void AdjustOffset_BodyNotInContact_DoesNothing()
    {
        var s = new ManagerScene(Start);
        s.Creature.SetPositionSimple(ManagerScene.At(Start + new Vector3(0f, 0f, 5f)), false);
        Assert.Equal(0, (int)(s.Creature.TransientState & TransientState.Contact));
        s.Managers.InterpolateTo(ManagerScene.At(Start + new Vector3(0f, 10f, 5f)), false);
        Frame offset = Step(s.Interpolation!, 0.1);
        Assert.Equal(Vector3.Zero, offset.Origin);
        Assert.Equal(0u, s.Interpolation!.FrameCounter);
    }

    [Fact]
    public void AdjustOffset_ProgressQuantumIsTheSumOfQuanta()
    {
        // acclient.c:389242: progress_quantum(float) = quantum + progress_quantum, per call.
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(10f), false);
        InterpolationManager im = s.Interpolation!;
        Step(im, 0.1);
        Step(im, 0.05);
        Step(im, 0.02);
        float expected = (float)(0.02 + (float)(0.05 + (float)(0.1 + 0f)));
        Assert.Equal(expected, im.ProgressQuantum);
        Assert.Equal(3u, im.FrameCounter);
    }

    [Fact]
    public void Audit_FirstAuditAfterAnEmptyQueueAlwaysPasses()
    {
        // original_distance is BIG_DISTANCE (999999) until the first audit: progress is huge.
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(10f), false);
        InterpolationManager im = s.Interpolation!;
        for (int i = 0; i < 5; i++)
        {
            Step(im, 0.1);
        }

        Assert.Equal(0u, im.FrameCounter);
        Assert.Equal(0f, im.ProgressQuantum);
        Assert.Equal(10f, im.OriginalDistance);
        Assert.Equal(0, im.NodeFailCounter);
    }

    [Theory]
    // pass when progress / progress_quantum / my_max_speed >= 0.3 (dimensionless).
    // 1.3 m in 5 x 0.1 s at 8 m/s: 1.3 / 0.5 / 8 = 0.325 -> pass. 1.1 m: 0.275 -> fail.
    // (The reference's "progress / progress_quantum / dt" would give 26 and 22: both pass.)
    [InlineData(1.3f, true)]
    [InlineData(1.1f, false)]
    public void Audit_ComparesClosingRateWithThirtyPercentOfTheSpeedCap(float moved, bool passes)
    {
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(10f), false);
        s.Managers.InterpolateTo(North(20f), false);
        InterpolationManager im = s.Interpolation!;
        for (int i = 0; i < 5; i++)
        {
            Step(im, 0.1);
        }

        s.Creature.SetPositionSimple(North(moved), false);
        for (int i = 0; i < 5; i++)
        {
            Step(im, 0.1);
        }

        if (passes)
        {
            Assert.Equal(2, im.Count);
            Assert.Equal(0, im.NodeFailCounter);
            Assert.Equal(10f - moved, im.OriginalDistance, 4);
        }
        else
        {
            Assert.Equal(1, im.Count);
            Assert.Equal(1, im.NodeFailCounter);
        }
    }

    [Fact]
    public void Audit_NoProgressButWithinPointTwoMetres_CompletesAsSuccess()
    {
        // acclient.c:389270: curr_distance 0.15 < 0.2 -> NodeCompleted(1), no fail count.
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(0.15f), false);
        InterpolationManager im = s.Interpolation!;
        for (int i = 0; i < 10; i++)
        {
            Step(im, 0.1);
        }

        Assert.Equal(0, im.Count);
        Assert.Equal(0, im.NodeFailCounter);
    }

    [Fact]
    public void Audit_NoProgressFarFromTheNode_FailsRemembersItAndTheNextUseTimeBlipsThere()
    {
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(10f), false);
        InterpolationManager im = s.Interpolation!;
        for (int i = 0; i < 10; i++)
        {
            Step(im, 0.1);
        }

        Assert.Equal(0, im.Count);
        Assert.Equal(1, im.NodeFailCounter);
        Assert.Equal(60f, im.BliptoPosition.Frame.Origin.Y);
        // Queue ran dry with a failure: UseTime blips to blipto_position (acclient.c:389307, 389366).
        im.UseTime();
        Assert.Equal(60f, s.Creature.Position.Frame.Origin.Y);
        Assert.Equal(0, im.NodeFailCounter);
    }

    [Fact]
    public void Audit_StuckToAnObject_PassesWithoutProgress()
    {
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(10f), false);
        s.Managers.StickTo(99, 0.5f, 1f);
        InterpolationManager im = s.Interpolation!;
        for (int i = 0; i < 10; i++)
        {
            Step(im, 0.1);
        }

        Assert.Equal(1, im.Count);
        Assert.Equal(0, im.NodeFailCounter);
    }

    [Fact]
    public void AdjustOffset_JumpOrVelocityHead_DoesNothing()
    {
        var s = new ManagerScene(Start);
        InterpolationManager im = InterpolationManagerQueueTests.InterpolationOf(s);
        im.EnqueueNode(InterpolationNodeType.Jump, North(5f), Vector3.Zero);
        Frame offset = Step(im, 0.1);
        Assert.Equal(Vector3.Zero, offset.Origin);
        Assert.Equal(0u, im.FrameCounter);
    }

    [Fact]
    public void WorldTick_InterpolationOffsetReplacesRootMotion()
    {
        // Root motion says 4 m/s north; the node is 10 m east: after one 0.1 s step the body moved east only.
        var s = new ManagerScene(Start);
        s.CreatureParts.SequenceVelocity = new Vector3(0f, 4f, 0f);
        s.Managers.InterpolateTo(ManagerScene.At(Start + new Vector3(10f, 0f, 0f)), false);
        s.World.Tick(0.1);
        Vector3 o = s.Creature.Position.Frame.Origin;
        Assert.Equal(50.8f, o.X, 3);
        Assert.Equal(50f, o.Y, 3);
    }

}
