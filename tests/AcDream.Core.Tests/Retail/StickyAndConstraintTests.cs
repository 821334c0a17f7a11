using System;
using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Tests.Replay.Harness;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>StickyManager (acclient.c:388501-388727) and ConstraintManager (acclient.c:389394-389513).</summary>
public class StickyAndConstraintTests
{
    private static readonly Vector3 Start = new(50f, 50f, 0f);

    private static (ManagerScene Scene, PhysicsObj Target) StuckScene(Vector3 targetAt)
    {
        var s = new ManagerScene(Start);
        PhysicsObj target = s.World.CreateObject(7);
        target.PartArray = new SimplePartArray(1, 1) { Radius = 0.5f };
        target.EnterWorld(ManagerScene.At(targetAt));
        s.Creature.StickToObject(7);
        s.Creature.HandleUpdateTarget(new TargetInfo { ObjectId = 7, Status = TargetStatus.Ok, TargetPosition = target.Position });
        return (s, target);
    }

    [Theory]
    // Target 5 m north, radii 0.5 + 0.5: mag = 5 - 1 - 0.3 = 3.7 m. Speed = get_max_speed (4) * 5 = 20 m/s.
    [InlineData(0.1, 2.0f)]    // step 20 * 0.1 = 2.0 < 3.7: moves 2.0
    [InlineData(0.25, 3.7f)]   // step 5.0 >= 3.7: moves exactly mag
    public void Sticky_StepsTowardThePointPointThreeMetresOutsideTheCylinders(double quantum, float expected)
    {
        (ManagerScene s, _) = StuckScene(Start + new Vector3(0f, 5f, 0f));
        Frame offset = Frame.Identity;
        s.Managers.StickyManager!.AdjustOffset(ref offset, quantum);
        Assert.Equal(0f, offset.Origin.X, 5);
        Assert.Equal(expected, offset.Origin.Y, 4);
        Assert.Equal(0.0, offset.Heading, 3);
    }

    [Fact]
    public void Sticky_TurnsTowardTheTarget_WrappingNegativeTurnsBy360()
    {
        // Body faces east (90); the target is due north (0): 0 - 90 = -90 < -EPSILON -> 270 (acclient.c:388599).
        var s = new ManagerScene(Start, creatureHeading: 90f);
        PhysicsObj target = s.World.CreateObject(7);
        target.PartArray = new SimplePartArray(1, 1);
        target.EnterWorld(ManagerScene.At(Start + new Vector3(0f, 5f, 0f)));
        s.Creature.StickToObject(7);
        s.Creature.HandleUpdateTarget(new TargetInfo { ObjectId = 7, Status = TargetStatus.Ok, TargetPosition = target.Position });
        Frame offset = Frame.Identity;
        s.Managers.StickyManager!.AdjustOffset(ref offset, 0.1);
        Assert.Equal(270.0, offset.Heading, 2);
    }

    [Fact]
    public void Sticky_NotInitialised_LeavesTheOffset()
    {
        var s = new ManagerScene(Start);
        s.Managers.StickTo(7, 0.5f, 1f);
        Frame offset = Frame.FromHeading(new Vector3(0f, 1f, 0f), 0f);
        s.Managers.StickyManager!.AdjustOffset(ref offset, 0.1);
        Assert.Equal(1f, offset.Origin.Y);
    }

    [Fact]
    public void Sticky_TargetUnknownToTheWorld_UsesTheReportedPosition()
    {
        var s = new ManagerScene(Start);
        s.Managers.StickTo(42, 0.5f, 1f);
        s.Creature.HandleUpdateTarget(new TargetInfo
        {
            ObjectId = 42,
            Status = TargetStatus.Ok,
            TargetPosition = ManagerScene.At(Start + new Vector3(5f, 0f, 0f)),
        });
        Frame offset = Frame.Identity;
        s.Managers.StickyManager!.AdjustOffset(ref offset, 0.1);
        Assert.Equal(2.0f, offset.Origin.X, 4);
        Assert.Equal(90.0, offset.Heading, 2);
    }

