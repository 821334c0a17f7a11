using System;
using System.Reflection;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.World;
using Xunit;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// The motion API reads at sight (issue #23): commands and errors print by name, the engine's callbacks are not on the public
/// surface, and reading the motion interpreter creates nothing.
/// </summary>
public sealed class MotionNamesTests
{
    [Fact]
    public void MovementEventHeader_PrintsItsStyleByName_AndAnUnnamedCommandInHex()
    {
        // NonCombat is 0x8000003D (command_ids[0x3D]); 0x8000003C (command_ids[0x3C]) has no name here.
        var named = new MovementEventHeader(0, MotionCommand.NonCombat, 0x50000001u, false);
        Assert.Equal("MovementEventHeader { MovementType = 0, Style = NonCombat, StickToObject = 0x50000001, StandingLongJump = False }",
            named.ToString());
        var unnamed = named with { Style = (MotionCommand)0x8000003Cu };
        Assert.Contains("Style = 0x8000003C,", unnamed.ToString());
    }

    [Fact]
    public void MotionRecordsAndStates_PrintCommandsByName()
    {
        Assert.Equal("ActionNode { Action = 0x10000057, Speed = 1.5, Stamp = 3, Autonomous = True }",
            new ActionNode((MotionCommand)0x10000057u, 1.5f, 3, true).ToString());
        Assert.Equal("MotionNode { ContextId = 0, Motion = Ready, JumpErrorCode = YouCantJumpFromThisPosition }",
            new MotionNode(0, MotionCommand.Ready, MotionError.YouCantJumpFromThisPosition).ToString());
        Assert.Equal("InterpretedMotionState { CurrentStyle = NonCombat, ForwardCommand = Ready, ForwardSpeed = 1, "
                     + "SidestepCommand = None, SidestepSpeed = 1, TurnCommand = None, TurnSpeed = 1, Actions = 0 }",
            new InterpretedMotionState().ToString());
        Assert.Equal("RawMotionState { CurrentHoldKey = None, CurrentStyle = NonCombat, ForwardCommand = Ready, ForwardSpeed = 1, "
                     + "SidestepCommand = None, SidestepSpeed = 1, TurnCommand = None, TurnSpeed = 1, Actions = 0 }",
            new RawMotionState().ToString());
    }

    [Fact]
    public void MovementParameters_PrintTheirFieldsByName()
    {
        // Retail's defaults (acclient.c:339436): flags 0x1EE0F = 0xF (walk, run, side-step, backwards) | 0x200 (towards) |
        // 0x400 (spheres) | 0x800 (set hold key) | 0x2000 | 0x4000 (modify raw, interpreted) | 0x8000 (cancel move-to) |
        // 0x10000 (stop completely); speed 1, hold key Invalid, distance to object 0.6 (0.6f prints as 0.6).
        string text = new MovementParameters().ToString();
        Assert.StartsWith("MovementParameters { Flags = CanWalk, CanRun, CanSidestep, CanWalkBackwards, MoveTowards, UseSpheres, "
                          + "SetHoldKey, ModifyRawState, ModifyInterpretedState, CancelMoveTo, StopCompletely, Speed = 1, "
                          + "HoldKeyToApply = Invalid, DistanceToObject = 0.6, ", text);
    }

    [Fact]
    public void CommandIds_GiveTheEnumsMembers()
    {
        Assert.True(MotionCommandIds.TryGet(0x3D, out MotionCommand style));
        Assert.Equal(MotionCommand.NonCombat, style);
        Assert.True(MotionCommandIds.TryGet(5, out MotionCommand walk));
        Assert.Equal(MotionCommand.WalkForward, walk);
        Assert.Equal("YouCantJumpWhileInTheAir", MotionError.YouCantJumpWhileInTheAir.ToString());
    }

    [Theory]
    [InlineData(typeof(MovementManager), "HitGround")]
    [InlineData(typeof(MovementManager), "LeaveGround")]
    [InlineData(typeof(MovementManager), "UseTime")]
    [InlineData(typeof(MovementManager), "MotionDone")]
    [InlineData(typeof(MovementManager), "HandleEnterWorld")]
    [InlineData(typeof(MovementManager), "HandleExitWorld")]
    [InlineData(typeof(MovementManager), "CancelMoveTo")]
    [InlineData(typeof(MotionInterp), "HitGround")]
    [InlineData(typeof(MotionInterp), "LeaveGround")]
    [InlineData(typeof(MotionInterp), "MotionDone")]
    [InlineData(typeof(MotionInterp), "HandleExitWorld")]
    [InlineData(typeof(BasicMovementManager), "HitGround")]
    [InlineData(typeof(BasicMovementManager), "LeaveGround")]
    [InlineData(typeof(BasicMovementManager), "UseTime")]
    [InlineData(typeof(BasicMovementManager), "HandleEnterWorld")]
    public void EngineCallbacks_AreNotPublicMembersOfTheClass(Type type, string name)
    {
        Assert.Null(type.GetMethod(name, BindingFlags.Public | BindingFlags.Instance));
    }

    [Fact]
    public void ReadingTheMotionInterpreter_CreatesNothing()
    {
        var world = new PhysicsWorld(0.0);
        var obj = world.CreateObject(1);
        var mm = MovementManager.Create(obj, null);
        IMovementManager seam = mm;
        Assert.Null(seam.MotionInterpreter);
        Assert.Null(seam.MotionInterpreter);   // still none: the getter does not create it
    }
}
