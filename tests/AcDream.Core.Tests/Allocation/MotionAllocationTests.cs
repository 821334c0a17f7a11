using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Shared;
using Xunit;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Core.Tests.Allocation;

public class MotionAllocationTests
{
    [Fact]
    public void RunningTurningPlayer_CommandsAndMovementEvents_AllocateNothing_AfterWarmUp()
    {
        var terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4);
        PhysicsObj player = world.CreateObject(1);
        player.Weenie = new PlayerWeenie { RunSkill = 200, JumpSkill = 200 };
        var parts = Walkers.OneSphere();
        parts.MotionPlayer = new SpeedOnlyMotionPlayer();
        player.PartArray = parts;
        Assert.True(player.EnterWorld(new Position(cell, new Vector3(96f, 90f, 20f))));
        world.Player = player;
        PhysicsObj remote = world.CreateObject(2);
        remote.Weenie = RemoteCreatureWeenie.Player;
        var rparts = Walkers.OneSphere();
        rparts.MotionPlayer = new SpeedOnlyMotionPlayer();
        remote.PartArray = rparts;
        Assert.True(remote.EnterWorld(new Position(cell, new Vector3(90f, 90f, 20f))));

        MovementManager mm = MovementManager.Of(player);
        MotionInterp mi = mm.GetOrCreateMotionInterpreter();
        var walk = new MovementParameters { HoldKeyToApply = HoldKey.Run };
        var turn = new MovementParameters();
        var run = new InterpretedMotionState { ForwardCommand = MotionCommand.RunForward, ForwardSpeed = 2.375f,
            TurnCommand = MotionCommand.TurnRight, TurnSpeed = 1f };
        var stop = new InterpretedMotionState();
        void Window()
        {
            for (int i = 0; i < 30; i++)
            {
                mm.DoMotion(MotionCommand.WalkForward, walk);
                mm.DoMotion(MotionCommand.TurnRight, turn);
                mi.SetHoldRun(i % 2 == 0, cancelMoveToOnChange: false);
                MovementEvent.ApplyInterpretedMotion(remote, i % 3 == 0 ? stop : run);
                world.Tick(world.CurrentTime + 1.0 / 30.0);
            }
        }

        Window();   // warm-up: managers created, tables filled
        AllocationProbe.AssertSteadyStateAllocatesNothing(Window);
    }
}
