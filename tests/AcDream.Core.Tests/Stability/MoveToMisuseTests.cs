using System;
using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>The move-to API refuses bad input with an ArgumentException before anything changes (no move-to manager is
/// created, no running move-to is cancelled), and every value it accepts leaves a world that ticks on.</summary>
public class MoveToMisuseTests
{
    public static TheoryData<string> BadParameters => new()
    {
        "default", "speed NaN", "speed +Inf", "speed 1e30", "speed -101", "distance NaN", "min -Inf", "fail NaN", "threshold +Inf", "heading NaN",
    };

    private static MovementParameters Bad(string which) => which switch
    {
        "default" => default,
        "speed NaN" => new MovementParameters { Speed = float.NaN },
        "speed +Inf" => new MovementParameters { Speed = float.PositiveInfinity },
        "speed 1e30" => new MovementParameters { Speed = 1e30f },
        "speed -101" => new MovementParameters { Speed = -101f },
        "distance NaN" => new MovementParameters { DistanceToObject = float.NaN },
        "min -Inf" => new MovementParameters { MinDistance = float.NegativeInfinity },
        "fail NaN" => new MovementParameters { FailDistance = float.NaN },
        "threshold +Inf" => new MovementParameters { WalkRunThreshold = float.PositiveInfinity },
        _ => new MovementParameters { DesiredHeading = float.NaN },
    };

    [Theory]
    [MemberData(nameof(BadParameters))]
    public void BadParameters_AreRefused_BeforeAnythingChanges(string which)
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        Target(world);
        MovementParameters p = Bad(which);
        Assert.Throws<ArgumentException>(() => mm.MoveToPosition(MoveToScene.At(100f, 60f), p));
        Assert.Throws<ArgumentException>(() => mm.MoveToObject(2, 2, 0.5f, 1f, p));
        Assert.Throws<ArgumentException>(() => mm.TurnToObject(2, 2, p));
        Assert.Throws<ArgumentException>(() => mm.TurnToHeading(p));
        Assert.Throws<ArgumentException>(() => player.MoveToObject(2, p));
        Assert.Throws<ArgumentException>(() => player.TurnToObject(2, p));
        Assert.Throws<ArgumentException>(() => player.TurnToHeading(p));
        Assert.Null(mm.MoveToManager);
        Assert.Null(player.TargetManager);

        // A running move-to is not cancelled by a refused one.
        mm.MoveToPosition(MoveToScene.At(100f, 60f), new MovementParameters());
        Assert.Throws<ArgumentException>(() => mm.MoveToPosition(MoveToScene.At(100f, 70f), p));
        Assert.True(player.IsMovingTo());
        Assert.Equal(60f, mm.MoveToManager!.CurrentTargetPosition.Frame.Origin.Y);
    }

    [Fact]
    public void BadTargets_AreRefused_BeforeAnythingChanges()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        Target(world);
        var p = new MovementParameters();
        Assert.Throws<ArgumentException>(() => mm.MoveToObject(0, 2, 0.5f, 1f, p));
        Assert.Throws<ArgumentException>(() => mm.MoveToObject(2, 0, 0.5f, 1f, p));
        Assert.Throws<ArgumentException>(() => mm.MoveToObject(2, 2, float.NaN, 1f, p));
        Assert.Throws<ArgumentException>(() => mm.MoveToObject(2, 2, -0.5f, 1f, p));
        Assert.Throws<ArgumentException>(() => mm.MoveToObject(2, 2, 0.5f, float.PositiveInfinity, p));
        Assert.Throws<ArgumentException>(() => mm.TurnToObject(0, 2, p));
        Assert.Throws<ArgumentException>(() => mm.MoveToPosition(new Position(MoveToScene.Cell, new Vector3(float.NaN, 0f, 0f)), p));
        Frame badQ = Frame.Identity;
        badQ.SetQuaternionRaw(2f, 0f, 0f, 0f);
        Assert.Throws<ArgumentException>(() => mm.MoveToPosition(new Position(MoveToScene.Cell, badQ), p));
        Assert.Null(mm.MoveToManager);
        Assert.Null(player.TargetManager);
    }

    [Fact]
    public void WrongState_IsInvalidOperation()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        MovementManager orphan = MovementManager.Create(null, null);
        Assert.Throws<InvalidOperationException>(() => orphan.TurnToHeading(new MovementParameters()));
        world.RemoveObject(player);
        Assert.Throws<InvalidOperationException>(() => mm.MoveToPosition(MoveToScene.At(100f, 60f), new MovementParameters()));
        Assert.Throws<InvalidOperationException>(() => player.MoveToObject(2, new MovementParameters()));
        Assert.Throws<InvalidOperationException>(() => player.TurnToHeading(new MovementParameters()));
        Assert.Throws<InvalidOperationException>(() => player.StopCompletely());
    }

    public static TheoryData<string> OddButAccepted => new()
    {
        "speed -1", "speed 100", "speed -100", "speed 0", "distance -5", "min 1e30", "fail 0", "threshold -1e30", "heading 1e30",
        "every flag", "no flag", "hold key 7",
    };

    [Theory]
    [MemberData(nameof(OddButAccepted))]
    public void OddValues_AreAccepted_AndTheWorldTicksOn(string which)
    {
        MovementParameters p = which switch
        {
            "speed -1" => new MovementParameters { Speed = -1f },
            "speed 100" => new MovementParameters { Speed = 100f },
            "speed -100" => new MovementParameters { Speed = -100f },
            "speed 0" => new MovementParameters { Speed = 0f },
            "distance -5" => new MovementParameters { DistanceToObject = -5f },
            "min 1e30" => new MovementParameters { MinDistance = 1e30f },
            "fail 0" => new MovementParameters { FailDistance = 0f },
            "threshold -1e30" => new MovementParameters { WalkRunThreshold = -1e30f },
            "heading 1e30" => new MovementParameters { DesiredHeading = 1e30f },
            "every flag" => new MovementParameters { Flags = (MovementParameterFlags)0xFFFFFFFFu },
            "no flag" => new MovementParameters { Flags = MovementParameterFlags.None },
            _ => new MovementParameters { HoldKeyToApply = (HoldKey)7 },
        };
        foreach (int kind in new[] { 6, 7, 8, 9 })
        {
            (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
            Target(world);
            switch (kind)
            {
                case 6: mm.MoveToObject(2, 2, 0.5f, 1f, p); break;
                case 7: mm.MoveToPosition(MoveToScene.At(100f, 60f), p); break;
                case 8: mm.TurnToObject(2, 2, p); break;
                default: mm.TurnToHeading(p); break;
            }

            SweepScene.Run(world, 60);
            Assert.True(InputLimits.IsPositionInDomain(player.Position), $"{which}, type {kind}: {player.Position}");
        }
    }

    [Fact]
    public void HandleUpdateTarget_OkReportWithABadPosition_IsRefused_BeforeTheMoveToActs()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer();
        mm.MoveToObject(42, 42, 0.5f, 1f, new MovementParameters());   // waiting for its first report
        var bad = new TargetInfo
        {
            ObjectId = 42, Status = TargetStatus.Ok, TargetPosition = MoveToScene.At(100f, 60f),
            InterpolatedPosition = new Position(MoveToScene.Cell, new Vector3(1000f, 0f, 20f)),   // outdoor x beyond 384
        };
        Assert.Throws<ArgumentException>(() => player.HandleUpdateTarget(bad));
        Assert.False(mm.MoveToManager!.Initialized);
        Assert.Equal(0, mm.MoveToManager.PendingActionCount);
        // A good report plans the move.
        bad.InterpolatedPosition = bad.TargetPosition;
        player.HandleUpdateTarget(bad);
        Assert.True(mm.MoveToManager.Initialized);
        Assert.Equal(MotionCommand.WalkForward, mm.MoveToManager.CurrentCommand);
        _ = world;
    }

    private static PhysicsObj Target(PhysicsWorld world) =>
        MoveToScene.Creature(world, 2, RemoteCreatureWeenie.Creature, new Vector3(100f, 50f, 20f));
}
