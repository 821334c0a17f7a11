using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Fixtures.Wire;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Motion.Wire;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Replay.Harness;
using Xunit;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Replay;

/// <summary>
/// Every server message of every recording rebuilt as its body, decoded by the library and applied through
/// <see cref="ServerMessageHandler"/>; and the recordings' CreateObjects made through the CreateObject door.
/// </summary>
public class RecordingWireTests(ITestOutputHelper output)
{
    private static readonly string[] Slugs =
    [
        "fellowship-one-vassal", "fellowship-two-monarch", "fellowship-three-vassal", "long-movement-run", "melee-attack-run",
        "first-login-walk-jump",
    ];

    private static IEnumerable<string[]> Rows(string file)
    {
        string path = Path.Combine(RealMotionReplayTests.Dir!, file);
        return File.Exists(path) ? Csv.Rows(path) : [];
    }

    // Every F748 decodes to its columns; every F74E and F74C decodes; all three go through one handler per recording in
    // arrival order, with each guid created (at its instance stamp) before its first message. Every result is one the
    // stamps explain: an UpdatePosition is stale exactly when its position stamp is not newer than the guid's last one.
    [ReplayDataFact]
    public void EveryPositionVectorAndMovementMessage_DecodesToItsColumns_AndAppliesThroughTheHandler()
    {
        int total = 0;
        foreach (string slug in Slugs)
        {
            var messages = new List<(double T, long Idx, uint Opcode, uint Guid, ushort Instance, byte[] Body, string[] Row)>();
            foreach (string[] c in Rows(slug + "_s2c_updateposition.csv"))
            {
                byte[] body = WireBodies.UpdatePosition(c);
                UpdatePositionMessage m = WireBodies.DecodePosition(body);
                Assert.Equal(Csv.U(c[1]), m.ObjectId);
                Assert.Equal(Csv.U(c[2]), (uint)m.Flags);
                Assert.Equal(Csv.U(c[3]), m.Position.ObjCellId);
                Assert.Equal(new Vector3(Csv.F(c[4]), Csv.F(c[5]), Csv.F(c[6])), m.Position.Frame.Origin);
                // The rotation is the columns' quaternion (omitted components 0), normalised: the same up to sign.
                var recorded = Quaternion.Normalize(new Quaternion(Csv.F(c[8]), Csv.F(c[9]), Csv.F(c[10]), Csv.F(c[7])));
                Assert.InRange(Math.Abs(Quaternion.Dot(recorded, m.Position.Frame.Rotation)), 1f - 1e-6f, 1f + 1e-6f);
                Assert.Equal(c[15] == "1", m.HasContact);
                Assert.Equal((Csv.U16(c[16]), Csv.U16(c[17]), Csv.U16(c[18]), Csv.U16(c[19])),
                    (m.InstanceTimestamp, m.PositionTimestamp, m.TeleportTimestamp, m.ForcePositionTimestamp));
                messages.Add((Csv.D(c[0]), long.Parse(c[21]), 0xF748, m.ObjectId, m.InstanceTimestamp, body, c));
            }

            foreach (string[] c in Rows(slug + "_s2c_vectorupdate.csv"))
            {
                var v = new VectorUpdateMessage();
                byte[] body = WireBodies.VectorUpdate(c);
                PhysicsMessageDecoder.Decode(body, v);
                Assert.Equal(new Vector3(Csv.F(c[2]), Csv.F(c[3]), Csv.F(c[4])), v.Velocity);
                messages.Add((Csv.D(c[0]), long.Parse(c[10]), 0xF74E, v.ObjectId, v.InstanceTimestamp, body, c));
            }

            foreach (string[] c in Rows(slug + "_s2c_movementevent.csv"))
            {
                var e = new MovementEventMessage();
                byte[] body = WireBodies.MovementEvent(c);
                MovementEventDecoder.Decode(body, e);
                messages.Add((Csv.D(c[0]), long.Parse(c[7]), 0xF74C, e.ObjectId, e.InstanceTimestamp, body, c));
            }

            messages.Sort((a, b) => a.Idx.CompareTo(b.Idx));
            var world = new PhysicsWorld(0.0) { Sweep = new LastReportGroundSweep { GroundZ = 0f } };
            var handler = new ServerMessageHandler(world);
            var lastPosition = new Dictionary<uint, ushort>();
            var counts = new int[9];
            foreach (var msg in messages)
            {
                if (world.GetObjectById(msg.Guid) is not PhysicsObj obj || obj.GetUpdateTime(PhysicsTimeStamp.Instance) != msg.Instance)
                {
                    // A new guid, or a new instance of it (a re-created player): created as its CreateObject would.
                    if (world.GetObjectById(msg.Guid) is PhysicsObj old)
                    {
                        world.RemoveObject(old);
                    }

                    obj = world.CreateObject(msg.Guid);
                    var parts = new SimplePartArray(SetupPhysics.Human) { MotionPlayer = new SpeedOnlyMotionPlayer() };
                    obj.PartArray = parts;
                    obj.Weenie = (msg.Guid >> 28) == 5 ? RemoteCreatureWeenie.Player : RemoteCreatureWeenie.Creature;
                    obj.NewerEvent(PhysicsTimeStamp.Instance, msg.Instance);
                    lastPosition.Remove(msg.Guid);
                }

                ServerMessageResult r = handler.HandleMessage(msg.Opcode, msg.Body);
                counts[(int)r]++;
                if (msg.Opcode == 0xF748)
                {
                    ushort seq = Csv.U16(msg.Row[17]);
                    bool newer = !lastPosition.TryGetValue(msg.Guid, out ushort before) || ServerMessageHandlerTestsAccess.IsNewer(before, seq);
                    Assert.Equal(newer ? ServerMessageResult.Applied : ServerMessageResult.Stale, r);
                    if (newer)
                    {
                        lastPosition[msg.Guid] = seq;
                    }
                }
                else
                {
                    Assert.NotEqual(ServerMessageResult.Queued, r);
                }
            }

            output.WriteLine($"{slug}: {messages.Count} messages; applied {counts[0]}, stale {counts[1]}, own echo {counts[5]}, not applicable {counts[8]}");
            total += messages.Count;
        }

        // 1,529 F748 + 10 F74E + 832 F74C: every row of the six recordings' files (as copied here: long-movement-run up to
        // 400 s, melee-attack-run up to 60 s).
        Assert.Equal(1529 + 10 + 832, total);
    }

