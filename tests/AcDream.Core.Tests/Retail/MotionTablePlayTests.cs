using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;

using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using AcDream.Core.Fixtures.Data;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// The retail motion table played end to end (<c>MotionTableManager::PerformMovement</c> -> <c>CMotionTable::GetObjectSequence</c>
/// -> <c>CSequence</c>; AnimDone hooks -> <c>MotionTableManager::AnimationDone</c> -> <c>CPhysicsObj::MotionDone</c>), with
/// a table and animations written to the decompiled layouts. Every clip plays at 10 frames per second and each step is
/// 0.1 s (float 0.1f = 0.100000001490116 s, so a step advances 1.0000000149 frames: a clip of n frames, played from frame
/// 0 with high frame n − 1, ends — frame number past n − 1 + 1 — at its n-th step, the tiny excess carried into the next).
/// </summary>
public class MotionTablePlayTests
{
    private const uint NonCombat = 0x8000003Du, HandCombat = 0x8000003Cu, Ready = 0x41000003u, Walk = 0x45000005u;
    private const uint Sitting = 0x41000013u, Turn = 0x6500000Du, Wave = 0x13000087u, Attack = 0x10000062u;

    // Clip ids and frame counts.
    private const uint RClip = 0x03000001, WClip = 0x03000002, L1Clip = 0x03000003, L2Clip = 0x03000004, WaveClip = 0x03000005;
    private const uint WalkToReadyClip = 0x03000006, AttackClip = 0x03000007, SitClip = 0x03000008, SitDownClip = 0x03000009;
    private const uint StandUpClip = 0x0300000A, HcClip = 0x0300000B, ToHcClip = 0x0300000C;

    private static MotionDataSpec Clip(uint id, Vector3 velocity = default) => MotionDataSpec.One(id, 0, -1, 10f, velocity);

    private static MotionTable Table() => MotionTable.UnPack(new MotionTableBytes { DefaultStyle = NonCombat }
        .StyleDefault(NonCombat, Ready)
        .StyleDefault(HandCombat, Ready)
        .Cycle(NonCombat, Ready, Clip(RClip))
        .Cycle(NonCombat, Walk, Clip(WClip, new Vector3(0f, 3.12f, 0f)))
        .Cycle(NonCombat, Sitting, Clip(SitClip))
        .Cycle(HandCombat, Ready, Clip(HcClip))
        .Modifier(0, Turn, new MotionDataSpec(Array.Empty<(uint, int, int, float)>(), Omega: new Vector3(0f, 0f, -1.5f)))
        // Ready -> Walk: a two-animation link (3 + 2 frames).
        .Link(NonCombat, Ready, Walk, new MotionDataSpec(new[] { (L1Clip, 0, -1, 10f), (L2Clip, 0, -1, 10f) }))
        .Link(NonCombat, Walk, Ready, Clip(WalkToReadyClip))
        .Link(NonCombat, Walk, Wave, Clip(WaveClip))
        .Link(NonCombat, Ready, Wave, Clip(WaveClip))
        .Link(NonCombat, Ready, Attack, Clip(AttackClip))
        .Link(NonCombat, Ready, Sitting, Clip(SitDownClip))
        .Link(NonCombat, Sitting, Ready, Clip(StandUpClip))
        .Link(NonCombat, Ready, HandCombat, Clip(ToHcClip))
        .ToArray());

    private static AnimationLibrary Clips()
    {
        var lib = new AnimationLibrary();
        void Add(uint id, int frames)
        {
            var b = new AnimationBytes(id);
            for (int i = 0; i < frames; i++)
            {
                b.Frame();
            }

            lib.Add(AnimClip.UnPack(b.ToArray()));
        }

        Add(RClip, 1);
        Add(WClip, 4);
        Add(L1Clip, 3);
        Add(L2Clip, 2);
        Add(WaveClip, 3);
        Add(WalkToReadyClip, 2);
        Add(AttackClip, 3);
        Add(SitClip, 1);
        Add(SitDownClip, 2);
        Add(StandUpClip, 3);
        Add(HcClip, 1);
        Add(ToHcClip, 2);
        return lib;
    }

    /// <summary>Records the motions the part array reports done.</summary>
    private sealed class Recorder : IMovementManager
    {
        public readonly List<(MotionCommand Motion, bool Success, int Step)> Done = new();
        public int Step;

