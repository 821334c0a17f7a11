using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using Xunit;
using static AcDream.Core.Tests.Retail.AnimTestSupport;

namespace AcDream.Core.Tests.Retail;

/// <summary>
/// A link then a cycle on one sequence: CSequence::append_animation (acclient.c:340589), update_internal's AnimDone hook
/// (acclient.c:340658), apricot (acclient.c:339892), the list edits (remove_link_animations acclient.c:339953,
/// remove_all_link_animations acclient.c:340019, remove_cyclic_anims acclient.c:340153, clear_animations acclient.c:340101)
/// and multiply_cyclic_animation_fr (acclient.c:339735). Link L: 2 frames, steps +x 1, 2 m, hooks 100 + k; cycle C: 3
/// frames, steps 16, 32, 64 m, hooks 200 + k (all both directions); 30 frames per second, steps of 1/16 s (1.875 frames).
/// </summary>
public class SequenceLinkAndCycleTests
{
    private const uint LinkId = 0x03000010, CycleId = 0x03000020, Link2Id = 0x03000030, TenId = 0x03000040;
    private const double Q = 0.0625;

    private static AnimationLibrary Clips()
    {
        var link = new AnimationBytes(LinkId)
            .Frame(new Vector3(1f, 0f, 0f)).Sound(100, AnimHookDirection.Both)
            .Frame(new Vector3(2f, 0f, 0f)).Sound(101, AnimHookDirection.Both);
        var cycle = new AnimationBytes(CycleId)
            .Frame(new Vector3(16f, 0f, 0f)).Sound(200, AnimHookDirection.Both)
            .Frame(new Vector3(32f, 0f, 0f)).Sound(201, AnimHookDirection.Both)
            .Frame(new Vector3(64f, 0f, 0f)).Sound(202, AnimHookDirection.Both);
        var link2 = new AnimationBytes(Link2Id)
            .Frame(new Vector3(0f, 1f, 0f)).Sound(300, AnimHookDirection.Both);
        var ten = new AnimationBytes(TenId);
        for (int i = 0; i < 10; i++)
        {
            ten.Frame();
        }

        return Library(link.Build(), cycle.Build(), link2.Build(), ten.Build());
    }

    private static AnimSequence LinkThenCycle(out PhysicsObj obj)
    {
        obj = HookObject(out PhysicsWorld _);
        var seq = new AnimSequence(Clips());
        seq.SetObject(obj);
        seq.AppendAnimation(new AnimData(LinkId, 0, -1, 30f));
        seq.AppendAnimation(new AnimData(CycleId, 0, -1, 30f));
        return seq;
    }

    [Fact]
    public void Append_LastAnimationIsTheFirstCyclic_TheFirstPlays()
    {
        AnimSequence seq = LinkThenCycle(out _);
        Assert.Equal(2, seq.AnimationCount);
        Assert.Equal(1, seq.LinkAnimationCount);
        Assert.Same(seq.Tail, seq.FirstCyclic);
        Assert.Same(seq.Head, seq.CurrAnim);
        Assert.Equal(LinkId, seq.CurrentAnimation!.Id);
        Assert.Equal(0.0, seq.FrameNumber);
    }

