using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Fixtures.Wire;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Motion.Wire;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Retail;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// <see cref="ServerMessageHandler"/> as retail's SmartBox: the instance gate (queue / older instance), each message's
/// stamp, the player's blip, teleport and own echo, the queue applied after CreateObject.
/// </summary>
public class ServerMessageHandlerTests
{
    private const uint Remote = 0x80000001u;
    private const uint Me = 0x50000002u;

    private sealed class Control : IPlayerControl
    {
        public bool UsePositionFromServer { get; set; } = true;
        public List<string> Calls { get; } = [];
        public void LoseControlToServer() => Calls.Add("lose");
        public void PositionForcedByServer() => Calls.Add("forced");
        public void PlayerTeleported() => Calls.Add("teleported");
    }

    private static (PhysicsWorld World, ServerMessageHandler Handler) Scene()
    {
        PhysicsWorld world = ObjectScene.Flat(out _);
        return (world, new ServerMessageHandler(world));
    }

    private static byte[] Pos(uint id, Position p, ushort instance, ushort position, ushort teleport = 0, ushort force = 0, uint flags = 0x04) =>
        PhysicsMessageBytes.UpdatePosition(id, flags, p.ObjCellId, p.Frame.Origin, p.Frame.Rotation, instance, position, teleport, force);

    private static ServerMessageResult Send(ServerMessageHandler h, PhysicsMessageOpcode op, byte[] body) => h.HandleMessage((uint)op, body);

    [Fact]
    public void UpdatePosition_Remote_PositionStampInWrapOrder_StaleChangesNothing()
    {
        var (world, h) = Scene();
        PhysicsObj c = ObjectScene.Creature(world, Remote, ObjectScene.At(100f, 100f));
        // No player: the player distance is float.MaxValue, so a report with contact places the creature (MoveOrTeleport).
        // 0xFFFF after 0: |0xFFFF - 0| > 0x7FFF, wrapped: newer = 0xFFFF < 0, false: stale.
        Assert.Equal(ServerMessageResult.Stale, Send(h, PhysicsMessageOpcode.UpdatePosition, Pos(Remote, ObjectScene.At(110f, 100f), 0, 0xFFFF)));
        Assert.Equal(ServerMessageResult.Applied, Send(h, PhysicsMessageOpcode.UpdatePosition, Pos(Remote, ObjectScene.At(110f, 100f), 0, 0x7FFF)));
        Assert.Equal(ReceivedPositionResult.Placed, h.LastReceivedPosition);
        Assert.Equal(new Vector3(110f, 100f, 20f), c.Position.Frame.Origin);
        // 0xFFFE after 0x7FFF: plain order, newer. The same again: not newer. 0x0001 after 0xFFFE: wrapped, newer.
        Assert.Equal(ServerMessageResult.Applied, Send(h, PhysicsMessageOpcode.UpdatePosition, Pos(Remote, ObjectScene.At(110f, 100f), 0, 0xFFFE)));
        Assert.Equal(ServerMessageResult.Stale, Send(h, PhysicsMessageOpcode.UpdatePosition, Pos(Remote, ObjectScene.At(120f, 100f), 0, 0xFFFE)));
        Assert.Equal(new Vector3(110f, 100f, 20f), c.Position.Frame.Origin);
        Assert.Equal(ServerMessageResult.Applied, Send(h, PhysicsMessageOpcode.UpdatePosition, Pos(Remote, ObjectScene.At(120f, 100f), 0, 0x0001)));
        Assert.Equal(new Vector3(120f, 100f, 20f), c.Position.Frame.Origin);
    }