    // The CreateObjects of first-login-walk-jump and melee-attack-run through the CreateObject door (a human Setup: the
    // recordings keep no Setup ids): every object with a position is where its create puts it; the three weapons held by
    // NPCs (README: parent bit 0x20) hang from their parents, two of them created before the parent and kept until it.
    [ReplayDataFact]
    public void RecordedCreates_ThroughTheCreateObjectDoor_AreWhereTheirCreatesPutThem()
    {
        var heldBy = new Dictionary<uint, uint>
        {
            [0x800004ADu] = 0x7A9B4026u, // Hand Axe: Sedor Wystan the Blacksmith
            [0x800004C0u] = 0x7A9B4028u, // Shortbow: Sontella Dagroff the Bowyer
            [0x80000576u] = 0x80000578u, // Paradox-touched Olthoi Spear: Rand, Game Hunter
        };
        foreach (string slug in new[] { "first-login-walk-jump", "melee-attack-run" })
        {
            var world = new PhysicsWorld(0.0) { Sweep = new LastReportGroundSweep { GroundZ = 0f } };
            var handler = new ServerMessageHandler(world)
            {
                ObjectFactory = (w, id, d) =>
                {
                    PhysicsObj o = w.CreateObject(id);
                    o.PartArray = new SimplePartArray(SetupPhysics.Human);
                    return o;
                },
                // The holding location as the parent's own frame (the recordings keep no Setup to look it up in).
                HoldingLocations = (PhysicsObj parent, uint location, out uint part, out Frame frame) =>
                {
                    part = uint.MaxValue;
                    frame = Frame.Identity;
                    return true;
                },
            };
            int placed = 0, held = 0, queuedOnce = 0;
            var expected = new Dictionary<uint, Position>();
            foreach (string[] c in Rows(slug + "_creates.csv"))
            {
                uint guid = Csv.U(c[0]);
                var stamps = new PhysicsMessageBytes.Stamps(Position: Csv.U16(c[14]), Instance: Csv.U16(c[13]));
                RetailDataWriter w = PhysicsMessageBytes.CreateObjectStart(guid);
                if (c[3].Length != 0)
                {
                    var p = new Position(Csv.U(c[3]), Csv.Frame(c, 4));
                    expected[guid] = p;
                    PhysicsMessageBytes.PhysicsDesc(w, 0x400C08, stamps, position: (p.ObjCellId, p.Frame.Origin, p.Frame.Rotation));
                }
                else if (heldBy.TryGetValue(guid, out uint parent))
                {
                    PhysicsMessageBytes.PhysicsDesc(w, 0x400C08, stamps, parent: (parent, 1u));
                }
                else
                {
                    PhysicsMessageBytes.PhysicsDesc(w, 0x400C08, stamps);
                }

                if (handler.HandleMessage(0xF745, w.ToArray()) == ServerMessageResult.Queued)
                {
                    queuedOnce++;
                }
            }

            Assert.Equal(0, handler.QueuedMessageCount);
            foreach ((uint guid, Position p) in expected)
            {
                PhysicsObj o = world.GetObjectById(guid)!;
                Assert.Equal(p.ObjCellId, o.Position.ObjCellId);
                Assert.Equal(p.Frame.Origin, o.Position.Frame.Origin);
                Assert.NotEqual(0u, o.CellId);
                placed++;
            }

            foreach ((uint item, uint parent) in heldBy)
            {
                if (world.GetObjectById(item) is PhysicsObj o)
                {
                    Assert.Same(world.GetObjectById(parent), o.Parent);
                    Assert.Equal(o.Parent!.Position.Frame.Origin, o.Position.Frame.Origin);
                    held++;
                }
            }

            output.WriteLine($"{slug}: {placed} placed, {held} held, {queuedOnce} kept until their parent");
            if (slug == "first-login-walk-jump")
            {
                // 71 creates with a position (the player and 70 world objects), 3 weapons; the Shortbow (msg 97) and the
                // Spear (msg 120) arrive before their parents (msgs 98, 127).
                Assert.Equal((71, 3, 2), (placed, held, queuedOnce));
            }
            else
            {
                // The 21 creates with a position in this copy (t < 60 s), no held item.
                Assert.Equal((21, 0, 0), (placed, held, queuedOnce));
            }
        }
    }
}

// The handler's 16-bit order, for the expectations above.
internal static class ServerMessageHandlerTestsAccess
{
    public static bool IsNewer(ushort oldTime, ushort newTime) => ServerMessageHandler.IsNewer(oldTime, newTime);
}
