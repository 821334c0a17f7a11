using System.Numerics;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

// jump, charge_jump, jump_is_allowed, get_jump_v_z, get_leave_ground_velocity, HitGround and LeaveGround, on objects with
// retail's default state (GRAVITY set).
public class MotionInterpJumpTests
{
    [Fact]
    public void JumpIsAllowed_OnTheGround_NotInTheAir()
    {
        var (obj, _, mi, _) = MotionFixture.Create(new PlayerWeenie { JumpSkill = 100 }, gravity: true);
        // Created in the air (no CONTACT): 0x24.
        Assert.Equal(MotionError.YouCantJumpWhileInTheAir, mi.JumpIsAllowed(1f, out _));
        MotionFixture.SetOnGround(obj);
        // On the ground, standing: allowed, cost ceil((0 + 0.5) * 1 * 8 + 2) = 6.
        Assert.Equal(MotionError.None, mi.JumpIsAllowed(1f, out int cost));
        Assert.Equal(6, cost);
    }

    [Fact]
    public void JumpIsAllowed_RefusedSittingAndLoadedDown()
    {
        var w = new PlayerWeenie { JumpSkill = 100 };
        var (obj, _, mi, _) = MotionFixture.Create(w, gravity: true);
        MotionFixture.SetOnGround(obj);
        mi.InterpretedState.ForwardCommand = MotionCommand.Sitting;
        Assert.Equal(MotionError.YouCantJumpFromThisPosition, mi.JumpIsAllowed(1f, out _));
        mi.InterpretedState.ForwardCommand = MotionCommand.Ready;
        w.Burden = 3000;   // load 2: CanJump refuses -> 0x49
        Assert.Equal(MotionError.CantJumpLoadedDown, mi.JumpIsAllowed(1f, out _));
    }

    [Theory]
    // get_jump_v_z: extent below EPSILON -> 0 (the weenie is not asked); else sqrt(h * 19.6) of the clamped extent
    // (values worked in MovementSystemTests: skill 100 -> 4.003748 at 0.5, 5.662155 at 1; skill 300 -> 6.425146, 9.086529).
    [InlineData(100, 0f, 0.0)]
    [InlineData(100, 0.5f, 4.003748)]
    [InlineData(100, 1f, 5.662155)]
    [InlineData(300, 0f, 0.0)]
    [InlineData(300, 0.5f, 6.425146)]
    [InlineData(300, 1f, 9.086529)]
    public void JumpVelocityZ_ForExtentAndSkill(int skill, float extent, double expected)
    {
        var (_, _, mi, _) = MotionFixture.Create(new PlayerWeenie { JumpSkill = skill }, gravity: true);
        mi.JumpExtent = extent;
        Assert.Equal(expected, mi.JumpVelocityZ, 5);
    }

    [Fact]
    public void JumpVelocityZ_NoWeenie_Is10()
    {
        var (_, _, mi, _) = MotionFixture.Create(null, gravity: true);
        mi.JumpExtent = 0.5f;
        Assert.Equal(10.0, mi.JumpVelocityZ);
    }

    [Fact]
    public void Jump_LeavesTheGround_WithStateVelocityAndVz_ThenLandingEndsIt()
    {
        var (obj, mm, mi, table) = MotionFixture.Create(new PlayerWeenie { RunSkill = 200, JumpSkill = 300 }, gravity: true);
        MotionFixture.SetOnGround(obj);
        mm.DoMotion(MotionCommand.WalkForward, MotionFixture.Params(1f, HoldKey.Run));
        Assert.Equal(9.5f, table.Velocity.Y);

        // jump(1): allowed, extent recorded, set_on_walkable(0) -> LeaveGround: local velocity = state velocity (0, 9.5, 0)
        // with z = get_jump_v_z = 9.086529; then the extent is cleared and the table plays Falling.
        Assert.Equal(MotionError.None, mi.Jump(1f, out int cost));
        Assert.Equal(6, cost);
        Assert.Equal(0f, mi.JumpExtent);
        Assert.Equal(9.5f, obj.Velocity.Y);
        Assert.Equal(9.086529, obj.Velocity.Z, 5);
        Assert.Equal(MotionCommand.Falling, table.Substate);
        Assert.Equal(MotionCommand.RunForward, mi.InterpretedState.ForwardCommand);  // still the commanded motion

        // Landing (set_on_walkable(1) -> HitGround) re-applies the movement: the run plays again.
        obj.SetOnWalkable(true);
        Assert.Equal(MotionCommand.RunForward, table.Substate);
        Assert.Equal(9.5f, table.Velocity.Y);
        // In the air a second jump is refused.
        obj.SetOnWalkable(false);
        Assert.Equal(MotionError.YouCantJumpWhileInTheAir, mi.Jump(1f, out _));
    }

