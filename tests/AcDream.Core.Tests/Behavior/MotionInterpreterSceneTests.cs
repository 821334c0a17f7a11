using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Shared;
using Xunit;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Core.Tests.Behavior;

// A player and a remote creature moved by the motion interpreter on flat ground (z = 20), the body moved by the
// SpeedOnlyMotionPlayer through the part array's root motion.
public class MotionInterpreterSceneTests
{
    private static PhysicsWorld FlatWorld()
    {
        var terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        return SweepScene.Physics(terrain, out _);
    }

    private static PhysicsObj Creature(PhysicsWorld world, uint id, IMotionWeenie weenie, Vector3 at)
    {
        PhysicsObj obj = world.CreateObject(id);
        obj.Weenie = weenie;
        var parts = Walkers.OneSphere();
        parts.MotionPlayer = new SpeedOnlyMotionPlayer();
        obj.PartArray = parts;
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4);
        Assert.True(obj.EnterWorld(new Position(cell, at)));
        return obj;
    }

    [Theory]
    // Walk: 3.12 m/s. Run with skill 200: rate 2.375, 4 * 2.375 = 9.5 m/s. Each 0.05 s tick is one step.
    [InlineData(false, 3.12)]
    [InlineData(true, 9.5)]
    public void Player_OnFlatGround_MovesAtExactlyTheRetailSpeed(bool run, double speed)
    {
        PhysicsWorld world = FlatWorld();
        PhysicsObj player = Creature(world, 1, new PlayerWeenie { RunSkill = 200 }, new Vector3(100f, 40f, 20f));
        world.Player = player;
        MovementManager mm = MovementManager.Of(player);
        Assert.Equal(MotionError.None, mm.DoMotion(MotionCommand.WalkForward, new MovementParameters { HoldKeyToApply = run ? HoldKey.Run : HoldKey.None }));

        SweepScene.Run(world, 2);   // the first tick after the command starts the step
        float y0 = player.Position.Frame.Origin.Y;
        const int n = 40;           // 2 s: 6.24 m walking, 19 m running, inside the landblock
        float prev = y0;
        SweepScene.Run(world, n, _ =>
        {
            float y = player.Position.Frame.Origin.Y;
            // Each step moves (float)(0.05 * v) along +Y (heading 0 = north), to float precision of the origin.
            Assert.Equal(0.05 * speed, y - prev, 4);
            prev = y;
            Assert.Equal(20f, player.Position.Frame.Origin.Z);
            Assert.Equal(100f, player.Position.Frame.Origin.X);
        });

        Assert.Equal(speed, (player.Position.Frame.Origin.Y - y0) / (n * 0.05), 3);
        Assert.Equal(speed, player.CachedVelocity.Y, 3);
    }

    [Fact]
    public void Player_Turning_1_5RadPerSecond_Turns85_94DegreesInOneSecond()
    {
        PhysicsWorld world = FlatWorld();
        PhysicsObj player = Creature(world, 1, new PlayerWeenie(), new Vector3(100f, 100f, 20f));
        world.Player = player;
        MovementManager mm = MovementManager.Of(player);
        mm.DoMotion(MotionCommand.TurnRight, new MovementParameters());
        SweepScene.Run(world, 1);
        double h0 = player.Position.Frame.Heading;
        SweepScene.Run(world, 20);   // 1 s at 1.5 rad/s clockwise: heading + 1.5 × 180/π = 85.943669°
        double turned = player.Position.Frame.Heading - h0;
        Assert.Equal(1.5 * 180.0 / Math.PI, (turned + 360.0) % 360.0, 2);
    }

    [Fact]
    public void Player_Jump_OnFlatGround_RisesLandsAndWalksOn()
    {
        PhysicsWorld world = FlatWorld();
        PhysicsObj player = Creature(world, 1, new PlayerWeenie { RunSkill = 200, JumpSkill = 300 }, new Vector3(100f, 40f, 20f));
        world.Player = player;
        MovementManager mm = MovementManager.Of(player);
        MotionInterp mi = mm.GetOrCreateMotionInterpreter();
        var table = (SpeedOnlyMotionPlayer)player.PartArray!.MotionPlayer!;
        mm.DoMotion(MotionCommand.WalkForward, new MovementParameters());
        SweepScene.Run(world, 2);

        // A full jump: v_z = 9.086529 (skill 300, extent 1); the flight lasts 2 * 9.0865 / 9.8 = 1.854 s (38 ticks).
        Assert.Equal(MotionError.None, mi.Jump(1f, out _));
        Assert.Equal(MotionCommand.Falling, table.Substate);
        float top = 20f;
        int airborne = 0;
        SweepScene.Run(world, 60, _ =>
        {
            top = Math.Max(top, player.Position.Frame.Origin.Z);
            if ((player.TransientState & TransientState.OnWalkable) == 0)
            {
                airborne++;
            }
        });

        // Apex h = v² / 2g = 82.565 / 19.6 = 4.2125 m (the jump height), reached within one step's drift.
        Assert.InRange(top - 20f, 4.0f, 4.3f);
        Assert.InRange(airborne, 35, 40);
        // Landed: on the ground, the walk plays again and the jump charge is spent.
        Assert.Equal(20f, player.Position.Frame.Origin.Z);
        Assert.Equal(MotionCommand.WalkForward, table.Substate);
        Assert.Equal(0f, mi.JumpExtent);
        Assert.Equal(3.12f, table.Velocity.Y);
    }

    [Fact]
    public void RemoteCreature_FedAMovementEvent_RunsAtItsServerRunRate()
    {
        PhysicsWorld world = FlatWorld();
        PhysicsObj player = Creature(world, 1, new PlayerWeenie(), new Vector3(20f, 20f, 20f));
        world.Player = player;
        PhysicsObj remote = Creature(world, 2, RemoteCreatureWeenie.Player, new Vector3(100f, 40f, 20f));

        // The server says: RunForward at 2.8256 (its run rate), no side-step, no turn.
        var state = new InterpretedMotionState { ForwardCommand = MotionCommand.RunForward, ForwardSpeed = 2.8256f };
        Assert.True(MovementEvent.ApplyInterpretedMotion(remote, state));
        MotionInterp mi = MovementManager.Of(remote).GetOrCreateMotionInterpreter();
        Assert.Equal(2.8256f, mi.MyRunRate);   // apply_interpreted_movement takes the run's speed as the run rate
        Assert.Equal(new Vector3(0f, 4f * 2.8256f, 0f), mi.StateVelocity);

        SweepScene.Run(world, 2);
        float y0 = remote.Position.Frame.Origin.Y;
        SweepScene.Run(world, 20);
        // 4 * 2.8256 = 11.3024 m/s for 1 s.
        Assert.Equal(11.3024, remote.Position.Frame.Origin.Y - y0, 2);

        // A stop event: Ready.
        Assert.True(MovementEvent.ApplyInterpretedMotion(remote, new InterpretedMotionState()));
        SweepScene.Run(world, 2);
        float y1 = remote.Position.Frame.Origin.Y;
        SweepScene.Run(world, 10);
        Assert.Equal(y1, remote.Position.Frame.Origin.Y);
    }
}
