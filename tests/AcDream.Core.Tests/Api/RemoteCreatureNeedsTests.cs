using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Motion.Wire;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Retail;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// What a creature moved by the server's MovementEvents needs, and what the entry points answer when it is missing (issue
/// #33, "what a client developer hit"): a weenie for the run rate a MoveTo carries, a motion table for anything to move, and
/// a movement manager for the object's own commands.
/// </summary>
public sealed class RemoteCreatureNeedsTests
{
    private static PhysicsObj Creature(IMotionWeenie? weenie, IMotionPlayer? player)
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = world.CreateObject(MovementEventBytes.ObjectId);
        obj.Weenie = weenie;
        obj.PartArray = new SimplePartArray(1, 0) { MotionPlayer = player };
        obj.SetState((PhysicsState)PhysicsGlobals.DefaultState & ~PhysicsState.Gravity);
        return obj;
    }

    // Type 7 (MoveToPosition) in the non-combat style: origin (30, 40, 0) of cell 0xA9B40001, the move-to parameters
    // (bitfield 0x1EE0F, distance 0.6, min 0, fail MaxValue, speed 1, walk/run threshold 15, heading 0), run rate 1.9.
    private static byte[] MoveToPosition() => new RetailDataWriter().Byte(7).Byte(0).UInt16(0x3D)
        .UInt32(0xA9B40001u).Single(30f).Single(40f).Single(0f)
        .UInt32(0x1EE0Fu).Single(0.6f).Single(0f).Single(float.MaxValue).Single(1f).Single(15f).Single(0f)
        .Single(1.9f).ToArray();

    [Fact]
    public void MoveTo_WithoutAWeenie_IgnoresTheRunRate_AndSetupIssuesSaySo()
    {
        // Retail's interpreter asks the weenie for the run rate (get_max_speed 343485, InqRunRate): a remote creature's
        // ACCWeenieObject refuses, so the MoveTo's run rate (my_run_rate, 339583) applies: 4 · 1.9 = 7.6 m/s. Without a
        // weenie the no-weenie branch takes run rate 1: 4 m/s, whatever the server sent.
        var m = new MovementEventMessage();
        PhysicsObj bare = Creature(null, new SpeedOnlyMotionPlayer());
        MovementEventDecoder.Decode(MovementEventBytes.Body(1, 0, false, MoveToPosition()), m);
        Assert.Equal(MovementEventResult.Applied, bare.HandleMovementEvent(m));
        MotionInterp bareInterp = MovementManager.Of(bare).GetOrCreateMotionInterpreter();
        Assert.Equal(1.9f, bareInterp.MyRunRate);
        Assert.Equal(4.0, bareInterp.MaxSpeed);
        Assert.Equal(ObjectSetupIssues.NoWeenie, bare.SetupIssues & ObjectSetupIssues.NoWeenie);

        PhysicsObj remote = Creature(RemoteCreatureWeenie.Creature, new SpeedOnlyMotionPlayer());
        MovementEventDecoder.Decode(MovementEventBytes.Body(1, 0, false, MoveToPosition()), m);
        Assert.Equal(MovementEventResult.Applied, remote.HandleMovementEvent(m));
        Assert.Equal(1.9f * 4.0, MovementManager.Of(remote).GetOrCreateMotionInterpreter().MaxSpeed);
        Assert.Equal(ObjectSetupIssues.None, remote.SetupIssues & ObjectSetupIssues.NoWeenie);
    }

    [Fact]
    public void MovementEvent_WithoutAMotionTable_AnswersNoMotionTable_NotApplied()
    {
        // The event is unpacked as retail unpacks it (the interpreter runs at 2.0), but nothing plays the commands: the
        // result names the missing motion table. Once the part array has one, the next event is Applied.
        PhysicsObj obj = Creature(RemoteCreatureWeenie.Creature, null);
        var m = new MovementEventMessage();
        MovementEventDecoder.Decode(MovementEventBytes.Body(1, 0, false, MovementEventBytes.Forward(0x3D, 0x07, 2f)), m);
        Assert.Equal(MovementEventResult.NoMotionTable, obj.HandleMovementEvent(m));
        MotionInterp mi = MovementManager.Of(obj).GetOrCreateMotionInterpreter();
        Assert.Equal(MotionCommand.RunForward, mi.InterpretedState.ForwardCommand);
        Assert.Equal(ObjectSetupIssues.NoMotionTable, obj.SetupIssues & ObjectSetupIssues.NoMotionTable);

        ((SimplePartArray)obj.PartArray!).MotionPlayer = new SpeedOnlyMotionPlayer();
        MovementEventDecoder.Decode(MovementEventBytes.Body(2, 0, false, MovementEventBytes.Forward(0x3D, 0x07, 2f)), m);
        Assert.Equal(MovementEventResult.Applied, obj.HandleMovementEvent(m));
    }
}