        public void UseTime()
        {
        }

        public void LeaveGround()
        {
        }

        public void HitGround()
        {
        }

        public bool IsMovingTo() => false;

        public void HandleEnterWorld()
        {
        }

        public IMotionInterpreter? MotionInterpreter => null;

        public void MotionDone(MotionCommand motion, bool success) => Done.Add((motion, success, Step));
    }

    private static (PhysicsObj Obj, AnimatedPartArray Parts, MotionTablePlayer Player, Recorder Rec) Create()
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = world.CreateObject(1);
        var setup = new SetupPhysics(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) }, ReadOnlySpan<CylSphere>.Empty, 0.5f, 1f, 0.6f, 0.6f);
        var parts = new AnimatedPartArray(setup, 1, Table(), Clips());
        obj.PartArray = parts;
        var rec = new Recorder();
        obj.Movement = rec;
        MotionTablePlayer player = parts.Player!;
        player.InitializeMotionTables();
        obj.CheckForCompletedMotions();
        rec.Done.Clear();
        return (obj, parts, player, rec);
    }

    // One 0.1 s step as the object's tick orders it: the sequence's update, then process_hooks (the AnimDone hooks).
    private static void Steps(PhysicsObj obj, AnimatedPartArray parts, Recorder rec, int n)
    {
        for (int i = 0; i < n; i++)
        {
            rec.Step++;
            Frame f = Frame.Identity;
            parts.Update(0.1f, ref f);
            obj.ProcessHooks();
        }
    }

    private static MovementParameters P(float speed = 1f) => new() { Speed = speed };

    [Fact]
    public void TwoAnimationLinkThenCycle_MotionDoneOnce_AtTheFifthStep()
    {
        (PhysicsObj obj, AnimatedPartArray parts, MotionTablePlayer player, Recorder rec) = Create();

        // GetObjectSequence, substate path: link Ready->Walk (2 anims) + Walk cycle (1): num_anims = 2 + 0 + 1 - 1 = 2.
        Assert.Equal(MotionError.None, player.DoInterpretedMotion((MotionCommand)Walk, P()));
        Assert.Equal(3, parts.Sequence.AnimationCount);        // L1, L2, W (the Ready cycle removed)
        Assert.Equal(2, parts.Sequence.LinkAnimationCount);
        Assert.Equal(L1Clip, parts.Sequence.CurrentAnimation!.Id);
        Assert.Equal(0x4047AE14u, BitConverter.SingleToUInt32Bits(player.Velocity.Y)); // 3.12f: the cycle's, set last

        // L1 (3 frames) ends at step 3: AnimDone, counter 1 < 2. L2 (2 frames) ends at step 5: counter 2 -> Walk done.
        Steps(obj, parts, rec, 3);
        Assert.Empty(rec.Done);
        Assert.Equal(L2Clip, parts.Sequence.CurrentAnimation!.Id);
        Steps(obj, parts, rec, 2);
        Assert.Equal(new[] { ((MotionCommand)Walk, true, 5) }, rec.Done);
        Assert.Equal(WClip, parts.Sequence.CurrentAnimation!.Id);

        // The cycle loops (4 frames, then from its first again) and nothing more is reported.
        Steps(obj, parts, rec, 12);
        Assert.Single(rec.Done);
        Assert.Equal(WClip, parts.Sequence.CurrentAnimation!.Id);
        Assert.Equal(1, parts.Sequence.AnimationCount);
        Assert.Equal(0, player.PendingMotionCount);
    }

    [Fact]
    public void WaveWhileWalking_KeepsTheWalk_TheActionEndsWithItsLink()
    {
        (PhysicsObj obj, AnimatedPartArray parts, MotionTablePlayer player, Recorder rec) = Create();
        player.DoInterpretedMotion((MotionCommand)Walk, P());
        Steps(obj, parts, rec, 5);
        rec.Done.Clear();
        rec.Step = 0;

        // Action path with a direct link Walk->Wave: add_action, link (1 anim) then the walk cycle again at substate_mod;
        // num_anims = 1. The velocity is the walk cycle's (add_motion of the cycle comes last).
        Assert.Equal(MotionError.None, player.DoInterpretedMotion((MotionCommand)Wave, P()));
        Assert.Equal(1, player.ActionCount);
        Assert.Equal((MotionCommand)Walk, player.Substate);
        Assert.Equal(0x4047AE14u, BitConverter.SingleToUInt32Bits(player.Velocity.Y));
        Assert.Equal(WaveClip, parts.Sequence.CurrentAnimation!.Id);

        Steps(obj, parts, rec, 3);   // the wave link: 3 frames
        Assert.Equal(new[] { ((MotionCommand)Wave, true, 3) }, rec.Done);
        Assert.Equal(0, player.ActionCount);   // remove_action_head as the action is done
        Assert.Equal(WClip, parts.Sequence.CurrentAnimation!.Id);
    }

    [Fact]
    public void AttackInterruptsTheWalkCycle_ThroughReady_AndReturnsToIt()
    {
        (PhysicsObj obj, AnimatedPartArray parts, MotionTablePlayer player, Recorder rec) = Create();
        player.DoInterpretedMotion((MotionCommand)Walk, P());
        Steps(obj, parts, rec, 5);
        rec.Done.Clear();
        rec.Step = 0;

        // No Walk->Attack link: Walk->Ready (1 anim), Ready->Attack (1), Ready->Walk (2), the walk cycle;
        // num_anims = 1 + 1 + 2 = 4.
        Assert.Equal(MotionError.None, player.DoInterpretedMotion((MotionCommand)Attack, P()));
        Assert.Equal(5, parts.Sequence.AnimationCount);
        Assert.Equal(WalkToReadyClip, parts.Sequence.CurrentAnimation!.Id);
        Assert.Equal((MotionCommand)Walk, player.Substate);

        // The links end at steps 2 (2 frames), 5 (3), 8 (3), 10 (2): the attack is done at the fourth, step 10.
        Steps(obj, parts, rec, 9);
        Assert.Empty(rec.Done);
        Assert.Equal(L2Clip, parts.Sequence.CurrentAnimation!.Id);
        Steps(obj, parts, rec, 1);
        Assert.Equal(new[] { ((MotionCommand)Attack, true, 10) }, rec.Done);
        Assert.Equal(WClip, parts.Sequence.CurrentAnimation!.Id);
        Assert.Equal(0, player.ActionCount);
    }

    [Fact]
    public void TurnModifierOnTheWalk_ThenStopCompletely_BackToReadyWithNothingMoving()
    {
        (PhysicsObj obj, AnimatedPartArray parts, MotionTablePlayer player, Recorder rec) = Create();
        player.DoInterpretedMotion((MotionCommand)Walk, P());
        Steps(obj, parts, rec, 5);
        // A modifier: combine_motion on the walk; num_anims 0 (done at the next check).
        Assert.Equal(MotionError.None, player.DoInterpretedMotion((MotionCommand)Turn, P()));
        Assert.Equal(1, player.ModifierCount);
        Assert.Equal(0xBFC00000u, BitConverter.SingleToUInt32Bits(player.Omega.Z));
        Assert.Equal(0x4047AE14u, BitConverter.SingleToUInt32Bits(player.Velocity.Y));

        // StopObjectCompletely: the turn subtracted and removed, then the walk stopped: GetObjectSequence(Ready, stop) via
        // the Walk->Ready link; num_anims = 1 + 0 + 1 - 1 = 1.
        Assert.Equal(MotionError.None, player.StopCompletely());
        Assert.Equal(0, player.ModifierCount);
        Assert.Equal((MotionCommand)Ready, player.Substate);
        Assert.Equal(Vector3.Zero, player.Velocity);
        Assert.Equal(Vector3.Zero, player.Omega);
        rec.Done.Clear();
        rec.Step = 0;
        Steps(obj, parts, rec, 2);   // the Walk->Ready link: 2 frames
        Assert.Contains(((MotionCommand)Ready, true, 2), rec.Done);
        Assert.Equal(RClip, parts.Sequence.CurrentAnimation!.Id);
    }

    [Fact]
    public void StyleChange_PlaysTheStyleLinkThenTheNewStylesDefaultCycle()
    {
        (PhysicsObj obj, AnimatedPartArray parts, MotionTablePlayer player, Recorder rec) = Create();
        // Style path: no pre-link (already in Ready), link NonCombat Ready -> HandCombat, HandCombat's Ready cycle;
        // num_anims = 1 + 0 + 1 + 0 - 1 = 1.
        Assert.Equal(MotionError.None, player.DoInterpretedMotion((MotionCommand)HandCombat, P()));
        Assert.Equal((MotionCommand)HandCombat, player.Style);
        Assert.Equal((MotionCommand)Ready, player.Substate);
        Assert.Equal(ToHcClip, parts.Sequence.CurrentAnimation!.Id);
        Steps(obj, parts, rec, 2);
        Assert.Equal(new[] { ((MotionCommand)HandCombat, true, 2) }, rec.Done);
        Assert.Equal(HcClip, parts.Sequence.CurrentAnimation!.Id);
        // The same style again: GetObjectSequence returns TRUE at once; a queue entry with 0 animations.
        Assert.Equal(MotionError.None, player.DoInterpretedMotion((MotionCommand)HandCombat, P()));
    }

    [Fact]
    public void WalkingBackwards_PlaysTheWalkToReadyLinkBackwards()
    {
        (PhysicsObj obj, AnimatedPartArray parts, MotionTablePlayer player, Recorder rec) = Create();
        // WalkForward at -0.65 from Ready (get_link, acclient.c:337584): the direct lookup with a negative speed finds
        // links[Walk][Ready] but the signs differ (same_sign(-0.65, 1) is false), so GetObjectSequence goes through the
        // default substate: get_link(Ready -> Ready) = none, get_link(Ready -> Walk, -0.65) = links[Walk][Ready], the
        // Walk->Ready link at -0.65 × 10 = -6.5 frames per second (backwards), then the walk cycle at -6.5;
        // num_anims = 0 + 1 + 1 - 1 = 1.
        Assert.Equal(MotionError.None, player.DoInterpretedMotion((MotionCommand)Walk, P(-0.65f)));
        Assert.Equal(WalkToReadyClip, parts.Sequence.CurrentAnimation!.Id);
        Assert.Equal(0xC0D00000u, BitConverter.SingleToUInt32Bits(parts.Sequence.CurrAnim!.GetFramerate()));  // -6.5
        Assert.Equal((float)(-0.65f * (double)3.12f), player.Velocity.Y);
        Assert.Equal(2, parts.Sequence.AnimationCount);
        Assert.Equal(-0.65f, player.SubstateSpeed);
        // The link's two frames backwards at 6.5 fps: 2 / 6.5 = 0.31 s, so it ends in the fourth 0.1 s step.
        Steps(obj, parts, rec, 3);
        Assert.Empty(rec.Done);
        Steps(obj, parts, rec, 1);
        Assert.Equal(new[] { ((MotionCommand)Walk, true, 4) }, rec.Done);
    }

    [Fact]
    public void AMotionTheTableHasNothingFor_IsNoMotionTableData_0x43()
    {
        (_, _, MotionTablePlayer player, _) = Create();
        Assert.Equal(0x43, (int)player.DoInterpretedMotion((MotionCommand)0x41000012u, P()));   // Crouch: no cycle
        Assert.Equal(0x43, (int)player.StopInterpretedMotion((MotionCommand)Turn, P()));        // not turning
        Assert.Equal(MotionError.NoMotionTableData, player.DoInterpretedMotion((MotionCommand)0x10000099u, P())); // no link
    }

    [Fact]
    public void ReModify_ReplaysTheNewestModifierOncePerModifier()
    {
        // re_modify (acclient.c:337285) counts its passes on a copy but takes each pass's modifier from the real state's
        // head, where the replayed one has just been put back: with Turn (newest) and SideStep on the walk, a new cycle
        // gets Turn's omega twice and SideStep's velocity not at all.
        MotionTable table = MotionTable.UnPack(HumanoidMotionTable.Builder().ToArray());
        var player = new MotionTablePlayer(table);
        player.InitializeMotionTables();
        player.DoInterpretedMotion((MotionCommand)HumanoidMotionTable.WalkForward, P());
        player.DoInterpretedMotion((MotionCommand)HumanoidMotionTable.SideStepRight, P());
        player.DoInterpretedMotion((MotionCommand)HumanoidMotionTable.TurnRight, P());
        Assert.Equal(new Vector3(1.25f, 3.12f, 0f), player.Velocity);
        Assert.Equal(-1.5f, player.Omega.Z);

        player.DoInterpretedMotion((MotionCommand)HumanoidMotionTable.RunForward, P());
        // add_motion(run cycle): v = (0, 4, 0), w = 0; re_modify: pass 1 Turn (w.z = -1.5), pass 2 Turn again (-3).
        Assert.Equal(new Vector3(0f, 4f, 0f), player.Velocity);
        Assert.Equal(-3f, player.Omega.Z);
        Assert.Equal(2, player.ModifierCount);
    }

    // The object with the retail movement manager and interpreter, in a cell of a flat world (an object without a cell
    // drops its link animations after each motion: CMotionInterp::DoInterpretedMotion's cell check), gravity off (every
    // motion may start). The steps are driven by hand, not by the world's tick.
    private static (PhysicsObj Obj, AnimatedPartArray Parts, MovementManager Mm, MotionInterp Mi) WithInterpreter()
    {
        var terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        PhysicsObj obj = world.CreateObject(1);
        obj.Weenie = new FixedRateWeenie(1f);
        var setup = new SetupPhysics(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) }, ReadOnlySpan<CylSphere>.Empty, 0.5f, 1f, 0.6f, 0.6f);
        var parts = new AnimatedPartArray(setup, 1, Table(), Clips());
        obj.PartArray = parts;
        obj.SetState((PhysicsState)PhysicsGlobals.DefaultState & ~PhysicsState.Gravity);
        Assert.True(obj.EnterWorld(new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4), new Vector3(100f, 100f, 20f))));
        MovementManager mm = MovementManager.Of(obj);
        return (obj, parts, mm, mm.GetOrCreateMotionInterpreter());
    }

    private static void Steps(PhysicsObj obj, AnimatedPartArray parts, int n)
    {
        for (int i = 0; i < n; i++)
        {
            Frame f = Frame.Identity;
            parts.Update(0.1f, ref f);
            obj.ProcessHooks();
        }
    }

    [Fact]
    public void SixActionsStillPlaying_TheSeventhIsTooManyActions_0x45()
    {
        (PhysicsObj obj, AnimatedPartArray parts, MovementManager mm, MotionInterp mi) = WithInterpreter();
        // Each wave waits for its link (3 frames) before the interpreter's action count drops; six are accepted.
        for (int i = 0; i < 6; i++)
        {
            Assert.Equal(MotionError.None, mm.DoMotion((MotionCommand)Wave, new MovementParameters()));
        }

        Assert.Equal(0x45, (int)mm.DoMotion((MotionCommand)Wave, new MovementParameters()));
        Assert.Equal(6, parts.Player!.ActionCount);

        // The first wave's link ends after 3 steps: one action done, room for one more.
        Steps(obj, parts, 3);
        Assert.Equal(MotionError.None, mm.DoMotion((MotionCommand)Wave, new MovementParameters()));
    }

    [Fact]
    public void StandingUpFromSitting_CannotJump_0x48_UntilTheStandUpLinkEnds()
    {
        (PhysicsObj obj, AnimatedPartArray parts, MovementManager mm, MotionInterp mi) = WithInterpreter();
        Assert.Equal(MotionError.None, mm.DoMotion(MotionCommand.Sitting, new MovementParameters()));
        Steps(obj, parts, 2);   // the sit-down link: 2 frames
        Assert.Equal(MotionError.YouCantJumpFromThisPosition, mi.JumpIsAllowed(1f, out _));

        // Ready from Sitting: the interpreter queues it with motion_allows_jump(Sitting) = 0x48 (the forward command it
        // leaves), and the table plays the Sitting->Ready link (3 frames) before the Ready cycle: num_anims 1.
        Assert.Equal(MotionError.None, mm.DoMotion(MotionCommand.Ready, new MovementParameters()));
        Assert.Equal(MotionCommand.Ready, mi.InterpretedState.ForwardCommand);
        Steps(obj, parts, 2);
        Assert.Equal(0x48, (int)mi.JumpIsAllowed(1f, out _));
        Steps(obj, parts, 1);   // the stand-up ends: MotionDone takes the Ready off the pending list
        Assert.Equal(MotionError.None, mi.JumpIsAllowed(1f, out _));
    }
}
