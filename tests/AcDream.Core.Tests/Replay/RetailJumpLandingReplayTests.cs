using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Numerics;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Replay;

// Issue #25 item 1 against the real recordings: the only jumps the retail client recorded (fellowship-one-vassal, Ash,
// three F61B Jump actions at t 551.7, 553.3, 554.9) are standing jumps: velocity (0, 0, vz). After the first two the client
// sent its pose again 0.79 s and 0.69 s later (F61C, after landing): the same x and y as before the jump, to the last
// digit. (After the third the next pose is 3.7 s later, F753 at 558.66, when a walk had begun: 0.19 m further by 559.65.) A running jump (the landing
// burst) is not in any recording, so its horizontal speed after landing cannot be measured from retail's own poses; what
// can be compared is that a standing jump lands where it left, which the port does too.
public class RetailJumpLandingReplayTests
{
    private sealed class RecordedJumpWeenie(float vz) : IMotionWeenie
    {
        public bool IsThePlayer => true;
        public bool IsCreature => true;
        public bool IsPlayer => true;
        public bool IsImpenetrable => false;
        public bool IsPK => false;
        public bool IsPKLite => false;

        public bool InqRunRate(out float r)
        {
            r = 1f;
            return true;
        }

        public bool InqJumpVelocity(float extent, out float v)
        {
            v = vz;
            return true;
        }

        public bool CanJump(float extent) => true;

        public bool JumpStaminaCost(float extent, out int cost)
        {
            cost = 0;
            return true;
        }
    }

    [ReplayDataFact]
    public void StandingJumps_RetailLandsWhereItLeft_AndSoDoesThePort()
    {
        string[] rows = File.ReadAllLines(Path.Combine(SharedDataDir.Replay.Dir!, "fellowship-one-vassal_c2s_autonomous.csv"));
        var jumps = new List<(int Row, float Extent, Vector3 Velocity)>();
        for (int i = 1; i < rows.Length; i++)
        {
            string[] c = rows[i].Split(',');
            if (c[9] == "0xF61B")
            {
                // motion_or_jump: "extent=E vel=X/Y/Z"
                string[] parts = c[15].Split(' ');
                float extent = float.Parse(parts[0].Substring(7), CultureInfo.InvariantCulture);
                string[] v = parts[1].Substring(4).Split('/');
                jumps.Add((i, extent, new Vector3(F(v[0]), F(v[1]), F(v[2]))));
            }
        }

        Assert.Equal(3, jumps.Count);
        for (int j = 0; j < jumps.Count; j++)
        {
            var (row, extent, vel) = jumps[j];
            // The launch velocity has no horizontal part (nothing commanded: a standing jump), vz 3.42..3.57 m/s.
            Assert.Equal(0f, vel.X);
            Assert.Equal(0f, vel.Y);
            Assert.InRange(vel.Z, 3.4f, 3.6f);
            Assert.InRange(extent, 0.8f, 0.95f);
            if (j == 2)
            {
                continue;
            }

            // The last pose before the jump and the first after it (F61C rows, same cell, within 0.8 s): same x and y.
            string[] before = rows[row - 1].Split(',');
            string[] after = rows[row + 1].Split(',');
            Assert.Equal("0xF61C", after[9]);
            Assert.InRange(double.Parse(after[0], CultureInfo.InvariantCulture) - double.Parse(rows[row].Split(',')[0], CultureInfo.InvariantCulture), 0.6, 0.8);
            Assert.Equal(before[1], after[1]);
            Assert.Equal(F(before[2]), F(after[2]));
            Assert.Equal(F(before[3]), F(after[3]));
        }

        // The port: the same standing jump (launch velocity (0, 0, vz) from the weenie, nothing commanded) lands at the x and
        // y it left from, and after landing no horizontal velocity is left.
        var terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        PhysicsObj p = world.CreateObject(1);
        p.Weenie = new RecordedJumpWeenie(jumps[0].Velocity.Z);
        var pa = Walkers.OneSphere(0.48f, 0.6f, 1.5f);
        pa.MotionPlayer = new SpeedOnlyMotionPlayer();
        p.PartArray = pa;
        Assert.True(p.EnterWorld(new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4), new Vector3(100f, 100f, 20f))));
        world.Player = p;
        MovementManager mm = MovementManager.Of(p);
        SweepScene.Run(world, 2);
        Vector3 start = p.Position.Frame.Origin;
        Assert.Equal(MotionError.None, mm.GetOrCreateMotionInterpreter().Jump(jumps[0].Extent, out _));
        Assert.Equal(new Vector3(0f, 0f, jumps[0].Velocity.Z), p.Velocity);
        SweepScene.Run(world, 40);   // 2 s: airborne 2 vz / g = 0.73 s
        Assert.True((p.TransientState & TransientState.OnWalkable) != 0);
        Assert.Equal(start.X, p.Position.Frame.Origin.X);
        Assert.Equal(start.Y, p.Position.Frame.Origin.Y);
        Assert.Equal(0f, p.Velocity.X);
        Assert.Equal(0f, p.Velocity.Y);
    }

    private static float F(string s) => float.Parse(s, CultureInfo.InvariantCulture);
}