    [Fact]
    public void PlaysTheLinkThenLoopsTheCycle_AnimDoneOnce_WhenTheLinkEnds()
    {
        AnimSequence seq = LinkThenCycle(out PhysicsObj obj);
        Frame f = Frame.Identity;

        // Step 1: L 0 -> 1.875 (high 1 not passed): frame 0 left (+1 m).
        seq.Update(Q, ref f);
        Assert.Equal(1f, f.Origin.X);
        Assert.Equal(new uint[] { 100 }, TakeQueuedHookNames(obj));

        // Step 2: 1.875 -> 3.75 passes L's high frame 1: time left (3.75 - 1 - 1) / 30 = 1.75 / 30 s; the list's head (L)
        // is not the first cyclic (C), so the AnimDone hook is queued; advance moves to C at frame 0 and combines its step
        // (+16 m); the 1.75 frames left leave C's frame 0 (+16 m, hook 200). apricot then drops L.
        seq.Update(Q, ref f);
        Assert.Equal(33f, f.Origin.X);
        Assert.Equal(new uint[] { AnimDone, 200 }, TakeQueuedHookNames(obj));
        Assert.Equal(1, seq.AnimationCount);
        Assert.Equal(0, seq.LinkAnimationCount);
        Assert.Equal(CycleId, seq.CurrentAnimation!.Id);
        Assert.Equal(1.75, seq.FrameNumber, 12);

        // Step 3: 1.75 -> 3.625 passes C's high frame 2: frame 1 left (+32 m, hook 201); the head is now the first cyclic:
        // no AnimDone; C loops to frame 0 (+16 m); 0.625 frames left cross nothing.
        seq.Update(Q, ref f);
        Assert.Equal(81f, f.Origin.X);
        Assert.Equal(new uint[] { 201 }, TakeQueuedHookNames(obj));
        Assert.Equal(0.625, seq.FrameNumber, 12);

        // Step 4 onwards: the cycle loops on, never another AnimDone.
        for (int i = 0; i < 20; i++)
        {
            seq.Update(Q, ref f);
            Assert.DoesNotContain(AnimDone, TakeQueuedHookNames(obj));
        }
    }

    [Fact]
    public void TwoLinks_AnimDoneForEach_InOneLongStep()
    {
        PhysicsObj obj = HookObject(out PhysicsWorld _);
        var seq = new AnimSequence(Clips());
        seq.SetObject(obj);
        seq.AppendAnimation(new AnimData(LinkId, 0, -1, 30f));
        seq.AppendAnimation(new AnimData(Link2Id, 0, -1, 30f));
        seq.AppendAnimation(new AnimData(CycleId, 0, -1, 30f));
        Frame f = Frame.Identity;
        // 0.25 s = 7.5 frames: L leaves frame 0 (hook 100) and ends at 1 (5.5 frames left); AnimDone; L2 (1 frame) starts at
        // 0 and ends at once (its high frame 0 is passed: 4.5 left, frame 0 not left); AnimDone; C starts, leaves frames 0 and
        // 1 (hooks 200, 201) and ends (1.5 left; head is still L: AnimDone); C loops and leaves frame 0 (hook 200).
        seq.Update(0.25, ref f);
        Assert.Equal(new uint[] { 100, AnimDone, AnimDone, 200, 201, AnimDone, 200 }, TakeQueuedHookNames(obj));
        Assert.Equal(1, seq.AnimationCount);
    }

    [Fact]
    public void RemoveLinkAnimations_RemovesTheLastLinks_ThePlayingOneMovesToTheCycle()
    {
        var seq = new AnimSequence(Clips());
        seq.AppendAnimation(new AnimData(LinkId, 0, -1, 30f));
        seq.AppendAnimation(new AnimData(Link2Id, 0, -1, 30f));
        seq.AppendAnimation(new AnimData(CycleId, 0, -1, 30f));
        // Playing L (the head). Remove one link: L2, the one just before the cycle; L still plays.
        seq.RemoveLinkAnimations(1);
        Assert.Equal(2, seq.AnimationCount);
        Assert.Equal(LinkId, seq.CurrentAnimation!.Id);
        // Remove one more: L, the playing one: the cycle starts at its starting frame 0.
        seq.RemoveLinkAnimations(1);
        Assert.Equal(1, seq.AnimationCount);
        Assert.Equal(CycleId, seq.CurrentAnimation!.Id);
        Assert.Equal(0.0, seq.FrameNumber);
        // No link left: nothing happens.
        seq.RemoveLinkAnimations(5);
        Assert.Equal(1, seq.AnimationCount);
    }

    [Fact]
    public void RemoveAllLinkAnimations_LeavesTheCycle()
    {
        var seq = new AnimSequence(Clips());
        seq.AppendAnimation(new AnimData(LinkId, 0, -1, 30f));
        seq.AppendAnimation(new AnimData(Link2Id, 0, -1, 30f));
        seq.AppendAnimation(new AnimData(CycleId, 0, -1, -30f));
        seq.RemoveAllLinkAnimations();
        Assert.Equal(1, seq.AnimationCount);
        Assert.Equal(CycleId, seq.CurrentAnimation!.Id);
        // Backwards: starting frame high + 1 - EPSILON = 3 - (double)0.0002f (the float EPSILON widened: AnimationEpsilonTests).
        Assert.Equal(3.0 - (double)0.0002f, seq.FrameNumber);
    }

