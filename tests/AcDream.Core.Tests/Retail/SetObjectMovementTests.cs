using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using Xunit;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Core.Tests.Retail;

/// <summary>A motion table that records every interpreted motion it is asked to play (and plays it on a retail-speed
/// table).</summary>
internal sealed class RecordingMotionTable : IMotionPlayer
{
    private readonly SpeedOnlyMotionPlayer _inner = new();

    public List<MotionCommand> Done { get; } = new();

    public MotionError DoInterpretedMotion(MotionCommand motion, in MovementParameters p)
    {
        Done.Add(motion);
        return _inner.DoInterpretedMotion(motion, p);
    }

    public MotionError StopInterpretedMotion(MotionCommand motion, in MovementParameters p) => _inner.StopInterpretedMotion(motion, p);

    public MotionError StopCompletely() => _inner.StopCompletely();

    public void InitializeMotionTables() => _inner.InitializeMotionTables();

    public void RemoveLinkAnimations() => _inner.RemoveLinkAnimations();

    public bool TryTakeCompletedMotion(out MotionCommand motion, out bool success) => _inner.TryTakeCompletedMotion(out motion, out success);

    public Vector3 Velocity => _inner.Velocity;

    public Vector3 Omega => _inner.Omega;
}

/// <summary>Builds MovementEvent bodies (the bytes after the 0xF74C opcode) as the server writes them.</summary>
internal static class MovementEventBytes
{
    public const uint ObjectId = 0x80000001u;

    /// <summary>guid, instance 0, the two stamps, the autonomous byte, one pad byte, then <paramref name="data"/>.</summary>
    public static byte[] Body(ushort movement, ushort serverControl, bool autonomous, byte[] data, uint id = ObjectId) =>
        new RetailDataWriter().UInt32(id).UInt16(0).UInt16(movement).UInt16(serverControl).Byte(autonomous ? (byte)1 : (byte)0)
            .Align4().Bytes(data).ToArray();

    /// <summary>Type-0 data: header style index <paramref name="styleIndex"/>, a state with only a forward command
    /// (index <paramref name="forwardIndex"/>) and its speed.</summary>
    public static byte[] Forward(ushort styleIndex, ushort forwardIndex, float speed) =>
        new RetailDataWriter().Byte(0).Byte(0).UInt16(styleIndex).UInt32(0x2 | 0x4).UInt16(forwardIndex).Single(speed).Align4().ToArray();
}

// Retail CPhysics::SetObjectMovement (acclient.c:311148-311194) and MovementManager::unpack_movement (acclient.c:339491):
// the stamps, the echo of the player's own motion, last_move_was_autonomous and the header's style.
public class SetObjectMovementTests
{
    // command_ids[0x3C] (acclient_data.h): the hand-combat style.
    private const MotionCommand HandCombat = (MotionCommand)0x8000003Cu;

