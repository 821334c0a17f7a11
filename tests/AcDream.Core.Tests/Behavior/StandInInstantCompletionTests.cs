using System.Numerics;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

// Issue #25 item 5: what the stand-in motion table's instant completion hides. Retail's CMotionInterp::DoInterpretedMotion
// (acclient.c:343974) queues every started motion with a jump error (343996-344004): 0x48 when the parameters disable
// jumping during the link, else motion_allows_jump(motion), else (not an action) motion_allows_jump(the current forward
// command). jump_is_allowed (343921) refuses with the error of the oldest unfinished node, and the node goes only when
// the motion table reports the motion done (MotionDone, 343640, from CheckForCompletedMotions). With a real table, standing
// up from sitting (DoMotion(Ready) while the forward command is Sitting: node error 0x48) is unfinished until the stand-up
// link animation ends, so a jump is refused (0x48) for that whole time; and DoMotion refuses a seventh action while six
// are queued (TooManyActions 0x45, CMotionInterp::DoMotion). The stand-in (SpeedOnlyMotionPlayer) completes every motion
// at once, so both last only until the next tick's CheckForCompletedMotions. These tests pin the stand-in's behaviour;
// with the real motion table the jump right after standing up and the action after six must be refused for the length
// of the animations. (MovementManager::PerformMovement takes the finished motions right after each command, so with the
// stand-in they never outlive the call.)
public class StandInInstantCompletionTests
{
    private static (PhysicsWorld World, PhysicsObj Player, MovementManager Mm) Player()
    {
        var terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        PhysicsObj obj = world.CreateObject(1);
        obj.Weenie = new PlayerWeenie { JumpSkill = 100 };
        var parts = Walkers.OneSphere();
        parts.MotionPlayer = new SpeedOnlyMotionPlayer();
        obj.PartArray = parts;
        Assert.True(obj.EnterWorld(new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4), new Vector3(100f, 100f, 20f))));
        world.Player = obj;
        MovementManager mm = MovementManager.Of(obj);
        SweepScene.Run(world, 2);
        return (world, obj, mm);
    }

    [Fact]
    public void JumpRightAfterStandingUp_IsAllowedAtOnce_WithTheStandIn()
    {
        var (world, _, mm) = Player();
        MotionInterp mi = mm.GetOrCreateMotionInterpreter();
        Assert.Equal(MotionError.None, mm.DoMotion(MotionCommand.Sitting, new MovementParameters()));
        SweepScene.Run(world, 1);
        Assert.Equal(MotionError.YouCantJumpFromThisPosition, mi.JumpIsAllowed(0.5f, out _));   // sitting (jump_charge_is_allowed)

        // Stand up through the movement manager, as a client does: MovementManager::PerformMovement takes the finished
        // motions right after the command, and the stand-in has finished it, so nothing is pending and the jump goes.
        // Retail with the real humanoid table would be playing the Sitting -> Ready link here and answer 0x48.
        Assert.Equal(MotionError.None, mm.DoMotion(MotionCommand.Ready, new MovementParameters()));
        Assert.Equal(0, mi.PendingMotions.Count);
        Assert.Equal(MotionError.None, mi.Jump(0.5f, out _));
    }

    [Fact]
    public void WhileTheStandUpIsPending_TheJumpIsRefused0x48_AsRetailDoesForTheWholeLink()
    {
        var (world, _, mm) = Player();
        MotionInterp mi = mm.GetOrCreateMotionInterpreter();
        Assert.Equal(MotionError.None, mi.DoMotion(MotionCommand.Sitting, new MovementParameters()));
        SweepScene.Run(world, 1);
        Assert.Equal(0, mi.PendingMotions.Count);

        // The interpreter alone (no completion check yet): the node for Ready carries motion_allows_jump(Sitting) = 0x48,
        // because the forward command is still Sitting when DoInterpretedMotion queues it; jump_is_allowed answers it.
        Assert.Equal(MotionError.None, mi.DoMotion(MotionCommand.Ready, new MovementParameters()));
        Assert.Equal(1, mi.PendingMotions.Count);
        Assert.Equal(MotionError.YouCantJumpFromThisPosition, mi.PendingMotions.Head.JumpErrorCode);
        Assert.Equal(MotionError.YouCantJumpFromThisPosition, mi.JumpIsAllowed(0.5f, out _));

        // The next tick takes the stand-in's completion: the node goes and the jump is allowed.
        SweepScene.Run(world, 1);
        Assert.Equal(0, mi.PendingMotions.Count);
        Assert.Equal(MotionError.None, mi.JumpIsAllowed(0.5f, out _));
    }

    [Fact]
    public void SixQueuedActions_RefuseTheSeventh_OnlyUntilTheStandInReportsThemDone()
    {
        var (world, _, mm) = Player();
        MotionInterp mi = mm.GetOrCreateMotionInterpreter();
        var action = (MotionCommand)0x10000079u;   // an action (0x10000000 class) motion_allows_jump allows

        // Through the movement manager each action is finished at once: seven in a row all start.
        for (int i = 0; i < 7; i++)
        {
            Assert.Equal(MotionError.None, mm.DoMotion(action, new MovementParameters()));
        }

        Assert.Equal(0, mi.PendingMotions.Count);

        // Unfinished (the interpreter alone, as with a real table while the animations play): six queued, the seventh is
        // TooManyActions (0x45, CMotionInterp::DoMotion's GetNumActions() >= 6).
        for (int i = 0; i < 6; i++)
        {
            Assert.Equal(MotionError.None, mi.DoMotion(action, new MovementParameters()));
        }

        Assert.Equal(MotionError.TooManyActions, mi.DoMotion(action, new MovementParameters()));
        SweepScene.Run(world, 1);
        Assert.Equal(0, mi.PendingMotions.Count);
        Assert.Equal(MotionError.None, mi.DoMotion(action, new MovementParameters()));
    }
}