    [Fact]
    public void Sticky_LastsOneSecond_ThenUnsticksAndCancelsTheMoveTo()
    {
        var s = new ManagerScene(Start);
        var motion = new StubMotion(4.0, 4.0);
        s.Creature.Movement = motion;
        s.Managers.StickTo(42, 0.5f, 1f);
        // set_target(0, 42, 0.5, 0.5) (acclient.c:388687): the creature's TargetManager tracks 42 (unknown to the world, so
        // no voyeur is registered anywhere).
        Assert.True(s.Creature.TargetManager!.HasTarget);
        Assert.Equal(42u, s.Creature.TargetManager.TargetInfo.ObjectId);
        Assert.Equal(0.5f, s.Creature.TargetManager.TargetInfo.Radius);
        Assert.Equal(0.5, s.Creature.TargetManager.TargetInfo.Quantum);
        s.World.SetCurrentTime(1.0);   // timeout = 0 + 1.0; the test is strict `>` (acclient.c:388613)
        s.Managers.UseTime();
        Assert.Equal(42u, s.Creature.StickyObjectId);
        s.World.SetCurrentTime(1.001);
        s.Managers.UseTime();
        Assert.Equal(0u, s.Creature.StickyObjectId);
        Assert.False(s.Creature.TargetManager.HasTarget);   // clear_target
        Assert.Equal(AcDream.Core.Physics.Motion.MotionError.ActionCancelled, motion.LastCancel);   // 0x36
    }

    [Fact]
    public void Sticky_ReportWithOtherStatus_Unsticks_AndOtherObjectsAreIgnored()
    {
        var s = new ManagerScene(Start);
        s.Managers.StickTo(42, 0.5f, 1f);
        s.Creature.HandleUpdateTarget(new TargetInfo { ObjectId = 43, Status = TargetStatus.ExitWorld });
        Assert.Equal(42u, s.Creature.StickyObjectId);
        s.Creature.HandleUpdateTarget(new TargetInfo { ContextId = 1, ObjectId = 42, Status = TargetStatus.ExitWorld });
        Assert.Equal(42u, s.Creature.StickyObjectId);   // context != 0 is not forwarded (acclient.c:319966)
        s.Creature.HandleUpdateTarget(new TargetInfo { ObjectId = 42, Status = TargetStatus.Teleported });
        Assert.Equal(0u, s.Creature.StickyObjectId);
    }

    [Fact]
    public void Sticky_OkReportWithBadPosition_Throws()
    {
        var s = new ManagerScene(Start);
        s.Managers.StickTo(42, 0.5f, 1f);
        Position bad = ManagerScene.At(Start);
        bad.Frame.Origin = new Vector3(float.PositiveInfinity, 0f, 0f);
        Assert.Throws<ArgumentException>(() => s.Creature.HandleUpdateTarget(new TargetInfo { ObjectId = 42, Status = TargetStatus.Ok, TargetPosition = bad }));
        Assert.False(s.Managers.StickyManager!.Initialized);
    }

    [Theory]
    // count 30 in (10, 50): scale (50 - 30) / (50 - 10) = 0.5 -> 1 m becomes 0.5 m, count 30.5
    [InlineData(30f, 0.5f, 30.5f)]
    // count 5 <= 10: unscaled, count 6
    [InlineData(5f, 1f, 6f)]
    // count 50 >= max: zeroed, count unchanged
    [InlineData(50f, 0f, 50f)]
    public void Constraint_ScalesLinearlyBetweenStartAndMax_ZeroFromMax(float count, float expectedStep, float expectedCount)
    {
        var s = new ManagerScene(Start);
        // ConstrainTo(p) starts the count at distance(p, body) (acclient.c:389526).
        s.Managers.ConstrainTo(ManagerScene.At(Start + new Vector3(0f, count, 0f)), 10f, 50f);
        ConstraintManager cm = s.Managers.ConstraintManager!;
        Assert.Equal(count, cm.ConstraintPosOffset, 4);
        Frame offset = Frame.FromHeading(new Vector3(0f, 1f, 0f), 0f);
        cm.AdjustOffset(ref offset, 0.1);
        Assert.Equal(expectedStep, offset.Origin.Y, 5);
        Assert.Equal(expectedCount, cm.ConstraintPosOffset, 4);
    }

