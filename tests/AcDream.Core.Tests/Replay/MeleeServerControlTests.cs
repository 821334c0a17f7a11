using System;
using System.Buffers.Binary;
using System.Collections.Generic;
using System.IO;
using AcDream.Core.Physics.Input;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Motion.Wire;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Replay.Harness;
using AcDream.Core.Tests.Support.Shared;
using Xunit;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Replay;

/// <summary>
/// The player under server control on melee-attack-run: every MovementEvent of the player and the monsters through
/// <see cref="ServerMessageHandler"/>, the player's <see cref="PlayerInput"/> its <see cref="ServerMessageHandler.PlayerControl"/>.
/// The server's four MoveToObject approaches (19.2-41.1 s) take control from the keys; the real client sent no MoveToState
/// from the first approach to 45 s (its keys did nothing) and AutonomousPositions carrying the server-control stamp of the
/// approach (2, 3, 4, 5): the library's outbound side does the same.
/// </summary>
public class MeleeServerControlTests(ITestOutputHelper output)
{
    [MeleeDataFact]
    public void Approaches_TakeControlFromTheKeys_AndThePositionsSentCarryTheApproachesServerControlStamp()
    {
        MeleeRecording rec = MeleeRecording.Load(RealMotionReplayTests.Dir!);
        (double startT, var playerStart) = rec.Creates[MeleeRecording.Player];
        var world = new PhysicsWorld(startT) { Sweep = new LastReportGroundSweep { GroundZ = MeleeReplay.GroundZ } };
        PhysicsObj player = world.CreateObject(MeleeRecording.Player);
        player.Weenie = new ReplayPlayerWeenie();
        var parts = Walkers.OneSphere(0.35f);
        parts.MotionPlayer = new SpeedOnlyMotionPlayer();
        player.PartArray = parts;
        player.EnterWorld(playerStart);
        world.Player = player;
        MovementManager.Of(player);
        player.NewerEvent(PhysicsTimeStamp.Instance, 4);
        foreach (uint guid in new[] { MeleeRecording.Chicken, MeleeRecording.TheChicken })
        {
            PhysicsObj m = world.CreateObject(guid);
            m.Weenie = RemoteCreatureWeenie.Creature;
            var mp = Walkers.OneSphere(0.35f);
            mp.MotionPlayer = new SpeedOnlyMotionPlayer();
            m.PartArray = mp;
            m.EnterWorld(rec.Creates[guid].Position);
        }

        var input = new PlayerInput(player);
        var handler = new ServerMessageHandler(world) { PlayerId = MeleeRecording.Player, PlayerControl = input };
        // The recorded AutonomousPositions and MoveToStates from the first approach on (their server-control stamps).
        var recorded = new List<(double T, string Action, ushort ServerControl)>();
        foreach (string[] c in Csv.Rows(Path.Combine(RealMotionReplayTests.Dir!, "melee-attack-run_c2s_autonomous.csv")))
        {
            double t = Csv.D(c[0]);
            if (t >= 19.2 && t <= 45.0)
            {
                recorded.Add((t, c[9], Csv.U16(c[11])));
            }
        }

        var sent = new List<(double T, string Action, ushort ServerControl)>();
        var controlledAfterMoveTo = new List<bool>();
        int mi = 0, ui = 0;
        for (double now = startT + MeleeReplay.Dt; now <= 45.0; now += MeleeReplay.Dt)
        {
            while (mi < rec.Movements.Count && rec.Movements[mi].T <= now)
            {
                MeleeMovement m = rec.Movements[mi++];
                if (m.Guid != MeleeRecording.Player && m.Guid != MeleeRecording.Chicken && m.Guid != MeleeRecording.TheChicken)
                {
                    continue;
                }

                handler.HandleMessage(0xF74C, m.Body);
                if (m.Guid == MeleeRecording.Player && m.Type == 6)
                {
                    controlledAfterMoveTo.Add(input.ControlledByServer && player.IsMovingTo());
                }
            }

            while (ui < rec.Updates.Count && rec.Updates[ui].T <= now)
            {
                MeleeUpdate u = rec.Updates[ui++];
                if (u.Guid != MeleeRecording.Player)
                {
                    handler.HandleMessage(0xF748, u.Body);
                }
            }

            input.UseTime();
            world.Tick(now);
            OutboundMessages o = input.TakeOutbound();
            if (now >= 19.2)
            {
                if ((o & OutboundMessages.MoveToState) != 0)
                {
                    sent.Add((now, "0xF61C", BinaryPrimitives.ReadUInt16LittleEndian(input.MoveToStateBody[^10..])));
                }

                if ((o & OutboundMessages.AutonomousPosition) != 0)
                {
                    sent.Add((now, "0xF753", BinaryPrimitives.ReadUInt16LittleEndian(input.AutonomousPositionBody[^10..])));
                }
            }
        }

        foreach (var r in recorded) output.WriteLine($"retail  {r.T,8:F3} {r.Action} server control {r.ServerControl}");
        foreach (var r in sent) output.WriteLine($"library {r.T,8:F3} {r.Action} server control {r.ServerControl}");

        // Four approaches before 45 s, each under server control while it moves.
        Assert.Equal([true, true, true, true], controlledAfterMoveTo);
        // No MoveToState in either stream; each library AutonomousPosition carries the stamp of the nearest recorded one.
        Assert.DoesNotContain(recorded, r => r.Action == "0xF61C");
        Assert.DoesNotContain(sent, r => r.Action == "0xF61C");
        Assert.NotEmpty(sent);
        foreach (var s in sent)
        {
            (double T, string Action, ushort ServerControl) nearest = recorded[0];
            foreach (var r in recorded)
            {
                if (Math.Abs(r.T - s.T) < Math.Abs(nearest.T - s.T))
                {
                    nearest = r;
                }
            }

            Assert.Equal(nearest.ServerControl, s.ServerControl);
        }
    }
}
