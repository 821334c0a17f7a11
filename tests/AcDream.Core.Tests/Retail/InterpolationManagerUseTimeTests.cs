using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Tests.Replay.Harness;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>UseTime: blips and Jump/Velocity heads (retail InterpolationManager::UseTime, acclient.c:389277).</summary>
public class InterpolationManagerUseTimeTests
{
    private static readonly Vector3 Start = new(50f, 50f, 0f);

    private static Position North(float metres) => ManagerScene.At(new Vector3(50f, 50f + metres, 0f));

    [Fact]
    public void FarUpdate_BlipsToTheTailWithinOneTick_WithSetPositionSimpleSlidingFlags()
    {
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(2f), false);
        s.Managers.InterpolateTo(North(150f), false);
        int before = s.Ground.PlacementCount;
        s.World.Tick(0.1);
        Position p = s.Creature.Position;
        Assert.Equal(North(150f).ObjCellId, p.ObjCellId);
        Assert.Equal(North(150f).Frame.Origin, p.Frame.Origin);
        Assert.Equal(before + 1, s.Ground.PlacementCount);
        // SetPositionSimple(p, 1): TELEPORT 0x2 | SLIDE 0x10 | SEND_POSITION_EVENT 0x1000 = 0x1012 (acclient.c:323420).
        Assert.Equal(0x1012u, (uint)s.Ground.LastPlacementFlags);
        Assert.Equal(0, s.Interpolation!.Count);
        Assert.Equal(0, s.Interpolation!.NodeFailCounter);
    }

    [Fact]
    public void UseTime_FailCounterAtThree_DoesNotBlip()
    {
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(10f), false);
        InterpolationManager im = s.Interpolation!;
        // Fail three nodes in a row (each audit without progress), leaving a fourth queued.
        s.Managers.InterpolateTo(North(11f), false);
        s.Managers.InterpolateTo(North(12f), false);
        s.Managers.InterpolateTo(North(13f), false);
        Frame offset = Frame.Identity;
        while (im.NodeFailCounter < 3)
        {
            offset = Frame.Identity;
            im.AdjustOffset(ref offset, 0.1);
        }

        int before = s.Ground.PlacementCount;
        im.UseTime();
        Assert.Equal(before, s.Ground.PlacementCount);
        Assert.Equal(1, im.Count);
    }

    [Fact]
    public void UseTime_BlipFails_KeepsQueueAndCounterAndRetriesNextTime()
    {
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(150f), false);
        InterpolationManager im = s.Interpolation!;
        s.Ground.FailPlacements = true;
        im.UseTime();
        Assert.Equal(1, im.Count);
        Assert.Equal(4, im.NodeFailCounter);
        s.Ground.FailPlacements = false;
        im.UseTime();
        Assert.Equal(0, im.Count);
        Assert.Equal(200f - 192f, s.Creature.Position.Frame.Origin.Y, 3);
    }

    [Fact]
    public void UseTime_VelocityHead_SetsVelocityAndCompletes()
    {
        var s = new ManagerScene(Start);
        InterpolationManager im = InterpolationManagerQueueTests.InterpolationOf(s);
        var v = new Vector3(1f, 2f, 0f);
        im.EnqueueNode(InterpolationNodeType.Velocity, North(1f), v);
        im.EnqueueNode(InterpolationNodeType.Position, North(3f), Vector3.Zero);
        im.UseTime();
        Assert.Equal(v, s.Creature.Velocity);
        Assert.Equal(1, im.Count);
        Assert.Equal(InterpolationNodeType.Position, im.GetNode(0).Type);
    }

    [Fact]
    public void UseTime_JumpHead_CompletesWithoutTouchingVelocity()
    {
        var s = new ManagerScene(Start);
        InterpolationManager im = InterpolationManagerQueueTests.InterpolationOf(s);
        im.EnqueueNode(InterpolationNodeType.Jump, North(1f), new Vector3(0f, 0f, 5f), 0.5f);
        im.UseTime();
        Assert.Equal(Vector3.Zero, s.Creature.Velocity);
        Assert.Equal(0, im.Count);
    }

    [Fact]
    public void Blip_VelocityTail_GoesToTheLastPositionBeforeItAndRestoresTheVelocity()
    {
        var s = new ManagerScene(Start);
        s.Managers.InterpolateTo(North(2f), false);
        s.Managers.InterpolateTo(North(150f), false);   // fail counter 4
        InterpolationManager im = s.Interpolation!;
        var v = new Vector3(0f, 3f, 0f);
        im.EnqueueNode(InterpolationNodeType.Velocity, North(160f), v);
        im.UseTime();
        // Tail is Velocity: scan head..tail-1, the last Position is the 150 m node (acclient.c:389330-389350).
        Assert.Equal(North(150f).Frame.Origin, s.Creature.Position.Frame.Origin);
        Assert.Equal(v, s.Creature.Velocity);
        Assert.Equal(0, im.Count);
    }

    [Fact]
    public void Blip_LoneJumpNodeLeft_GoesToBliptoPosition()
    {
        // Queue P(10) P(11) P(12) P(13) Jump; the body never moves so each audit fails a Position node. After the fourth,
        // NodeCompleted(0) sees a Jump head and remembers P(13) as blipto (acclient.c:388923). UseTime: counter 4 > 3,
        // tail Jump == head, nothing to scan -> SetPositionSimple(blipto) (acclient.c:389366).
        var s = new ManagerScene(Start);
        InterpolationManager im = InterpolationManagerQueueTests.InterpolationOf(s);
        for (int i = 0; i < 4; i++)
        {
            im.EnqueueNode(InterpolationNodeType.Position, North(10f + i), Vector3.Zero);
        }

        im.EnqueueNode(InterpolationNodeType.Jump, North(30f), Vector3.Zero);
        while (im.NodeFailCounter < 4)
        {
            Frame f = Frame.Identity;
            im.AdjustOffset(ref f, 0.1);
        }

        Assert.Equal(1, im.Count);
        Assert.Equal(63f, im.BliptoPosition.Frame.Origin.Y);
        im.UseTime();
        Assert.Equal(63f, s.Creature.Position.Frame.Origin.Y);
        Assert.Equal(0, im.Count);
    }
}