    private static (PhysicsObj Obj, RecordingMotionTable Table, MovementEventMessage Message) Create(IMotionWeenie? weenie)
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = world.CreateObject(MovementEventBytes.ObjectId);
        obj.Weenie = weenie;
        var table = new RecordingMotionTable();
        obj.PartArray = new SimplePartArray(1, 0) { MotionPlayer = table };
        obj.SetState((PhysicsState)PhysicsGlobals.DefaultState & ~PhysicsState.Gravity);
        MovementManager.Of(obj);
        return (obj, table, new MovementEventMessage());
    }

    private static MovementEventResult Send(PhysicsObj obj, MovementEventMessage m, ushort movement, ushort serverControl,
                                            bool autonomous = false, byte[]? data = null)
    {
        // 0x0007 RunForward at 2.0 in the non-combat style (index 0x3D).
        MovementEventDecoder.Decode(MovementEventBytes.Body(movement, serverControl, autonomous,
            data ?? MovementEventBytes.Forward(0x3D, 0x07, 2f)), m);
        return obj.HandleMovementEvent(m);
    }

    [Fact]
    public void MovementStamp_MustBeNewer_InWrapAroundOrder()
    {
        var (obj, _, m) = Create(RemoteCreatureWeenie.Creature);
        // Stored 0 at creation: 0 is not newer (old < new fails), 1 is.
        Assert.Equal(MovementEventResult.Stale, Send(obj, m, 0, 0));
        Assert.Equal(MovementEventResult.Applied, Send(obj, m, 1, 0));
        Assert.Equal(MovementEventResult.Stale, Send(obj, m, 1, 0));
        Assert.Equal(MovementEventResult.Applied, Send(obj, m, 0x7FFF, 0));
        // |0x8000 - 0x7FFF| = 1: plain order, newer.
        Assert.Equal(MovementEventResult.Applied, Send(obj, m, 0x8000, 0));
        Assert.Equal(MovementEventResult.Applied, Send(obj, m, 0xFFF0, 0));
        // |0x0005 - 0xFFF0| = 0xFFEB > 0x7FFF: wrapped, newer = new < old = 5 < 0xFFF0, true.
        Assert.Equal(MovementEventResult.Applied, Send(obj, m, 0x0005, 0));
        // |0x8006 - 0x0005| = 0x8001 > 0x7FFF: newer = 0x8006 < 5, false.
        Assert.Equal(MovementEventResult.Stale, Send(obj, m, 0x8006, 0));
        Assert.Equal((ushort)0x0005, obj.GetUpdateTime(PhysicsTimeStamp.Movement));
    }

    [Fact]
    public void OlderServerControlStamp_IsDropped_AfterTheMovementStampIsTaken()
    {
        var (obj, table, m) = Create(RemoteCreatureWeenie.Creature);
        Assert.Equal(MovementEventResult.Applied, Send(obj, m, 1, 3));
        Assert.Equal((ushort)3, obj.GetUpdateTime(PhysicsTimeStamp.ServerControlledMove));
        int played = table.Done.Count;
        // Server control 2 < 3: dropped, but update_times[1] = 2 was already written (acclient.c:311175 before 311177).
        Assert.Equal(MovementEventResult.StaleServerControl, Send(obj, m, 2, 2));
        Assert.Equal((ushort)2, obj.GetUpdateTime(PhysicsTimeStamp.Movement));
        Assert.Equal((ushort)3, obj.GetUpdateTime(PhysicsTimeStamp.ServerControlledMove));
        Assert.Equal(played, table.Done.Count);
        // Equal is not older: taken.
        Assert.Equal(MovementEventResult.Applied, Send(obj, m, 3, 3));
        // Wrapped: stored 3, received 0xFFFF: |3 - 0xFFFF| > 0x7FFF, older = stored < received = 3 < 0xFFFF, true.
        Assert.Equal(MovementEventResult.StaleServerControl, Send(obj, m, 4, 0xFFFF));
    }

    [Fact]
    public void EchoOfThePlayersOwnAutonomousMotion_IsIgnored_OthersApply()
    {
        var (player, table, m) = Create(new PlayerWeenie());
        player.LastMoveWasAutonomous = true;
        Assert.Equal(MovementEventResult.OwnAutonomousEcho, Send(player, m, 1, 1, autonomous: true));
        // Nothing played, both stamps taken.
        Assert.Empty(table.Done);
        Assert.Equal((ushort)1, player.GetUpdateTime(PhysicsTimeStamp.Movement));
        Assert.Equal((ushort)1, player.GetUpdateTime(PhysicsTimeStamp.ServerControlledMove));
        Assert.Equal(MotionCommand.Ready, MovementManager.Of(player).InqInterpretedMotionState().ForwardCommand);
        // The server's own motion for the player (autonomous 0) applies, and last_move_was_autonomous becomes 0.
        Assert.Equal(MovementEventResult.Applied, Send(player, m, 2, 2, autonomous: false));
        Assert.False(player.LastMoveWasAutonomous);
        Assert.Equal(MotionCommand.RunForward, MovementManager.Of(player).InqInterpretedMotionState().ForwardCommand);

        // Another player's autonomous motion (IsThePlayer false) applies and is recorded autonomous.
        var (remote, _, m2) = Create(RemoteCreatureWeenie.Player);
        Assert.Equal(MovementEventResult.Applied, Send(remote, m2, 1, 0, autonomous: true));
        Assert.True(remote.LastMoveWasAutonomous);
    }

    [Fact]
    public void StyleSwitch_UsesTheHeadersStyle_NotTheStates()
    {
        // Header style index 0x3C = HandCombat (0x8000003C); the state has no style flag, so its own style is the default
        // NonCombat (0x8000003D), which is also the interpreter's. Retail (acclient.c:339540-339542) compares the interpreter's
        // style with the header's and calls DoMotion(HandCombat): the table plays 0x8000003C. Taking the state's style (the
        // library before this test) compared NonCombat with NonCombat and never played it.
        var (obj, table, m) = Create(RemoteCreatureWeenie.Creature);
        Assert.Equal(MovementEventResult.Applied, Send(obj, m, 1, 0, data: MovementEventBytes.Forward(0x3C, 0x03, 1f)));
        Assert.Equal(HandCombat, m.Style);
        Assert.Equal(MotionCommand.NonCombat, m.State.CurrentStyle);
        Assert.Contains(HandCombat, table.Done);

        // The same state through ApplyInterpretedMotion (whose header style is the state's) never asks for HandCombat.
        var (obj2, table2, _) = Create(RemoteCreatureWeenie.Creature);
        Assert.True(MovementEvent.ApplyInterpretedMotion(obj2, m.State));
        Assert.DoesNotContain(HandCombat, table2.Done);
    }

    [Fact]
    public void Type0_StickyFlag_SticksToTheObject_AndLongJumpFlagIsRecorded()
    {
        var (obj, _, m) = Create(RemoteCreatureWeenie.Creature);
        PhysicsObj target = obj.World.CreateObject(0x80000002u);
        target.PartArray = new SimplePartArray(1, 0);
        // Motion flags 0x03: sticky (the object id follows the state) and standing long jump.
        byte[] data = new RetailDataWriter().Byte(0).Byte(0x03).UInt16(0x3D).UInt32(0).UInt32(0x80000002u).ToArray();
        Assert.Equal(MovementEventResult.Applied, Send(obj, m, 1, 0, data: data));
        Assert.Equal(0x80000002u, m.StickToObject);
        Assert.Equal(0x80000002u, obj.StickyObjectId);
        Assert.True(MovementManager.Of(obj).GetOrCreateMotionInterpreter().StandingLongJump);
    }

    [Fact]
    public void MoveToObject_OfAnUnknownObject_MovesToTheOrigin_TurnToObject_TurnsToTheEventsHeading()
    {
        // acclient.c:339564-339578: CPhysicsObj::GetObjectA(target) fails -> MoveToManager::MoveToPosition(origin);
        // acclient.c:339592-339606: for type 8 -> params.desired_heading = the event's heading, TurnToHeading.
        var (obj, _, m) = Create(RemoteCreatureWeenie.Creature);
        byte[] moveTo = new RetailDataWriter().Byte(6).Byte(0).UInt16(0x3D).UInt32(0x80000077u)
            .UInt32(0xA9B40001u).Single(30f).Single(40f).Single(0f)
            .UInt32(0x1EE0Fu).Single(0.6f).Single(0f).Single(float.MaxValue).Single(1f).Single(15f).Single(0f)
            .Single(1.25f).ToArray();
        Assert.Equal(MovementEventResult.Applied, Send(obj, m, 1, 0, data: moveTo));
        MovementManager mm = MovementManager.Of(obj);
        Assert.Equal(1.25f, mm.GetOrCreateMotionInterpreter().MyRunRate);
        Assert.Equal(MovementType.MoveToPosition, mm.MoveToManager!.MovementType);
        Assert.Equal(new Vector3(30f, 40f, 0f), mm.MoveToManager.SoughtPosition.Frame.Origin);
        Assert.Equal(0xA9B40001u, mm.MoveToManager.SoughtPosition.ObjCellId);

        // Type 8 with heading 123 before the parameters (whose own desired heading is 0): turns to 123.
        byte[] turnTo = new RetailDataWriter().Byte(8).Byte(0).UInt16(0x3D).UInt32(0x80000077u).Single(123f)
            .UInt32(0x1EE0Fu).Single(1f).Single(0f).ToArray();
        Assert.Equal(MovementEventResult.Applied, Send(obj, m, 2, 0, data: turnTo));
        Assert.Equal(MovementType.TurnToHeading, mm.MoveToManager.MovementType);
        Assert.Equal(123f, mm.MoveToManager.MovementParams.DesiredHeading);
    }
}