    [Fact]
    public void Instance_OlderDropped_NewerOrUnknownQueued_AppliedAfterCreateObject()
    {
        var (world, h) = Scene();
        h.ObjectFactory = (w, id, _) => ObjectScene.Creature(w, id, ObjectScene.At(50f, 50f));
        // Unknown object: kept.
        Assert.Equal(ServerMessageResult.Queued, Send(h, PhysicsMessageOpcode.UpdatePosition, Pos(Remote, ObjectScene.At(60f, 50f), 3, 2)));
        Assert.Equal(ServerMessageResult.Queued, Send(h, PhysicsMessageOpcode.SetState, PhysicsMessageBytes.SetState(Remote, 0x400C08 | 0x4, 3, 1)));
        Assert.Equal(2, h.QueuedMessageCount);
        // The CreateObject of instance 3 with position stamp 1 at (55, 50): created there, then the two kept messages apply.
        Position at = ObjectScene.At(55f, 50f);
        byte[] create = PhysicsMessageBytes.PhysicsDesc(PhysicsMessageBytes.CreateObjectStart(Remote), 0x400C08,
            new PhysicsMessageBytes.Stamps(Position: 1, Instance: 3), position: (at.ObjCellId, at.Frame.Origin, at.Frame.Rotation)).ToArray();
        Assert.Equal(ServerMessageResult.Applied, Send(h, PhysicsMessageOpcode.CreateObject, create));
        PhysicsObj c = world.GetObjectById(Remote)!;
        Assert.Equal(0, h.QueuedMessageCount);
        Assert.Equal(new Vector3(60f, 50f, 20f), c.Position.Frame.Origin);
        Assert.Equal((PhysicsState)(0x400C08 | 0x4), c.State);
        Assert.Equal((ushort)3, c.GetUpdateTime(PhysicsTimeStamp.Instance));
        // Instance 2 < 3: an older instance, dropped; 4 > 3: a newer one, kept.
        Assert.Equal(ServerMessageResult.OldInstance, Send(h, PhysicsMessageOpcode.UpdatePosition, Pos(Remote, ObjectScene.At(70f, 50f), 2, 3)));
        Assert.Equal(ServerMessageResult.Queued, Send(h, PhysicsMessageOpcode.UpdatePosition, Pos(Remote, ObjectScene.At(70f, 50f), 4, 3)));
        Assert.Equal(new Vector3(60f, 50f, 20f), c.Position.Frame.Origin);
    }

    [Fact]
    public void Player_NewerForcePosition_Blips_KeepingItsOwnHeading()
    {
        var (world, h) = Scene();
        PhysicsObj me = ObjectScene.Creature(world, Me, ObjectScene.At(100f, 100f, heading: 90f));
        var control = new Control { UsePositionFromServer = false };
        h.PlayerId = Me;
        h.PlayerControl = control;
        Assert.Equal(ServerMessageResult.PlayerBlipped,
            Send(h, PhysicsMessageOpcode.UpdatePosition, Pos(Me, ObjectScene.At(103f, 100f, heading: 0f), 0, 5, force: 1)));
        Assert.Equal(new Vector3(103f, 100f, 20f), me.Position.Frame.Origin);
        Assert.Equal(90.0, me.Position.Frame.Heading, 3);
        Assert.Equal((ushort)5, me.GetUpdateTime(PhysicsTimeStamp.Position));
        Assert.Equal(["forced"], control.Calls);
        // The same force stamp again: not a blip; the client is in control, so the echo is not used (stamp taken).
        Assert.Equal(ServerMessageResult.PlayerOwnEcho,
            Send(h, PhysicsMessageOpcode.UpdatePosition, Pos(Me, ObjectScene.At(110f, 100f), 0, 6, force: 1)));
        Assert.Equal(new Vector3(103f, 100f, 20f), me.Position.Frame.Origin);
        Assert.Equal(ServerMessageResult.Stale, Send(h, PhysicsMessageOpcode.UpdatePosition, Pos(Me, ObjectScene.At(110f, 100f), 0, 6)));
    }

