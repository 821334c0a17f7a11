using System;
using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Tests.Replay.Harness;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>InterpolateTo: near/far branches, stop, tail prune, cap (retail InterpolationManager::InterpolateTo, acclient.c:389016).</summary>
public class InterpolationManagerQueueTests
{
    private static readonly Vector3 Start = new(50f, 50f, 0f);

    private static Position North(float metres, float heading = 0f) => ManagerScene.At(new Vector3(50f, 50f + metres, 0f), heading);

    [Fact]
    public void InterpolateTo_NearAndFartherThanDesiredDistance_AppendsOnePositionNode()
    {
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(2f), false);
        InterpolationManager im = s.Interpolation!;
        Assert.Equal(1, im.Count);
        Assert.Equal(InterpolationNodeType.Position, im.GetNode(0).Type);
        Assert.Equal(0, im.NodeFailCounter);
        Assert.True(s.Creature.IsInterpolating);
    }

    [Fact]
    public void InterpolateTo_WithinDesiredDistance_StopsAndTurnsToReportedHeading()
    {
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(5f), false);
        // 0.04 m < 0.05 m (acclient.c:389057): StopInterpolating and set_heading(p's heading).
        s.Managers.InterpolateTo(North(0.04f, heading: 90f), false);
        Assert.Equal(0, s.Interpolation!.Count);
        Assert.Equal(90.0, s.Creature.Position.Frame.Heading, 3);
    }

    [Fact]
    public void InterpolateTo_WithinDesiredDistanceKeepingHeading_StopsWithoutTurning()
    {
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(0.04f, heading: 90f), true);
        Assert.Equal(0, s.Interpolation!.Count);
        Assert.Equal(0.0, s.Creature.Position.Frame.Heading, 3);
    }

    [Fact]
    public void InterpolateTo_SeveralTailNodesWithinDesiredDistance_AllCollapseIntoTheNewTarget()
    {
        // Retail walks the tail in a loop, not a single compare. B (2.00) and C (2.06) are 0.06 m apart so both are kept; D (2.03) is
        // 0.03 m from C and 0.03 m from B: both go; A (1.00) is 1.03 m away and stops the walk.
        var s = new ManagerScene(Start);
        PositionManager pm = s.Managers;
        pm.InterpolateTo(North(1f), false);
        pm.InterpolateTo(North(2f), false);
        pm.InterpolateTo(North(2.06f), false);
        Assert.Equal(3, s.Interpolation!.Count);
        pm.InterpolateTo(North(2.03f), false);
        InterpolationManager im = s.Interpolation!;
        Assert.Equal(2, im.Count);
        Assert.Equal(51f, im.GetNode(0).Position.Frame.Origin.Y);
        Assert.Equal(52.03f, im.GetNode(1).Position.Frame.Origin.Y);
    }

    [Fact]
    public void InterpolateTo_TailIsVelocityNode_PruneStopsThere()
    {
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(2f), false);
        InterpolationManager im = s.Interpolation!;
        im.EnqueueNode(InterpolationNodeType.Velocity, North(2f), new Vector3(0f, 1f, 0f));
        // Within 0.05 m of the Position node, but the tail is a Velocity node: nothing is removed.
        s.Managers.InterpolateTo(North(2.01f), false);
        Assert.Equal(3, im.Count);
    }

    [Fact]
    public void InterpolateTo_TwentyFiveNearUpdates_KeepsTheNewestTwentyEvictingAtTheHead()
    {
        // Retail: while count >= 20 pop the head, then append. Updates at 51, 51.5, ..., 63 m: the first five go.
        var s = new ManagerScene(Start);
        for (int i = 0; i < 25; i++)
        {
            s.Managers.InterpolateTo(North(1f + (i * 0.5f)), false);
        }

        InterpolationManager im = s.Interpolation!;
        Assert.Equal(20, im.Count);
        Assert.Equal(50f + 1f + (5 * 0.5f), im.GetNode(0).Position.Frame.Origin.Y);
        Assert.Equal(50f + 1f + (24 * 0.5f), im.GetNode(19).Position.Frame.Origin.Y);
    }

    [Fact]
    public void InterpolateTo_FartherThanAutonomyBlipDistance_AppendsAndPrearmsFailCounterToFour()
    {
        // 150 m > 100 m outdoors (GetAutonomyBlipDistance, acclient.c:315860).
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(1f), false);
        s.Managers.InterpolateTo(North(150f), false);
        InterpolationManager im = s.Interpolation!;
        Assert.Equal(2, im.Count);
        Assert.Equal(4, im.NodeFailCounter);
    }

    [Fact]
    public void InterpolateTo_FarBranch_UsesTheStoredKeepHeadingNotTheArgument()
    {
        // acclient.c:389157 reads the member keep_heading, which only the near branch writes (389098).
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(1f, heading: 90f), true);
        s.Managers.InterpolateTo(North(150f, heading: 90f), false);
        InterpolationManager im = s.Interpolation!;
        Assert.True(im.KeepHeading);
        // Both nodes carry the body's heading (0) instead of the reported 90.
        Assert.Equal(0.0, im.GetNode(0).Position.Frame.Heading, 3);
        Assert.Equal(0.0, im.GetNode(1).Position.Frame.Heading, 3);
    }

    [Fact]
    public void InterpolateTo_DistanceMeasuredFromTheTailNode_NotTheBody()
    {
        // Tail at 95 m; a report at 190 m is 95 m from the tail (near) although 140 m from the body.
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(95f), false);
        s.Managers.InterpolateTo(North(190f), false);
        Assert.Equal(0, s.Interpolation!.NodeFailCounter);
        Assert.Equal(2, s.Interpolation!.Count);
    }

    [Fact]
    public void AutonomyBlipDistance_IsTwentyIndoorsForOthersTwentyFiveForThePlayerAndHundredOutdoors()
    {
        var s = new ManagerScene(Start);
        Assert.Equal(100.0, s.Creature.AutonomyBlipDistance);
        Assert.Equal(100.0, s.Player.AutonomyBlipDistance);
        var indoor = new Position(ManagerScene.Block | 0x0100u, Frame.FromHeading(Start, 0f));
        s.Creature.SetPositionSimple(indoor, true);
        s.Player.SetPositionSimple(indoor, true);
        Assert.Equal(20.0, s.Creature.AutonomyBlipDistance);
        Assert.Equal(25.0, s.Player.AutonomyBlipDistance);
        // Indoors a report 21 m away is far for a creature: pre-armed blip.
        var far = new Position(ManagerScene.Block | 0x0100u, Frame.FromHeading(Start + new Vector3(0f, 21f, 0f), 0f));
        s.Creature.InterpolateTo(far, false);
        Assert.Equal(4, s.Interpolation!.NodeFailCounter);
    }

    [Fact]
    public void Enqueue_WithCurrentBodyPosition_MeasuresFromThatBody()
    {
        var s = new ManagerScene(Start);
        InterpolationManager im = InterpolationOf(s);
        // Stored body at 50 m: 0.03 m would stop; the given body 10 m south makes it a 10.03 m move.
        im.Enqueue(North(0.03f), false, North(-10f));
        Assert.Equal(1, im.Count);
        im.Enqueue(North(0.03f));
        Assert.Equal(0, im.Count);
    }

    [Fact]
    public void InterpolateTo_NonFinitePosition_ThrowsAndLeavesTheQueue()
    {
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(2f), false);
        Position bad = North(3f);
        bad.Frame.Origin = new Vector3(float.NaN, 0f, 0f);
        Assert.Throws<ArgumentException>(() => s.Interpolation!.InterpolateTo(bad, false));
        Assert.Throws<ArgumentException>(() => s.Interpolation!.Enqueue(North(1f), false, bad));
        Assert.Equal(1, s.Interpolation!.Count);
    }

    [Fact]
    public void StopInterpolating_ClearsQueueCountersAndAuditState()
    {
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(150f), false);
        InterpolationManager im = s.Interpolation!;
        im.StopInterpolating();
        Assert.Equal(0, im.Count);
        Assert.False(im.IsInterpolating);
        Assert.Equal(0, im.NodeFailCounter);
        Assert.Equal(0u, im.FrameCounter);
        Assert.Equal(0f, im.ProgressQuantum);
        Assert.Equal(InterpolationManager.BigDistance, im.OriginalDistance);
    }

    internal static InterpolationManager InterpolationOf(ManagerScene s)
    {
        // Creates the manager without queuing: a stop-branch call on the body's own position.
        s.Managers.InterpolateTo(s.Creature.Position, true);
        return s.Interpolation!;
    }
}
