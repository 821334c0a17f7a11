using System;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Allocation;

public class AnimatedPartArrayAllocationTests
{
    private const uint NonCombat = 0x8000003Du, Ready = 0x41000003u, Walk = 0x45000005u, Turn = 0x6500000Du, Wave = 0x13000087u;

    [Fact]
    public void WalkingTurningWavingAnimatedPlayer_TicksAndCommandsAllocateNothing_AfterWarmUp()
    {
        var terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        MotionTable table = MotionTable.UnPack(new MotionTableBytes { DefaultStyle = NonCombat }
            .StyleDefault(NonCombat, Ready)
            .Cycle(NonCombat, Ready, MotionDataSpec.One(0x03000001, 0, -1, 30f))
            .Cycle(NonCombat, Walk, MotionDataSpec.One(0x03000002, 0, -1, 30f, velocity: new Vector3(0f, 3.12f, 0f)))
            .Modifier(0, Turn, new MotionDataSpec(Array.Empty<(uint, int, int, float)>(), Omega: new Vector3(0f, 0f, -1.5f)))
            .Link(NonCombat, Ready, Walk, MotionDataSpec.One(0x03000003, 0, -1, 30f))
            .Link(NonCombat, Walk, Wave, MotionDataSpec.One(0x03000003, 0, -1, 30f))
            .ToArray());
        var lib = new AnimationLibrary();
        foreach (uint id in new uint[] { 0x03000001, 0x03000002, 0x03000003 })
        {
            var b = new AnimationBytes(id, 3);
            for (int i = 0; i < 8; i++)
            {
                b.Frame(new Vector3(0f, 0.001f, 0f), Quaternion.Identity);
            }

            lib.Add(AnimClip.UnPack(b.ToArray()));
        }

        PhysicsObj player = world.CreateObject(1);
        player.Weenie = new PlayerWeenie { RunSkill = 200 };
        var setup = new SetupPhysics(new[] { new Sphere(new Vector3(0f, 0f, 0.48f), 0.48f) }, ReadOnlySpan<CylSphere>.Empty,
            0.48f, 1.835f, 0.6f, 1.5f);
        var parts = new AnimatedPartArray(setup, 3, table, lib);
        player.PartArray = parts;
        Assert.True(player.EnterWorld(new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4), new Vector3(96f, 90f, 20f))));
        world.Player = player;
        MovementManager mm = MovementManager.Of(player);
        var p = new MovementParameters();
        Span<Frame> frames = stackalloc Frame[3];
        void Window()
        {
            for (int i = 0; i < 30; i++)
            {
                mm.DoMotion(MotionCommand.WalkForward, p);
                if (i % 10 == 0)
                {
                    mm.DoMotion(MotionCommand.TurnRight, p);
                    mm.DoMotion((MotionCommand)Wave, p);
                }
                else if (i % 10 == 5)
                {
                    mm.StopMotion(MotionCommand.TurnRight, p);
                }

                world.Tick(world.CurrentTime + 1.0 / 30.0);
            }
        }

        Window();   // warm-up: node pools and queues grown
        Window();
        AllocationProbe.AssertSteadyStateAllocatesNothing(Window);
        parts.CopyPartFrames(frames);
        Assert.Equal(MotionCommand.WalkForward, parts.Player!.Substate);
    }
}
