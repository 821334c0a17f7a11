using System;
using System.Collections.Generic;
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
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// The same player motion — walk, turn while walking, run while turning, stop turning, stop — through the stand-in
/// (<see cref="SpeedOnlyMotionPlayer"/>) and through the retail motion table path (a humanoid-like table read from bytes,
/// <see cref="HumanoidMotionTable"/>, played by <c>MotionTableManager</c> / <c>CMotionTable::GetObjectSequence</c> onto an
/// <see cref="AnimSequence"/>), on flat ground, 0.05 s ticks.
/// </summary>
public class HumanoidTablePathTests
{
    private static PhysicsWorld FlatWorld()
    {
        var terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        return SweepScene.Physics(terrain, out _);
    }

    private static PhysicsObj Player(IPartArray parts)
    {
        PhysicsWorld world = FlatWorld();
        PhysicsObj obj = world.CreateObject(1);
        obj.Weenie = new PlayerWeenie { RunSkill = 200 };
        obj.PartArray = parts;
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4);
        Assert.True(obj.EnterWorld(new Position(cell, new Vector3(100f, 60f, 20f))));
        world.Player = obj;
        return obj;
    }

    private static SimplePartArray StandIn()
    {
        SimplePartArray p = Walkers.OneSphere();
        p.MotionPlayer = new SpeedOnlyMotionPlayer();
        return p;
    }

    private static SimplePartArray TableOnSimpleParts()
    {
        SimplePartArray p = Walkers.OneSphere();
        p.MotionPlayer = new MotionTablePlayer(MotionTable.UnPack(HumanoidMotionTable.Bytes()));
        return p;
    }

    private static AnimatedPartArray TableOnAnimatedParts()
    {
        var setup = new SetupPhysics(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) }, ReadOnlySpan<CylSphere>.Empty,
            0f, 0f, 0.6f, 0.6f);
        var lib = new AnimationLibrary();
        foreach (uint id in new[] { HumanoidMotionTable.ReadyAnim, HumanoidMotionTable.WalkAnim, HumanoidMotionTable.RunAnim })
        {
            lib.Add(AnimClip.UnPack(new AnimationBytes(id).Frame().ToArray()));
        }

        return new AnimatedPartArray(setup, 1, MotionTable.UnPack(HumanoidMotionTable.Bytes()), lib);
    }

    private readonly record struct Step(Vector3 Origin, float Qw, float Qx, float Qy, float Qz, Vector3 V, Vector3 W);

    // Walk 1 s, turn right while walking 1 s, run (run key) while turning 1 s, stop turning 0.5 s, stop 0.5 s.
    private static List<Step> Drive(PhysicsObj player)
    {
        var steps = new List<Step>();
        MovementManager mm = MovementManager.Of(player);
        IMotionPlayer table = player.PartArray!.MotionPlayer!;
        void Run(int n) => SweepScene.Run(player.World, n, _ =>
        {
            Frame f = player.Position.Frame;
            steps.Add(new Step(f.Origin, f.Qw, f.Qx, f.Qy, f.Qz, table.Velocity, table.Omega));
        });

        Assert.Equal(MotionError.None, mm.DoMotion(MotionCommand.WalkForward, new MovementParameters()));
        Run(20);
        Assert.Equal(MotionError.None, mm.DoMotion(MotionCommand.TurnRight, new MovementParameters()));
        Run(20);
        Assert.Equal(MotionError.None, mm.DoMotion(MotionCommand.WalkForward, new MovementParameters { HoldKeyToApply = HoldKey.Run }));
        Run(20);
        Assert.Equal(MotionError.None, mm.StopMotion(MotionCommand.TurnRight, new MovementParameters()));
        Run(10);
        Assert.Equal(MotionError.None, mm.StopMotion(MotionCommand.WalkForward, new MovementParameters()));
        Run(10);
        return steps;
    }

    [Fact]
    public void RealTableOnTheSimplePartArray_MovesThePlayerBitForBitAsTheStandIn()
    {
        List<Step> standIn = Drive(Player(StandIn()));
        List<Step> real = Drive(Player(TableOnSimpleParts()));

        Assert.Equal(standIn.Count, real.Count);
        for (int i = 0; i < standIn.Count; i++)
        {
            Assert.Equal(standIn[i], real[i]);   // record equality: every float compared exactly
        }

        // It moved: walked, turned, ran and stopped (run rate 2.375 at skill 200: 4 × 2.375 = 9.5 m/s).
        Assert.Equal(0x4047AE14u, BitConverter.SingleToUInt32Bits(real[10].V.Y));  // 3.12f walking
        Assert.Equal(0xBFC00000u, BitConverter.SingleToUInt32Bits(real[30].W.Z));  // -1.5f turning
        Assert.Equal(9.5f, real[50].V.Y);
        Assert.Equal(Vector3.Zero, real[^1].V);
        Assert.Equal(Vector3.Zero, real[^1].W);
    }

    [Fact]
    public void RealTableOnTheAnimatedPartArray_MovesThePlayerBitForBitAsTheStandIn()
    {
        // The real path: the sequence plays each cycle's one animation at framerate 0 (a held pose): update_internal crosses
        // no frame and applies the velocity and omega over the whole quantum (acclient.c:339892), as the stand-in's
        // SimplePartArray does. apply_physics keeps the y and z displacements in a float temporary before adding them
        // (AnimSequence.ApplyPhysics), SimplePartArray.Update adds in double and rounds once; the two agree here because
        // the step's offset frame starts at the identity (origin +0): (float)((float)(s·v) + 0) = (float)(s·v + 0). They
        // would differ in the last bit after a root-motion frame moved the offset first (real animations).
        List<Step> standIn = Drive(Player(StandIn()));
        List<Step> real = Drive(Player(TableOnAnimatedParts()));

        Assert.Equal(standIn.Count, real.Count);
        for (int i = 0; i < standIn.Count; i++)
        {
            Assert.Equal(standIn[i], real[i]);   // origin, quaternion, velocity and omega: every float exactly
        }

        Assert.Equal(0xBFC00000u, BitConverter.SingleToUInt32Bits(real[30].W.Z));  // it turned
        Assert.Equal(9.5f, real[50].V.Y);                                          // it ran
    }
}