    [Fact]
    public void Constraint_NotInContact_DoesNotScaleButStillCounts()
    {
        var s = new ManagerScene(Start);
        s.Creature.SetPositionSimple(ManagerScene.At(Start + new Vector3(0f, 0f, 3f)), false);
        s.Managers.ConstrainTo(ManagerScene.At(Start + new Vector3(0f, 0f, 33f)), 10f, 50f);
        ConstraintManager cm = s.Managers.ConstraintManager!;
        Frame offset = Frame.FromHeading(new Vector3(0f, 1f, 0f), 0f);
        cm.AdjustOffset(ref offset, 0.1);
        Assert.Equal(1f, offset.Origin.Y);
        Assert.Equal(31f, cm.ConstraintPosOffset, 4);
    }

    [Fact]
    public void Constraint_CountIsARunningTotalOfStepLengths_NotTheLatestStep()
    {
        // adjust_offset ends with constraint_pos_offset = |offset| + constraint_pos_offset (acclient.c:389477, the last
        // statement): every step adds its length. From a count of 0, three 1 m steps give 1, 2, 3 (a reading that stores
        // only the current step's length would give 1, 1, 1). Step 3 is still unscaled: 2 <= start 10.
        var s = new ManagerScene(Start);
        s.Managers.ConstrainTo(ManagerScene.At(Start), 10f, 50f);
        ConstraintManager cm = s.Managers.ConstraintManager!;
        Assert.Equal(0f, cm.ConstraintPosOffset);
        for (int i = 1; i <= 3; i++)
        {
            Frame offset = Frame.FromHeading(new Vector3(0f, 1f, 0f), 0f);
            cm.AdjustOffset(ref offset, 1.0 / 30.0);
            Assert.Equal(1f, offset.Origin.Y);
            Assert.Equal((float)i, cm.ConstraintPosOffset);
        }
    }

    [Theory]
    // fully constrained when max * 0.9 < count: 50 * 0.9 = 45
    [InlineData(44.9f, false)]
    [InlineData(45.1f, true)]
    public void Constraint_FullyConstrainedAboveNinetyPercentOfMax(float count, bool expected)
    {
        var s = new ManagerScene(Start);
        s.Managers.ConstrainTo(ManagerScene.At(Start + new Vector3(0f, count, 0f)), 10f, 50f);
        Assert.Equal(expected, s.Creature.IsFullyConstrained);
    }

    [Fact]
    public void ConstraintDistances_AreFiveAndTwentyIndoorsTenAndFiftyOutdoors()
    {
        var s = new ManagerScene(Start);
        Assert.Equal(10.0, s.Creature.StartConstraintDistance);
        Assert.Equal(50.0, s.Creature.MaxConstraintDistance);
        s.Creature.SetPositionSimple(new Position(ManagerScene.Block | 0x0100u, Frame.FromHeading(Start, 0f)), true);
        Assert.Equal(5.0, s.Creature.StartConstraintDistance);
        Assert.Equal(20.0, s.Creature.MaxConstraintDistance);
    }

    [Fact]
    public void Constraint_Unconstrained_LeavesOffsetAndCount()
    {
        var s = new ManagerScene(Start);
        s.Managers.ConstrainTo(ManagerScene.At(Start + new Vector3(0f, 30f, 0f)), 10f, 50f);
        s.Managers.StopConstraining();
        Frame offset = Frame.FromHeading(new Vector3(0f, 1f, 0f), 0f);
        s.Managers.ConstraintManager!.AdjustOffset(ref offset, 0.1);
        Assert.Equal(1f, offset.Origin.Y);
        Assert.Equal(30f, s.Managers.ConstraintManager!.ConstraintPosOffset, 4);
    }

    [Fact]
    public void PositionManager_AdjustOrder_InterpolationThenStickyThenConstraint()
    {
        // Interpolation wants 0.8 m north-east-ish; sticky overrides with 2.0 m north; the constraint (count 30) halves it.
        (ManagerScene s, _) = StuckScene(Start + new Vector3(0f, 5f, 0f));
        s.Managers.InterpolateTo(ManagerScene.At(Start + new Vector3(10f, 0f, 0f)), false);
        s.Managers.ConstrainTo(ManagerScene.At(Start + new Vector3(0f, 30f, 0f)), 10f, 50f);
        Frame offset = Frame.Identity;
        s.Managers.AdjustOffset(ref offset, 0.1);
        Assert.Equal(0f, offset.Origin.X, 4);
        Assert.Equal(1.0f, offset.Origin.Y, 4);
    }
}