    [Fact]
    public void RemoveCyclicAnims_NotPlayingACycle_LeavesThePlayingLink()
    {
        AnimSequence seq = LinkThenCycle(out _);
        // curr is L, a link: it stays at its frame; C goes and L, now the tail, is the first cyclic.
        seq.RemoveCyclicAnims();
        Assert.Equal(1, seq.AnimationCount);
        Assert.Equal(LinkId, seq.CurrentAnimation!.Id);
        Assert.Same(seq.Head, seq.FirstCyclic);
        Assert.Equal(0.0, seq.FrameNumber);
    }

    [Fact]
    public void RemoveCyclicAnims_PlayingTheCycle_TheLinkBeforeItPlaysOnFromItsEndingFrame()
    {
        // [L, C] playing C at 1.5 (an unpacked sequence: between two updates apricot has not yet dropped L).
        var seq = new AnimSequence(Clips());
        byte[] packed = new RetailDataWriter()
            .UInt32(2)
            .UInt32(LinkId).Int32(0).Int32(-1).Single(30f)
            .UInt32(CycleId).Int32(0).Int32(-1).Single(30f)
            .Bytes(System.BitConverter.GetBytes(1.5))
            .UInt32(1).UInt32(1)
            .UInt32(0)
            .ToArray();
        seq.UnPack(packed);
        Assert.Equal(CycleId, seq.CurrentAnimation!.Id);
        seq.RemoveCyclicAnims();
        // curr = C's previous, L, at L's ending frame high + 1 - EPSILON = 2 - (double)0.0002f (the float EPSILON widened).
        Assert.Equal(LinkId, seq.CurrentAnimation!.Id);
        Assert.Equal(2.0 - (double)0.0002f, seq.FrameNumber);
        Assert.Same(seq.Head, seq.FirstCyclic);
        Assert.Equal(1, seq.AnimationCount);
    }

    [Fact]
    public void RemoveCyclicAnims_PlayingTheOnlyAnimation_EmptiesTheSequence()
    {
        var seq = new AnimSequence(Clips());
        seq.AppendAnimation(new AnimData(CycleId, 0, -1, 30f));
        seq.RemoveCyclicAnims();
        Assert.False(seq.HasAnims);
        Assert.Null(seq.CurrentAnimation);
        Assert.Null(seq.FirstCyclic);
        Assert.Equal(0.0, seq.FrameNumber);
    }

    [Fact]
    public void ClearAnimations_EmptiesTheList()
    {
        AnimSequence seq = LinkThenCycle(out _);
        Frame f = Frame.Identity;
        seq.Update(Q, ref f);
        seq.ClearAnimations();
        Assert.False(seq.HasAnims);
        Assert.Equal(0, seq.AnimationCount);
        Assert.Null(seq.CurrentAnimation);
        Assert.Equal(0.0, seq.FrameNumber);
    }

    [Fact]
    public void MultiplyCyclicAnimationFramerate_ScalesOnlyTheCycle_ANegativeOneSwapsItsRange()
    {
        AnimSequence seq = LinkThenCycle(out _);
        seq.MultiplyCyclicAnimationFramerate(2f);
        Assert.Equal(30f, seq.Head!.Framerate);
        Assert.Equal(60f, seq.FirstCyclic!.Framerate);
        seq.MultiplyCyclicAnimationFramerate(-0.5f);
        Assert.Equal(30f, seq.Head!.Framerate);
        Assert.Equal(-30f, seq.FirstCyclic!.Framerate);
        // C's range 0..2 swapped to 2..0; L's untouched (0..1).
        Assert.Equal(2, seq.FirstCyclic!.LowFrame);
        Assert.Equal(0, seq.FirstCyclic!.HighFrame);
        Assert.Equal(0, seq.Head!.LowFrame);
        Assert.Equal(1, seq.Head!.HighFrame);
    }

