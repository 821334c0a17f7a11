using System.Numerics;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Allocation;

/// <summary>A running move-to allocates nothing per step: the pending steps are a pooled ring, the target reports are
/// structs, the voyeur entries are pooled.</summary>
public class MoveToAllocationTests
{
    [Fact]
    public void MoveToObjectChase_AfterWarmUp_AllocatesZeroBytes()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer(100f, 10f);
        PhysicsObj target = MoveToScene.Creature(world, 2, RemoteCreatureWeenie.Creature, new Vector3(100f, 30f, 20f));
        MovementManager.Of(target).DoMotion(MotionCommand.WalkForward, new MovementParameters { HoldKeyToApply = HoldKey.None });
        // Both walk at 3.12 m/s (the player may not run): the gap stays, the chase and its 0.5 s reports go on.
        var p = new MovementParameters();
        p.Flags &= ~MovementParameterFlags.CanRun;
        player.MoveToObject(2, p);
        SweepScene.Run(world, 40);
        Assert.True(player.IsMovingTo());
        AllocationProbe.AssertSteadyStateAllocatesNothing(() => SweepScene.Run(world, 30));
        Assert.True(player.IsMovingTo());
        Assert.Equal(1, target.TargetManager!.VoyeurCount);
    }

    [Fact]
    public void RepeatedMoveToPosition_AfterWarmUp_AllocatesZeroBytes()
    {
        (PhysicsWorld world, PhysicsObj player, MovementManager mm) = MoveToScene.WithPlayer(100f, 40f);
        var there = MoveToScene.At(110f, 50f);
        var back = MoveToScene.At(100f, 40f);
        var p = new MovementParameters();
        p.Flags |= MovementParameterFlags.UseFinalHeading;
        void Cycle()
        {
            mm.MoveToPosition(there, p);
            SweepScene.Run(world, 60);
            mm.MoveToPosition(back, p);
            SweepScene.Run(world, 60);
        }

        Cycle();
        AllocationProbe.AssertSteadyStateAllocatesNothing(Cycle);
    }
}
