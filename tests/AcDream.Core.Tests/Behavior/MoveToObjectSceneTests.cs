using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;
using AcDream.Core.Physics.Motion.MoveTo;

namespace AcDream.Core.Tests.Behavior;

// MoveToObject and TurnToObject through the world's object table and TargetManager (MoveToScene: the player, id 1, at
// (100, 40) facing north, radius 0.5, run 0.475 m and walk 0.156 m per step). The target's report reaches the player when it
// is sent: at the move-to (add_voyeur), then from the target's own step every 0.5 s of physics time when its predicted
// position moved more than 0.5 m.
public class MoveToObjectSceneTests
{
    private static PhysicsObj Target(PhysicsWorld world, float x, float y) =>
        MoveToScene.Creature(world, 2, RemoteCreatureWeenie.Creature, new Vector3(x, y, 20f));

    [Fact]
    public void MoveToObject_Stationary_PlansAtTheFirstReport_AndStopsAtTheCylinderDistance()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        PhysicsObj target = Target(world, 100f, 50f);
        // Threshold 1: run. The target's report (add_voyeur) arrives inside the call: the steps are planned at once.
        player.MoveToObject(2, new MovementParameters { WalkRunThreshold = 1f });
        MoveToManager m = mm.MoveToManager!;
        Assert.True(m.Initialized);
        Assert.Equal(MovementType.MoveToObject, m.MovementType);
        Assert.Equal(2u, m.TopLevelObjectId);
        Assert.Equal(0.5f, m.SoughtObjectRadius);
        Assert.True(player.TargetManager!.HasTarget);
        Assert.Equal(2u, player.TargetManager.TargetInfo.ObjectId);
        Assert.Equal(1, target.TargetManager!.VoyeurCount);
        Assert.Equal(1u, target.TargetManager.GetVoyeur(0).ObjectId);
        Assert.Equal(MotionCommand.WalkForward, m.CurrentCommand);
        Assert.Equal(HoldKey.Run, m.MovementParams.HoldKeyToApply);