    [Fact]
    public void MultiplyCyclicAnimationFramerate_DoublesTheFramesCrossed()
    {
        var seq = new AnimSequence(Clips());
        seq.AppendAnimation(new AnimData(CycleId, 0, -1, 30f));
        seq.MultiplyCyclicAnimationFramerate(2f);
        Frame f = Frame.Identity;
        // 60 fps for 1/16 s = 3.75 frames: frames 0, 1 left (+48 m), high 2 passed (time left 0.75 / 60 s), loop to 0
        // (+16 m), 0.75 frames cross nothing.
        seq.Update(Q, ref f);
        Assert.Equal(64f, f.Origin.X);
        Assert.Equal(0.75, seq.FrameNumber, 12);
    }

    [Theory]
    [InlineData(-5, -1, 9, 9)]   // high < 0: the last frame (9); low -5 is 0xFFFFFFFB unsigned, >= 10: 9
    [InlineData(3, 20, 3, 9)]    // high past the end: 9
    [InlineData(4, 2, 4, 4)]     // low above high: high = low
    [InlineData(12, -1, 9, 9)]   // high: 9; low past the end: 9
    [InlineData(0, -1, 0, 9)]    // the whole animation
    public void SetAnimationId_ClampsTheRangeToTheAnimation(int low, int high, int expectedLow, int expectedHigh)
    {
        var seq = new AnimSequence(Clips());
        seq.AppendAnimation(new AnimData(TenId, low, high, 30f));
        Assert.Equal(expectedLow, seq.Head!.LowFrame);
        Assert.Equal(expectedHigh, seq.Head!.HighFrame);
    }

    [Fact]
    public void AnAnimationTheSourceDoesNotKnow_IsDropped()
    {
        var seq = new AnimSequence(Clips());
        seq.AppendAnimation(new AnimData(0x0300FFFF, 0, -1, 30f));
        seq.AppendAnimation(new AnimData(0, 0, -1, 30f));
        Assert.False(seq.HasAnims);
        Assert.Null(seq.CurrentAnimation);
        var none = new AnimSequence(null);
        none.AppendAnimation(new AnimData(LinkId, 0, -1, 30f));
        Assert.False(none.HasAnims);
    }

    [Fact]
    public void Physics_CombineSubtractClear()
    {
        var seq = new AnimSequence(null);
        seq.SetVelocity(new Vector3(1f, 2f, 3f));
        seq.SetOmega(new Vector3(0f, 0f, 1f));
        seq.CombinePhysics(new Vector3(0.5f, 0.25f, 0.125f), new Vector3(0f, 0f, 0.5f));
        Assert.Equal(new Vector3(1.5f, 2.25f, 3.125f), seq.Velocity);
        Assert.Equal(new Vector3(0f, 0f, 1.5f), seq.Omega);
        seq.SubtractPhysics(new Vector3(1f, 1f, 1f), new Vector3(0f, 0f, 1f));
        Assert.Equal(new Vector3(0.5f, 1.25f, 2.125f), seq.Velocity);
        Assert.Equal(new Vector3(0f, 0f, 0.5f), seq.Omega);
        seq.ClearPhysics();
        Assert.Equal(Vector3.Zero, seq.Velocity);
        Assert.Equal(Vector3.Zero, seq.Omega);
    }

    [Fact]
    public void CurrentAnimFrame_IsThePlayingFrame_OrThePlacementFrame()
    {
        var seq = new AnimSequence(Clips());
        var placement = new AnimFrame(new[] { AFrame.Identity }, null, 0);
        seq.SetPlacementFrame(placement, 0x65);
        Assert.Same(placement, seq.CurrentAnimFrame);
        Assert.Equal(0x65u, seq.PlacementFrameId);
        seq.AppendAnimation(new AnimData(CycleId, 0, -1, 30f));
        Frame f = Frame.Identity;
        seq.Update(Q, ref f); // frame 1.875
        Assert.Same(seq.CurrentAnimation!.PartFrames[1], seq.CurrentAnimFrame);
        Assert.Equal(1L, seq.CurrentFrameNumber);
        seq.Clear();
        Assert.Null(seq.CurrentAnimFrame);
        Assert.Equal(0u, seq.PlacementFrameId);
    }
}
