using System;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;
using AcDream.Core.Physics.Motion.MoveTo;

namespace AcDream.Core.Tests.Behavior;

// MoveToManager on flat ground (MoveToScene): the player at (100, 40, 20) facing north, radius 0.5, run 9.5 m/s (0.475 m per
// step), walk 3.12 m/s (0.156 m per step), turn 4.2971835° per step. A position target has radius 0 and the default
// parameters measure between cylinders (UseSpheres), so the move ends at the first step whose centre distance is at most
// 0.6 + 0.5 = 1.1 m. The move-to runs in the step's UseTime, after the step moved the body.
public class MoveToPositionSceneTests
{
    [Fact]
    public void MoveToPosition_Runs_AndStopsAtTheFirstStepWithinDistanceToObject()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        // 20 m north, already faced (heading error 0): the turn node ends at once and the run starts at the call.
        // get_command: 19.5 - 0.6 = 18.9 > 15 (threshold) -> hold key Run.
        mm.MoveToPosition(MoveToScene.At(100f, 60f), new MovementParameters());
        MoveToManager m = mm.MoveToManager!;
        Assert.Equal(MovementType.MoveToPosition, m.MovementType);
        Assert.Equal(MotionCommand.WalkForward, m.CurrentCommand);
        Assert.Equal(HoldKey.Run, m.MovementParams.HoldKeyToApply);
        Assert.Equal(1, m.PendingActionCount);
        Assert.Equal(MotionCommand.RunForward, mm.GetOrCreateMotionInterpreter().InterpretedState.ForwardCommand);