    [Fact]
    public void Player_NewerTeleportStamp_Teleports_ThenPlayerTeleportWaitsUntilNotHidden()
    {
        var (world, h) = Scene();
        PhysicsObj me = ObjectScene.Creature(world, Me, ObjectScene.At(100f, 100f));
        me.SetVelocity(new Vector3(2f, 0f, 0f));
        var control = new Control();
        h.PlayerId = Me;
        h.PlayerControl = control;
        h.UseTime();
        Assert.True(h.PositionUpdateComplete);
        // PlayerTeleport 1 (not older than 0): waiting, the bookkeeping cleared.
        Assert.Equal(ServerMessageResult.Applied, Send(h, PhysicsMessageOpcode.PlayerTeleport, PhysicsMessageBytes.PlayerTeleport(1)));
        Assert.True(h.WaitingForTeleport);
        Assert.False(h.PositionUpdateComplete);
        h.UseTime();
        Assert.False(h.PositionUpdateComplete);
        // Hidden (0x4000): still waiting; the same state stamp: stale; shown: done.
        Assert.Equal(ServerMessageResult.Applied, Send(h, PhysicsMessageOpcode.SetState, PhysicsMessageBytes.SetState(Me, 0x404C08, 0, 1)));
        Assert.True(h.WaitingForTeleport);
        Assert.Equal(ServerMessageResult.Stale, Send(h, PhysicsMessageOpcode.SetState, PhysicsMessageBytes.SetState(Me, 0x400C08, 0, 1)));
        Assert.True(h.WaitingForTeleport);
        Assert.Equal(ServerMessageResult.Applied, Send(h, PhysicsMessageOpcode.SetState, PhysicsMessageBytes.SetState(Me, 0x400C08, 0, 2)));
        Assert.False(h.WaitingForTeleport);
        // The teleport's position (teleport stamp 1): placed, leashed, stopped, the interpreter told, the bookkeeping
        // restarted (PlayerPositionUpdated); the next frame completes it.
        Assert.Equal(ServerMessageResult.PlayerTeleported,
            Send(h, PhysicsMessageOpcode.UpdatePosition, Pos(Me, ObjectScene.At(20f, 30f), 0, 1, teleport: 1)));
        Assert.Equal(new Vector3(20f, 30f, 20f), me.Position.Frame.Origin);
        Assert.Equal(Vector3.Zero, me.Velocity);
        Assert.Equal(["teleported"], control.Calls);
        Assert.False(h.PositionUpdateComplete || h.HasBeenTeleported);
        h.UseTime();
        Assert.True(h.PositionUpdateComplete && h.HasBeenTeleported);
        // PlayerTeleport 0 is older than the player's teleport stamp 1: dropped.
        Assert.Equal(ServerMessageResult.Stale, Send(h, PhysicsMessageOpcode.PlayerTeleport, PhysicsMessageBytes.PlayerTeleport(0)));
        Assert.False(h.WaitingForTeleport);
    }

    [Fact]
    public void VectorUpdate_RemoteJumps_PlayerInControlIgnoresItsEcho()
    {
        var (world, h) = Scene();
        PhysicsObj c = ObjectScene.Creature(world, Remote, ObjectScene.At(100f, 100f));
        PhysicsObj me = ObjectScene.Creature(world, Me, ObjectScene.At(120f, 100f));
        h.PlayerId = Me;
        h.PlayerControl = new Control { UsePositionFromServer = false };
        var up = new Vector3(0f, 0f, 3.56924868f);
        Assert.Equal(ServerMessageResult.Applied, Send(h, PhysicsMessageOpcode.VectorUpdate, PhysicsMessageBytes.VectorUpdate(Remote, up, new Vector3(0f, 0f, 1f), 0, 1)));
        Assert.Equal(up, c.Velocity);
        Assert.Equal(new Vector3(0f, 0f, 1f), c.Omega);
        Assert.Equal(ServerMessageResult.Stale, Send(h, PhysicsMessageOpcode.VectorUpdate, PhysicsMessageBytes.VectorUpdate(Remote, Vector3.Zero, Vector3.Zero, 0, 1)));
        Assert.Equal(up, c.Velocity);
        Assert.Equal(ServerMessageResult.PlayerOwnEcho, Send(h, PhysicsMessageOpcode.VectorUpdate, PhysicsMessageBytes.VectorUpdate(Me, up, Vector3.Zero, 0, 1)));
        Assert.Equal(Vector3.Zero, me.Velocity);
        Assert.Equal((ushort)1, me.GetUpdateTime(PhysicsTimeStamp.Vector));
    }