    [Fact]
    public void ChargeJump_StandingStill_StartsAStandingLongJump_WhichHoldsTheWalk()
    {
        var (obj, mm, mi, table) = MotionFixture.Create(new PlayerWeenie { RunSkill = 200, JumpSkill = 300 }, gravity: true);
        MotionFixture.SetOnGround(obj);
        Assert.Equal(MotionError.None, mi.ChargeJump());
        Assert.True(mi.StandingLongJump);
        // While charging, a walk is recorded but not played (DoInterpretedMotion's standing_longjump branch).
        mm.DoMotion(MotionCommand.WalkForward, MotionFixture.Params());
        Assert.Equal(MotionCommand.WalkForward, mi.InterpretedState.ForwardCommand);
        Assert.Equal(Vector3.Zero, table.Velocity);
        // The jump launches with the recorded walk: (0, 3.12, vz(0.5) = 6.42515), and ends the long jump.
        Assert.Equal(MotionError.None, mi.Jump(0.5f, out _));
        Assert.False(mi.StandingLongJump);
        Assert.Equal(3.12f, obj.Velocity.Y);
        Assert.Equal(6.425146, obj.Velocity.Z, 5);
    }

    [Fact]
    public void LeaveGround_NothingCommanded_KeepsTheObjectsVelocity()
    {
        // get_leave_ground_velocity: all of x, y, vz below EPSILON -> the current velocity in local axes.
        var (obj, _, mi, _) = MotionFixture.Create(new PlayerWeenie(), gravity: true);
        MotionFixture.SetOnGround(obj);
        obj.SetVelocity(new Vector3(1f, 2f, 0f));
        Assert.Equal(new Vector3(1f, 2f, 0f), mi.LeaveGroundVelocity);
        obj.SetOnWalkable(false);
        Assert.Equal(new Vector3(1f, 2f, 0f), obj.Velocity);
    }

    [Fact]
    public void MotionAllowsJump_Table()
    {
        // motion_allows_jump (acclient.c:343294): 0x48 for the postures and poses, 0 otherwise.
        Assert.Equal(MotionError.None, MotionInterp.MotionAllowsJump(MotionCommand.Ready));
        Assert.Equal(MotionError.None, MotionInterp.MotionAllowsJump(MotionCommand.RunForward));
        Assert.Equal(MotionError.None, MotionInterp.MotionAllowsJump(MotionCommand.Falling));
        Assert.Equal(MotionError.YouCantJumpFromThisPosition, MotionInterp.MotionAllowsJump(MotionCommand.Fallen));
        Assert.Equal(MotionError.YouCantJumpFromThisPosition, MotionInterp.MotionAllowsJump(MotionCommand.Crouch));
        Assert.Equal(MotionError.YouCantJumpFromThisPosition, MotionInterp.MotionAllowsJump(MotionCommand.Sleeping));
        Assert.Equal(MotionError.None, MotionInterp.MotionAllowsJump((MotionCommand)0x41000015u));
        Assert.Equal(MotionError.YouCantJumpFromThisPosition, MotionInterp.MotionAllowsJump((MotionCommand)0x40000016u));
        Assert.Equal(MotionError.YouCantJumpFromThisPosition, MotionInterp.MotionAllowsJump((MotionCommand)0x4000001Eu));
        Assert.Equal(MotionError.YouCantJumpFromThisPosition, MotionInterp.MotionAllowsJump((MotionCommand)0x40000039u));
        Assert.Equal(MotionError.None, MotionInterp.MotionAllowsJump((MotionCommand)0x4000003Au));
        Assert.Equal(MotionError.YouCantJumpFromThisPosition, MotionInterp.MotionAllowsJump((MotionCommand)0x1000006Fu));
        Assert.Equal(MotionError.YouCantJumpFromThisPosition, MotionInterp.MotionAllowsJump((MotionCommand)0x10000131u));
        Assert.Equal(MotionError.None, MotionInterp.MotionAllowsJump((MotionCommand)0x10000079u));
    }

    [Fact]
    public void ContactAllowsMove_InTheAir_OnlyTurnsFallingAndDead()
    {
        var (obj, _, mi, _) = MotionFixture.Create(new PlayerWeenie(), gravity: true);
        Assert.False(mi.ContactAllowsMove(MotionCommand.WalkForward));
        Assert.True(mi.ContactAllowsMove(MotionCommand.TurnRight));
        Assert.True(mi.ContactAllowsMove(MotionCommand.TurnLeft));
        Assert.True(mi.ContactAllowsMove(MotionCommand.Falling));
        Assert.True(mi.ContactAllowsMove(MotionCommand.Dead));
        Assert.False(mi.ContactAllowsMove(MotionCommand.SideStepRight));
        MotionFixture.SetOnGround(obj);
        Assert.True(mi.ContactAllowsMove(MotionCommand.WalkForward));
        Assert.Equal(TransientState.Contact | TransientState.OnWalkable,
            obj.TransientState & (TransientState.Contact | TransientState.OnWalkable));
    }
}