        // Cylinders of radius 0.5 and 0.5: the gap is 10 - 1 - 0.475 k, at most 0.6 first at k = ceil(8.4 / 0.475) =
        // ceil(17.68) = 18 (y = 48.55, centre distance 1.45).
        SweepScene.Run(world, 17);
        Assert.True(player.IsMovingTo());
        SweepScene.Run(world, 1);
        Assert.False(player.IsMovingTo());
        Assert.Equal(40.0 + 18 * 0.475, player.Position.Frame.Origin.Y, 3);
        Assert.Equal(MotionError.None, m.LastResult);
        // CleanUp's clear_target: the player tracks nothing, the target has no voyeur.
        Assert.False(player.TargetManager.HasTarget);
        Assert.Equal(0, target.TargetManager.VoyeurCount);
    }

    [Fact]
    public void MoveToObject_FollowsATargetThatWalksAway()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        PhysicsObj target = Target(world, 100f, 50f);
        MovementManager.Of(target).DoMotion(MotionCommand.WalkForward, new MovementParameters { HoldKeyToApply = HoldKey.None });
        player.MoveToObject(2, new MovementParameters { WalkRunThreshold = 1f });
        MoveToManager m = mm.MoveToManager!;
        Assert.Equal(50f, m.CurrentTargetPosition.Frame.Origin.Y);

        // Without reports the player would stop 1.6 m (cylinders) short of y = 50: at y <= 48.4 + 0.475. The target walks
        // 0.156 m per step, 1.56 m per 0.5 s, so each voyeur pass (every 0.5 s of its physics time) sends a new report
        // (moved more than 0.5 m): the player's target moves on and the player follows.
        Position lastTarget = m.CurrentTargetPosition;
        int reports = 0;
        int ticks = 0;
        while (player.IsMovingTo() && ticks < 100)
        {
            lastTarget = m.CurrentTargetPosition;
            SweepScene.Run(world, 1);
            ticks++;
            if (player.IsMovingTo() && m.CurrentTargetPosition.Frame.Origin.Y != lastTarget.Frame.Origin.Y)
            {
                reports++;
                // Each report is the target's position when it was sent (quantum 0: no look-ahead), behind the live one.
                Assert.True(m.CurrentTargetPosition.Frame.Origin.Y <= target.Position.Frame.Origin.Y);
                Assert.True(m.CurrentTargetPosition.Frame.Origin.Y > lastTarget.Frame.Origin.Y + 0.5f);
            }
        }

        Assert.False(player.IsMovingTo());
        Assert.Equal(MotionError.None, m.LastResult);
        Assert.True(reports >= 2, $"reports {reports}");
        // Ended at the first step within 0.6 m (cylinders) of the last reported position.
        float gap = lastTarget.Frame.Origin.Y - player.Position.Frame.Origin.Y - 1f;
        Assert.InRange(gap, 0.6f - 0.475f, 0.6f);
        // It followed: past where it would have stopped for the first report.
        Assert.True(player.Position.Frame.Origin.Y > 48.4f + 0.475f + 1f);
        Assert.Equal(0, target.TargetManager!.VoyeurCount);
    }

    [Fact]
    public void MoveToObject_Sticky_SticksToTheTargetOnArrival_ForOneSecond()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        Target(world, 100f, 45f);
        var p = new MovementParameters { WalkRunThreshold = 1f };
        p.Flags |= MovementParameterFlags.Sticky;
        player.MoveToObject(2, p);
        // Gap 5 - 1 - 0.475 k <= 0.6 first at k = ceil(3.4 / 0.475) = 8.
        SweepScene.Run(world, 8);
        Assert.False(player.IsMovingTo());
        // BeginNextNode with the sticky bit: StickTo(top-level id 2, radius 0.5, height) (acclient.c:345520).
        Assert.Equal(2u, player.StickyObjectId);
        StickyManager sticky = player.PositionManager!.StickyManager!;
        Assert.Equal(0.5f, sticky.TargetRadius);
        // The stick's own set_target (radius 0.5, quantum 0.5): the report came at once, the stick is initialised.
        Assert.True(sticky.Initialized);
        Assert.Equal(0.5, player.TargetManager!.TargetInfo.Quantum);
        // A new move-to unsticks first (MoveToManager::PerformMovement).
        mm.TurnToHeading(new MovementParameters { DesiredHeading = 90f });
        Assert.Equal(0u, player.StickyObjectId);
    }

    [Fact]
    public void TurnToObject_FacesTheTarget()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        Target(world, 110f, 40f);   // due east: heading 90
        player.TurnToObject(2, new MovementParameters());
        MoveToManager m = mm.MoveToManager!;
        Assert.Equal(MovementType.TurnToObject, m.MovementType);
        Assert.True(m.Initialized);
        Assert.Equal(MotionCommand.TurnRight, m.CurrentCommand);
        // 90 / 4.2971835 = 20.94: done at step 21, heading set to exactly 90.
        SweepScene.Run(world, 20);
        Assert.True(player.IsMovingTo());
        SweepScene.Run(world, 1);
        Assert.False(player.IsMovingTo());
        Assert.Equal(90.0, player.Position.Frame.Heading, 4);
        Assert.Equal(100f, player.Position.Frame.Origin.X);
    }

    [Fact]
    public void MoveToObject_TargetLeavesTheWorld_CancelsWithObjectGone()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        PhysicsObj target = Target(world, 100f, 60f);
        player.MoveToObject(2, new MovementParameters());
        SweepScene.Run(world, 3);
        Assert.True(player.IsMovingTo());
        // exit_world: NotifyVoyeurOfEvent(ExitWorld) -> the (initialised) move-to cancels with 0x37.
        world.RemoveObject(target);
        Assert.False(player.IsMovingTo());
        Assert.Equal(MotionError.ObjectGone, mm.MoveToManager!.LastResult);
        Assert.False(player.TargetManager!.HasTarget);
    }

    [Fact]
    public void MoveToObject_UnknownTarget_TimesOutAfterTenSeconds_WithNoObject()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        // Through the movement manager (the id need not be in the world): set_target finds no object, so no report comes.
        mm.MoveToObject(42, 42, 0.5f, 1f, new MovementParameters());
        MoveToManager m = mm.MoveToManager!;
        Assert.True(player.IsMovingTo());
        Assert.False(m.Initialized);
        // UseTime does nothing until the first report (top-level id set, not initialised).
        SweepScene.Run(world, 20);
        Assert.Equal(40f, player.Position.Frame.Origin.Y);
        // HandleTargetting (every 0.5 s of physics time): status still Undefined and last update + 10 < now -> TimedOut ->
        // HandleUpdateTarget before initialisation with a status other than Ok -> CancelMoveTo(0x38).
        SweepScene.Run(world, 200);   // 11 s in all
        Assert.False(player.IsMovingTo());
        Assert.Equal(MotionError.NoObject, m.LastResult);
    }

    [Fact]
    public void MoveToObject_Itself_OnlyStops()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        player.MoveToObject(1, new MovementParameters());
        Assert.False(player.IsMovingTo());
        Assert.Null(player.TargetManager);
        SweepScene.Run(world, 3);
        Assert.Equal(40f, player.Position.Frame.Origin.Y);
    }
}