    [Fact]
    public void ParentEvent_AttachesThroughTheHoldingLocation_PickupLeavesTheWorld_DeleteRemoves()
    {
        var (world, h) = Scene();
        PhysicsObj npc = ObjectScene.Creature(world, 0x7A9B4026u, ObjectScene.At(100f, 100f));
        // The child does not exist yet: kept under the child's id.
        Assert.Equal(ServerMessageResult.Queued,
            Send(h, PhysicsMessageOpcode.ParentEvent, PhysicsMessageBytes.ParentEvent(npc.Id, Remote, 1, 0, 0, 1)));
        PhysicsObj axe = ObjectScene.Creature(world, Remote, ObjectScene.At(10f, 10f));
        // No holding locations: nothing attached (the stamp taken, as retail).
        Assert.Equal(ServerMessageResult.NotApplicable,
            Send(h, PhysicsMessageOpcode.ParentEvent, PhysicsMessageBytes.ParentEvent(npc.Id, Remote, 1, 0, 0, 1)));
        Assert.Null(axe.Parent);
        h.HoldingLocations = (PhysicsObj parent, uint location, out uint part, out Frame frame) =>
        {
            part = location;
            frame = Frame.Identity;
            return location == 1;
        };
        Assert.Equal(ServerMessageResult.Stale,
            Send(h, PhysicsMessageOpcode.ParentEvent, PhysicsMessageBytes.ParentEvent(npc.Id, Remote, 1, 0, 0, 1)));
        Assert.Equal(ServerMessageResult.Applied,
            Send(h, PhysicsMessageOpcode.ParentEvent, PhysicsMessageBytes.ParentEvent(npc.Id, Remote, 1, 0, 0, 2)));
        Assert.Same(npc, axe.Parent);
        // Picked up: off its parent and out of every cell, still an object of the world.
        Assert.Equal(ServerMessageResult.Applied, Send(h, PhysicsMessageOpcode.PickupEvent, PhysicsMessageBytes.PickupEvent(Remote, 0, 3)));
        Assert.Null(axe.Parent);
        Assert.Equal(0u, axe.CellId);
        Assert.Equal(0u, axe.Position.ObjCellId);
        Assert.Same(axe, world.GetObjectById(Remote));
        // Delete: the player never; an older instance dropped; this instance removed.
        h.PlayerId = npc.Id;
        Assert.Equal(ServerMessageResult.NotApplicable, Send(h, PhysicsMessageOpcode.DeleteObject, PhysicsMessageBytes.DeleteObject(npc.Id, 0)));
        axe.NewerEvent(PhysicsTimeStamp.Instance, 2);
        Assert.Equal(ServerMessageResult.OldInstance, Send(h, PhysicsMessageOpcode.DeleteObject, PhysicsMessageBytes.DeleteObject(Remote, 1)));
        Assert.Equal(ServerMessageResult.Applied, Send(h, PhysicsMessageOpcode.DeleteObject, PhysicsMessageBytes.DeleteObject(Remote, 2)));
        Assert.True(axe.IsRemoved);
        Assert.Null(world.GetObjectById(Remote));
    }

    [Fact]
    public void MovementEvent_AppliedToThePlayer_GivesControlToTheServer()
    {
        var (world, h) = Scene();
        PhysicsObj me = world.CreateObject(MovementEventBytes.ObjectId);
        // A motion player: without one the event is unpacked but moves nothing (MovementEventResult.NoMotionTable, #33).
        var body = Walkers.OneSphere(0.5f);
        body.MotionPlayer = new SpeedOnlyMotionPlayer();
        me.PartArray = body;
        me.Weenie = new PlayerWeenie();
        Assert.True(me.EnterWorld(ObjectScene.At(100f, 100f)));
        var control = new Control();
        h.PlayerId = me.Id;
        h.PlayerControl = control;
        // The echo of its own motion (autonomous 1): ignored, control stays.
        Assert.Equal(ServerMessageResult.PlayerOwnEcho, Send(h, PhysicsMessageOpcode.MovementEvent,
            MovementEventBytes.Body(1, 0, true, MovementEventBytes.Forward(0x3D, 0x07, 2f))));
        Assert.Empty(control.Calls);
        Assert.Equal(ServerMessageResult.Applied, Send(h, PhysicsMessageOpcode.MovementEvent,
            MovementEventBytes.Body(2, 1, false, MovementEventBytes.Forward(0x3D, 0x07, 2f))));
        Assert.Equal(["lose"], control.Calls);
        Assert.Equal(MotionCommand.RunForward, MovementManager.Of(me).InqInterpretedMotionState().ForwardCommand);
    }

