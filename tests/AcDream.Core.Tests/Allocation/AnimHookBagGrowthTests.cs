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

/// <summary>
/// Issue #34's soak spike (one tick of 77,432 B against a mean of 5 B): the object's anim-hook bag (retail's
/// <c>anim_hooks</c> list, acclient.c:322062, one heap node per hook; here an array that doubles) grows the first time one step
/// queues more hooks than ever before. Animation data played fast passes many frames in one step, each with its hooks: a
/// first-time cost per object (docs/performance.md), after which the same load allocates nothing.
/// </summary>
public class AnimHookBagGrowthTests
{
    private const uint NonCombat = 0x8000003Du, Ready = 0x41000003u, Walk = 0x45000005u;

    [Fact]
    public void AStepPassingTwoThousandFourHundredHooks_GrowsTheBagOnce_ThenAllocatesNothing()
    {
        var terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        MotionTable table = MotionTable.UnPack(new MotionTableBytes { DefaultStyle = NonCombat }
            .StyleDefault(NonCombat, Ready)
            .Cycle(NonCombat, Ready, MotionDataSpec.One(0x03000001, 0, -1, 30f))
            .Cycle(NonCombat, Walk, MotionDataSpec.One(0x03000002, 0, -1, 30f, velocity: new Vector3(0f, 3.12f, 0f)))
            .ToArray());
        var lib = new AnimationLibrary();
        foreach (uint id in new uint[] { 0x03000001, 0x03000002 })
        {
            // Eight frames, each with four sound hooks.
            var b = new AnimationBytes(id, 2);
            for (int i = 0; i < 8; i++)
            {
                b.Frame(new Vector3(0f, 0.001f, 0f), Quaternion.Identity);
                for (uint k = 0; k < 4; k++)
                {
                    b.Sound(0x0A000001u + k, AnimHookDirection.Both);
                }
            }

            lib.Add(AnimClip.UnPack(b.ToArray()));
        }

        PhysicsObj p = world.CreateObject(1);
        p.Weenie = new PlayerWeenie { RunSkill = 200 };
        var setup = new SetupPhysics(new[] { new Sphere(new Vector3(0f, 0f, 0.48f), 0.48f) }, ReadOnlySpan<CylSphere>.Empty,
            0.48f, 1.835f, 0.6f, 1.5f);
        p.PartArray = new AnimatedPartArray(setup, 2, table, lib);
        Assert.True(p.EnterWorld(new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4), new Vector3(96f, 90f, 20f))));
        world.Player = p;
        MovementManager mm = MovementManager.Of(p);
        for (int t = 0; t < 20; t++)
        {
            world.Tick(world.CurrentTime + 0.2); // Ready at speed 1: 6 frames, 24 hooks a step; the bag holds 32
        }

        // A walk at the largest motion speed, 100: 30 fps × 100 × 0.2 s = 600 frames a step, 2,400 hooks. The bag doubles
        // from 32 to 4,096 entries: arrays of 64, 128, ..., 4,096 references, 7 × 24 B of headers + 8 B × 8,128 = 65,192 B.
        mm.DoMotion((MotionCommand)Walk, new MovementParameters { Speed = InputLimits.MaxMotionSpeed });
        long before = GC.GetAllocatedBytesForCurrentThread();
        world.Tick(world.CurrentTime + 0.2);
        Assert.Equal(65_192L, GC.GetAllocatedBytesForCurrentThread() - before);

        // The same load again: nothing.
        before = GC.GetAllocatedBytesForCurrentThread();
        for (int t = 0; t < 50; t++)
        {
            world.Tick(world.CurrentTime + 0.2);
        }

        Assert.Equal(0L, GC.GetAllocatedBytesForCurrentThread() - before);
    }
}