        // y_k = 40 + 0.475 k; within 1.1 of 60 first at k = ceil(18.9 / 0.475) = ceil(39.79) = 40 (y = 59.0).
        SweepScene.Run(world, 39);
        Assert.True(player.IsMovingTo());
        Assert.Equal(40.0 + 39 * 0.475, player.Position.Frame.Origin.Y, 3);
        SweepScene.Run(world, 1);
        Assert.False(player.IsMovingTo());
        Assert.Equal(59.0, player.Position.Frame.Origin.Y, 3);
        Assert.Equal(MotionError.None, m.LastResult);
        Assert.Equal(0, m.PendingActionCount);
        // Stopped completely: Ready, and the body stays.
        Assert.Equal(MotionCommand.Ready, mm.GetOrCreateMotionInterpreter().InterpretedState.ForwardCommand);
        float y = player.Position.Frame.Origin.Y;
        SweepScene.Run(world, 10);
        Assert.Equal(y, player.Position.Frame.Origin.Y);
        Assert.Equal(0f, player.Position.Frame.Origin.X - 100f, 4);
    }

    [Theory]
    // 10 m north: cylinder distance 9.5, 9.5 - 0.6 = 8.9. Threshold 15: 8.9 <= 15 -> walk, 0.156 m per step: within 1.1 m
    // first at k = ceil(8.9 / 0.156) = ceil(57.05) = 58 (y = 49.048). Threshold 1 (the melee approach's): 8.9 > 1 -> run:
    // k = ceil(8.9 / 0.475) = ceil(18.74) = 19 (y = 49.025).
    [InlineData(15f, HoldKey.None, MotionCommand.WalkForward, 58, 0.156)]
    [InlineData(1f, HoldKey.Run, MotionCommand.RunForward, 19, 0.475)]
    public void MoveToPosition_WalksOrRuns_ByTheWalkRunThreshold(float threshold, HoldKey key, MotionCommand played, int steps,
        double perStep)
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        mm.MoveToPosition(MoveToScene.At(100f, 50f), new MovementParameters { WalkRunThreshold = threshold });
        MoveToManager m = mm.MoveToManager!;
        Assert.Equal(key, m.MovementParams.HoldKeyToApply);
        Assert.Equal(played, mm.GetOrCreateMotionInterpreter().InterpretedState.ForwardCommand);
        SweepScene.Run(world, steps - 1);
        Assert.True(player.IsMovingTo());
        SweepScene.Run(world, 1);
        Assert.False(player.IsMovingTo());
        Assert.Equal(40.0 + steps * perStep, player.Position.Frame.Origin.Y, 3);
    }

    [Fact]
    public void MoveToPosition_TurnsFirst_ThenMoves_WhenTheTargetIsOffToTheSide()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        // 20 m east: heading error 90 -> nodes [turn to 90, move]; heading_diff(90, 0, right) = 90 <= 180 -> TurnRight.
        mm.MoveToPosition(MoveToScene.At(120f, 40f), new MovementParameters());
        MoveToManager m = mm.MoveToManager!;
        Assert.Equal(2, m.PendingActionCount);
        Assert.Equal(MotionCommand.TurnRight, m.CurrentCommand);
        // 20 steps: 20 × 4.2971835 = 85.94367° (< 90, still turning, not moved).
        SweepScene.Run(world, 20);
        Assert.Equal(20 * MoveToScene.TurnStepDegrees, player.Position.Frame.Heading, 3);
        Assert.Equal(MotionCommand.TurnRight, m.CurrentCommand);
        Assert.Equal(100f, player.Position.Frame.Origin.X);
        // Step 21 passes 90 (90.24): heading_greater -> the heading is set to exactly 90, the turn node ends and the run
        // starts (in that step's UseTime: the body has not moved yet).
        SweepScene.Run(world, 1);
        Assert.Equal(90.0, player.Position.Frame.Heading, 4);
        Assert.Equal(MotionCommand.WalkForward, m.CurrentCommand);
        Assert.Equal(1, m.PendingActionCount);
        Assert.Equal(100f, player.Position.Frame.Origin.X);
        // Then as the straight run: 40 steps of 0.475 m to x = 119.0.
        SweepScene.Run(world, 39);
        Assert.True(player.IsMovingTo());
        SweepScene.Run(world, 1);
        Assert.False(player.IsMovingTo());
        Assert.Equal(119.0, player.Position.Frame.Origin.X, 3);
        Assert.Equal(40f, player.Position.Frame.Origin.Y, 3);
    }

    [Fact]
    public void MoveToPosition_UseFinalHeading_TurnsToTheDesiredHeadingAtTheEnd()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        var p = new MovementParameters { DesiredHeading = 180f };
        p.Flags |= MovementParameterFlags.UseFinalHeading;
        // Nodes: [turn 0, move, turn 180]; the first turn ends at the call. The run takes 40 steps (as above). Its stop queues
        // a Ready, so BeginTurnToHeading waits (motions_pending) until the step after, when the part array has reported it:
        // the turn starts in step 41's UseTime. heading_diff(180, 0, right) = 180 <= 180 -> TurnRight, with the move-to's hold
        // key, Run since the run (BeginMoveForward stored it): apply_run_to_command makes the turn 1.5 times faster, 6.4457752°
        // per step; 180 / 6.4457752 = 27.93 -> heading_greater(h, 180) first after 28 turning steps, steps 42..69.
        mm.MoveToPosition(MoveToScene.At(100f, 60f), p);
        Assert.Equal(2, mm.MoveToManager!.PendingActionCount);
        SweepScene.Run(world, 40);
        Assert.True(player.IsMovingTo());
        Assert.Equal((MotionCommand)0, mm.MoveToManager.CurrentCommand);
        Assert.Equal(1, mm.MoveToManager.PendingActionCount);
        SweepScene.Run(world, 1);
        Assert.Equal(MotionCommand.TurnRight, mm.MoveToManager.CurrentCommand);
        Assert.Equal(HoldKey.Run, mm.MoveToManager.MovementParams.HoldKeyToApply);
        SweepScene.Run(world, 27);
        Assert.True(player.IsMovingTo());
        Assert.Equal(27 * 1.5 * MoveToScene.TurnStepDegrees, player.Position.Frame.Heading, 3);
        SweepScene.Run(world, 1);
        Assert.False(player.IsMovingTo());
        Assert.Equal(180.0, player.Position.Frame.Heading, 4);
        Assert.Equal(59.0, player.Position.Frame.Origin.Y, 3);
    }

    [Fact]
    public void TurnToHeading_TurnsLeftTheShortWay_AndEndsExactlyAtTheHeading()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        // From 0 to 270: heading_diff(270, 0, right) = 270 > 180 -> TurnLeft (speed -1 after adjust_motion).
        mm.TurnToHeading(new MovementParameters { DesiredHeading = 270f });
        MoveToManager m = mm.MoveToManager!;
        Assert.Equal(MovementType.TurnToHeading, m.MovementType);
        Assert.Equal(MotionCommand.TurnLeft, m.CurrentCommand);
        // heading_k = 360 - 4.2971835 k; heading_greater(h, 270, left) = h <= 270 first at k = ceil(90 / 4.297) = 21.
        SweepScene.Run(world, 20);
        Assert.Equal(360.0 - 20 * MoveToScene.TurnStepDegrees, player.Position.Frame.Heading, 3);
        Assert.True(player.IsMovingTo());
        Assert.Equal(0u, m.FailProgressCount);
        SweepScene.Run(world, 1);
        Assert.False(player.IsMovingTo());
        Assert.Equal(270.0, player.Position.Frame.Heading, 4);
        SweepScene.Run(world, 5);
        Assert.Equal(270.0, player.Position.Frame.Heading, 4);
        Assert.Equal(100f, player.Position.Frame.Origin.X);
        Assert.Equal(40f, player.Position.Frame.Origin.Y);
    }

    [Fact]
    public void MoveToPosition_BeyondTheFailDistance_CancelsWithYouChargedTooFar()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        // Fail distance 5 m from the start: 0.475 k > 5 first at k = 11 (5.225 m), before any arrival (19.5 m away) and
        // before the first progress check (t = 0.55 s < 1 s).
        mm.MoveToPosition(MoveToScene.At(100f, 60f), new MovementParameters { FailDistance = 5f });
        SweepScene.Run(world, 10);
        Assert.True(player.IsMovingTo());
        SweepScene.Run(world, 1);
        Assert.False(player.IsMovingTo());
        Assert.Equal(MotionError.YouChargedTooFar, mm.MoveToManager!.LastResult);
        Assert.Equal(0x3Du, (uint)mm.MoveToManager.LastResult);
        Assert.Equal(40.0 + 11 * 0.475, player.Position.Frame.Origin.Y, 3);
        float y = player.Position.Frame.Origin.Y;
        SweepScene.Run(world, 5);
        Assert.Equal(y, player.Position.Frame.Origin.Y);
    }

    [Fact]
    public void StopCompletely_CancelsTheMoveTo_WithActionCancelled()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        mm.MoveToPosition(MoveToScene.At(100f, 60f), new MovementParameters());
        SweepScene.Run(world, 5);
        // CMotionInterp::StopCompletely calls cancel_moveto -> CancelMoveTo(0x36).
        player.StopCompletely();
        MoveToManager m = mm.MoveToManager!;
        Assert.False(player.IsMovingTo());
        Assert.Equal(MotionError.ActionCancelled, m.LastResult);
        Assert.Equal(0, m.PendingActionCount);
        Assert.Equal((MotionCommand)0, m.CurrentCommand);
        float y = player.Position.Frame.Origin.Y;
        Assert.Equal(40.0 + 5 * 0.475, y, 3);
        SweepScene.Run(world, 5);
        Assert.Equal(y, player.Position.Frame.Origin.Y);
    }

    [Fact]
    public void PlayerCommand_WithCancelMoveTo_CancelsTheMoveTo_AndTeleportCancelsWithITeleported()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        mm.MoveToPosition(MoveToScene.At(100f, 60f), new MovementParameters());
        SweepScene.Run(world, 3);
        // DoMotion with retail's default parameters carries CancelMoveTo (0x8000): cancel_moveto first.
        Assert.Equal(MotionError.None, mm.DoMotion(MotionCommand.WalkForward, new MovementParameters()));
        Assert.False(player.IsMovingTo());
        Assert.Equal(MotionError.ActionCancelled, mm.MoveToManager!.LastResult);

        mm.MoveToPosition(MoveToScene.At(100f, 80f), new MovementParameters());
        Assert.True(player.IsMovingTo());
        player.TeleportHook();
        Assert.False(player.IsMovingTo());
        Assert.Equal(MotionError.ITeleported, mm.MoveToManager.LastResult);
    }

    [Fact]
    public void HitGround_RestartsTheCurrentStep()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        mm.MoveToPosition(MoveToScene.At(100f, 60f), new MovementParameters());
        SweepScene.Run(world, 10);
        MoveToManager m = mm.MoveToManager!;
        Assert.Equal(19.5f, m.OriginalDistance, 4);
        // MoveToManager::HitGround -> BeginNextNode -> BeginMoveForward: the run is played again and the progress
        // bookkeeping restarts from the current distance (19.5 - 10 × 0.475 = 14.75).
        ((AcDream.Core.Physics.Objects.Seams.IMovementManager)mm).HitGround();
        Assert.True(player.IsMovingTo());
        Assert.Equal(MotionCommand.WalkForward, m.CurrentCommand);
        Assert.Equal(14.75f, m.OriginalDistance, 3);
        Assert.Equal(m.OriginalDistance, m.PreviousDistance);
        Assert.Equal(world.CurrentTime, m.OriginalDistanceTime);
    }

    [Fact]
    public void NoProgress_CountsFailedChecks_AfterOneSecond_AndKeepsGoing()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        // Speed 0: the run plays at 0 m/s. CheckProgressMade passes while now - start <= 1 s; after that every step fails
        // (closing rate 0 < 0.25 m/s, and the last-check time is not advanced by a failing check): one count per step.
        double start = world.CurrentTime;
        mm.MoveToPosition(MoveToScene.At(100f, 60f), new MovementParameters { Speed = 0f });
        MoveToManager m = mm.MoveToManager!;
        int expected = 0;
        double t = start;
        for (int k = 1; k <= 30; k++)
        {
            t += SweepScene.Dt;   // the clock SweepScene.Run advances, summed the same way
            if (t - start > MoveToManager.ProgressCheckInterval)
            {
                expected++;
            }
        }

        SweepScene.Run(world, 30);
        Assert.InRange(expected, 9, 11);   // 30 steps, the first ~20 within the first second
        Assert.Equal((uint)expected, m.FailProgressCount);
        Assert.True(player.IsMovingTo());   // retail gives up on nothing by it
        Assert.Equal(40f, player.Position.Frame.Origin.Y);
    }
}