    [Fact]
    public void CreateObject_AppliesThePhysicsDescription_AndItsMovementBuffer()
    {
        var (world, h) = Scene();
        PhysicsDesc? seen = null;
        h.ObjectFactory = (w, id, d) =>
        {
            seen = d;
            PhysicsObj o = w.CreateObject(id);
            o.PartArray = Walkers.OneSphere(0.5f);
            o.Weenie = RemoteCreatureWeenie.Creature;
            return o;
        };
        Position at = ObjectScene.At(100f, 100f);
        byte[] body = PhysicsMessageBytes.PhysicsDesc(PhysicsMessageBytes.CreateObjectStart(Remote), 0x400C08,
            new PhysicsMessageBytes.Stamps(Position: 1, Movement: 2, State: 3, Vector: 4, Instance: 9),
            movement: MovementEventBytes.Forward(0x3D, 0x07, 2f), setup: 0x02000001u, scale: 1.5f, friction: 0.5f, elasticity: 0.2f, translucency: 0.3f,
            velocity: new Vector3(1f, 0f, 0f), omega: new Vector3(0f, 0f, 0.5f)).ToArray();
        Assert.Equal(ServerMessageResult.Applied, Send(h, PhysicsMessageOpcode.CreateObject, body));
        PhysicsObj o = world.GetObjectById(Remote)!;
        Assert.Equal(0x02000001u, seen!.SetupId);
        Assert.Equal(0u, o.CellId); // no position: not in the world
        Assert.Equal((1.5f, 0.5f, 0.2f, 0.3f, 0.3f), (o.Scale, o.Friction, o.Elasticity, o.Translucency, o.TranslucencyOriginal));
        Assert.Equal(new Vector3(1f, 0f, 0f), o.Velocity);
        Assert.Equal(new Vector3(0f, 0f, 0.5f), o.Omega);
        Assert.Equal(MotionCommand.RunForward, MovementManager.Of(o).InqInterpretedMotionState().ForwardCommand);
        Assert.Equal(((ushort)1, (ushort)2, (ushort)3, (ushort)4, (ushort)9), (o.GetUpdateTime(PhysicsTimeStamp.Position),
            o.GetUpdateTime(PhysicsTimeStamp.Movement), o.GetUpdateTime(PhysicsTimeStamp.State), o.GetUpdateTime(PhysicsTimeStamp.Vector),
            o.GetUpdateTime(PhysicsTimeStamp.Instance)));
        // The same CreateObject again (same instance): an update, each part gated by its stamp: nothing is newer.
        o.SetVelocity(Vector3.Zero);
        Assert.Equal(ServerMessageResult.Applied, Send(h, PhysicsMessageOpcode.CreateObject, body));
        Assert.Equal(Vector3.Zero, o.Velocity);
        Assert.Same(o, world.GetObjectById(Remote));
        // With a position (and no parent): the object enters the world there.
        byte[] placed = PhysicsMessageBytes.PhysicsDesc(PhysicsMessageBytes.CreateObjectStart(Remote + 1), 0x400C08,
            new PhysicsMessageBytes.Stamps(Instance: 1), position: (at.ObjCellId, at.Frame.Origin, at.Frame.Rotation)).ToArray();
        Assert.Equal(ServerMessageResult.Applied, Send(h, PhysicsMessageOpcode.CreateObject, placed));
        Assert.Equal(at.ObjCellId, world.GetObjectById(Remote + 1)!.CellId);
        Assert.Equal(at.Frame.Origin, world.GetObjectById(Remote + 1)!.Position.Frame.Origin);
    }

    [Fact]
    public void BadInput_RefusedBeforeAnythingChanges()
    {
        var (world, h) = Scene();
        PhysicsObj c = ObjectScene.Creature(world, Remote, ObjectScene.At(100f, 100f));
        // Outdoor x beyond 384 m: outside the position domain.
        byte[] far = PhysicsMessageBytes.UpdatePosition(Remote, 0x04, c.Position.ObjCellId, new Vector3(500f, 100f, 20f), Quaternion.Identity, 0, 1);
        Assert.Throws<System.ArgumentException>(() => Send(h, PhysicsMessageOpcode.UpdatePosition, far));
        Assert.Equal((ushort)0, c.GetUpdateTime(PhysicsTimeStamp.Position));
        Assert.Throws<AcDream.Core.Physics.Format.RetailDataFormatException>(() =>
            Send(h, PhysicsMessageOpcode.UpdatePosition, Pos(Remote, ObjectScene.At(110f, 100f), 0, 1)[..^1]));
        Assert.Equal(new Vector3(100f, 100f, 20f), c.Position.Frame.Origin);
        Assert.Equal(0, h.QueuedMessageCount);
        Assert.Equal(ServerMessageResult.NotApplicable, h.HandleMessage(0xF7B0, [1, 2, 3]));
    }
}
