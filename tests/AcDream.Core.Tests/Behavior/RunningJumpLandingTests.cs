using System;
using System.Numerics;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

// Issue #25 item 1, the running-jump landing burst: retail keeps the launch velocity on landing and lets friction take
// it off while the run's root motion starts again, so just after touchdown the body moves at root motion + kept velocity.
// Retail path: CMotionInterp::LeaveGround (acclient.c:344456) sets the local velocity get_leave_ground_velocity = state
// velocity (the run) with z = the jump's vz; in the air UpdatePositionInternal (acclient.c:319988) scales the root motion
// by 0 (not ON_WALKABLE) and calc_friction (acclient.c:316090) does nothing (not ON_WALKABLE). Landing:
// SetPositionInternal (322503) -> set_on_walkable(1) (318501) -> MovementManager::HitGround -> CMotionInterp::HitGround
// (acclient.c:344428), which only calls RemoveLinkAnimations and apply_current_movement (the motion table plays the run
// again; no velocity is set), and handle_all_collisions (acclient.c:321807) bounces only
// the component along the collision normal (+z) by (1 + elasticity). Nothing clears the horizontal velocity: it decays
// by calc_friction's (1 - 0.95)^dt on the ground until |v|^2 - 0.0625 < 0.0002 zeroes it (UpdatePhysicsInternal).
public class RunningJumpLandingTests
{
    private static PhysicsObj RunningPlayer(out PhysicsWorld world, out MovementManager mm)
    {
        var terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        world = SweepScene.Physics(terrain, out _);
        PhysicsObj obj = world.CreateObject(1);
        obj.Weenie = new PlayerWeenie { RunSkill = 200, JumpSkill = 100 };
        var parts = Walkers.OneSphere();
        parts.MotionPlayer = new SpeedOnlyMotionPlayer();
        obj.PartArray = parts;
        Assert.True(obj.EnterWorld(new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 1), new Vector3(100f, 30f, 20f))));
        world.Player = obj;
        mm = MovementManager.Of(obj);
        Assert.Equal(MotionError.None, mm.DoMotion(MotionCommand.WalkForward, new MovementParameters { HoldKeyToApply = HoldKey.Run }));
        SweepScene.Run(world, 4);
        return obj;
    }

    [Fact]
    public void RunningJump_LandsWithTheLaunchVelocityKept_ThenFrictionDecaysItOnTopOfTheRun()
    {
        PhysicsObj p = RunningPlayer(out PhysicsWorld world, out MovementManager mm);
        MotionInterp mi = mm.GetOrCreateMotionInterpreter();
        // Run skill 200: 4 * 2.375 = 9.5 m/s. Jump skill 100 at extent 0.5: vz = 4.003748 (MotionInterpJumpTests).
        Assert.Equal(MotionError.None, mi.Jump(0.5f, out _));
        Assert.Equal(9.5f, p.Velocity.Y);

        int landing = -1;
        for (int i = 0; i < 40 && landing < 0; i++)
        {
            SweepScene.Run(world, 1);
            if ((p.TransientState & TransientState.OnWalkable) != 0)
            {
                landing = i;
            }
        }

        Assert.True(landing > 0, "the jump never landed");
        // At touchdown the horizontal velocity is the launch's 9.5 m/s, untouched: the bounce acts along +z only (adds
        // 0 * impulse to y) and no friction ran in the air. The bounce leaves z = 0.05 * |vz at impact| (about 0.2 m/s).
        Assert.Equal(9.5f, p.Velocity.Y);
        Assert.Equal(0f, p.Velocity.X);
        Assert.InRange(p.Velocity.Z, 0f, 0.25f);

        // First tick on the ground (0.05 s): calc_friction removes the normal component (v . N = 0.2 < 0.25), then
        // scales by (1 - 0.95)^0.05 = exp(0.05 ln 0.05) = 0.8608917; v = 9.5 * 0.8608917 = 8.178471. The step is the run's
        // root motion 0.05 * 9.5 = 0.475 plus 0.05 * 8.178471 = 0.4089236: 0.8839236 m (17.68 m/s).
        double f = Math.Pow(0.05, 0.05);
        float y0 = p.Position.Frame.Origin.Y;
        SweepScene.Run(world, 1);
        Assert.Equal(9.5 * f, p.Velocity.Y, 4);
        Assert.Equal(0f, p.Velocity.Z);
        Assert.Equal(0.475 + 0.05 * 9.5 * f, p.Position.Frame.Origin.Y - y0, 4);

        // The first second on the ground (20 ticks): 20 * 0.475 = 9.5 m of run plus 0.475 * sum_{k=1..20} f^k
        // = 0.475 * f (1 - f^20) / (1 - f) with f^20 = 0.05 exactly: 0.475 * 0.8608917 * 0.95 / 0.1391083 = 2.792625;
        // 12.292625 m in all (against 9.5 m for the run alone).
        SweepScene.Run(world, 19);
        double expected = 20 * 0.475 + 0.475 * f * (1 - Math.Pow(f, 20)) / (1 - f);
        Assert.Equal(12.292625, expected, 5);
        Assert.Equal(expected, p.Position.Frame.Origin.Y - y0, 3);

        // Zeroed when |v|^2 - 0.0625 < 0.0002 at the start of a tick: v_n = 9.5 f^n; v_24 = 0.2609 (0.06807 - 0.0625 =
        // 0.0056, kept), v_25 = 0.2246 (0.0504, zeroed in the 26th tick on the ground).
        SweepScene.Run(world, 4);   // 24 ticks: v_24
        Assert.Equal(9.5 * Math.Pow(f, 24), p.Velocity.Y, 4);
        SweepScene.Run(world, 1);   // 25
        Assert.NotEqual(0f, p.Velocity.Y);
        SweepScene.Run(world, 1);   // 26
        Assert.Equal(Vector3.Zero, p.Velocity);
    }
}
