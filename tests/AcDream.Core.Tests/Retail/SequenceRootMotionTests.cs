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
/// CSequence::update_internal (acclient.c:340658) and advance_to_next_animation (acclient.c:340472) on one cyclic
/// animation of four frames whose root-motion steps are +x 1, 2, 4 and 8 m (identity rotations, so each combine adds its
/// step exactly and each subtract takes it off exactly; which frames applied can be read off the sum). Frame k carries
/// three sound hooks: 10 + k forward, 20 + k backward, 30 + k both. Steps of 1/16 s at ±30 frames per second cross 1.875
/// frames (exact in binary).
/// </summary>
public class SequenceRootMotionTests
{
    private const uint AnimId = 0x03000001;
    private const double Q = 0.0625;

    private static AnimClip FourFrames()
    {
        var b = new AnimationBytes(AnimId);
        float[] steps = { 1f, 2f, 4f, 8f };
        for (uint k = 0; k < 4; k++)
        {
            b.Frame(new Vector3(steps[k], 0f, 0f))
                .Sound(10 + k, AnimHookDirection.Forward)
                .Sound(20 + k, AnimHookDirection.Backward)
                .Sound(30 + k, AnimHookDirection.Both);
        }

        return b.Build();
    }

    private static AnimSequence Playing(float framerate, out PhysicsObj obj)
    {
        obj = HookObject(out PhysicsWorld _);
        var seq = new AnimSequence(Library(FourFrames()));
        seq.SetObject(obj);
        seq.AppendAnimation(new AnimData(AnimId, 0, -1, framerate));
        return seq;
    }

    [Fact]
    public void Forward30_CombinesEachFrameItLeaves_AndFiresItsForwardAndBothHooks()
    {
        AnimSequence seq = Playing(30f, out PhysicsObj obj);
        Frame f = Frame.Identity;
        // Starting frame of a forward animation: its low frame, 0.
        Assert.Equal(0.0, seq.FrameNumber);

        // Step 1: frame 0 -> 1.875. Crossed: frame 0 (step 1 m; hooks 10, 30).
        seq.Update(Q, ref f);
        Assert.Equal(1f, f.Origin.X);
        Assert.Equal(1.875, seq.FrameNumber);
        Assert.Equal(new uint[] { 10, 30 }, TakeQueuedHookNames(obj));

        // Step 2: 1.875 -> 3.75 (high frame 3 not passed). Crossed: frames 1 and 2 (2 m + 4 m).
        seq.Update(Q, ref f);
        Assert.Equal(7f, f.Origin.X);
        Assert.Equal(3.75, seq.FrameNumber);
        Assert.Equal(new uint[] { 11, 31, 12, 32 }, TakeQueuedHookNames(obj));

        // Step 3: 3.75 + 1.875 = 5.625 passes high frame 3: time left (5.625 - 3 - 1) / 30 = 1.625 / 30 s, the frame number
        // is clamped to 3 and no frame is left (floor 3 = 3), so frame 3's step and hooks never apply forwards. The single
        // animation is its own first cyclic one (no links: no AnimDone); advance loops to it at frame 0 and, the framerate
        // being positive, combines frame 0's step (1 m). The 1.625 frames left then cross frame 0 again (1 m; hooks 10, 30).
        seq.Update(Q, ref f);
        Assert.Equal(9f, f.Origin.X);
        Assert.Equal(1L, seq.CurrentFrameNumber);
        Assert.Equal(1.625, seq.FrameNumber, 12);
        Assert.Equal(new uint[] { 10, 30 }, TakeQueuedHookNames(obj));

        // Step 4: 1.625 -> 3.5: frames 1 and 2 again (+6 m).
        seq.Update(Q, ref f);
        Assert.Equal(15f, f.Origin.X);
        Assert.Equal(new uint[] { 11, 31, 12, 32 }, TakeQueuedHookNames(obj));
        Assert.Equal(0f, f.Origin.Y);
        Assert.Equal(1f, f.Qw);
    }

    [Fact]
    public void Backward30_SubtractsEachFrameItLeaves_AndFiresItsBackwardAndBothHooks()
    {
        AnimSequence seq = Playing(-30f, out PhysicsObj obj);
        Frame f = Frame.Identity;
        // Starting frame of a backward animation: high + 1 - EPSILON = 4 - (double)0.0002f (retail's float EPSILON widened;
        // issue #33 moved it from the decompiler's printed literal 0.00019999999, 4.95e-12 smaller: AnimationEpsilonTests).
        Assert.Equal(4.0 - (double)0.0002f, seq.FrameNumber);

        // Step 1: 3.9998 -> 2.1248. Left: frame 3 (subtract 8 m; hooks 23, 33).
        seq.Update(Q, ref f);
        Assert.Equal(-8f, f.Origin.X);
        Assert.Equal(new uint[] { 23, 33 }, TakeQueuedHookNames(obj));

        // Step 2: 2.1248 -> 0.2498. Left: frames 2 and 1 (-4 m, -2 m).
        seq.Update(Q, ref f);
        Assert.Equal(-14f, f.Origin.X);
        Assert.Equal(new uint[] { 22, 32, 21, 31 }, TakeQueuedHookNames(obj));

        // Step 3: 0.2498 - 1.875 = -1.6252 passes low frame 0: time left -1.6252 / -30 s (positive, as the step), frame
        // number clamped to 0, nothing left in the loop. advance (quantum >= 0): the ended animation plays backwards, so
        // frame 0's step is subtracted (-1 m); the next (the same, first cyclic) starts at 3.9998 and, playing backwards,
        // adds nothing. The 1.6252 frames left leave frame 3 (-8 m; hooks 23, 33). Frame 0's hooks never fire backwards.
        seq.Update(Q, ref f);
        Assert.Equal(-23f, f.Origin.X);
        Assert.Equal(2L, seq.CurrentFrameNumber);
        Assert.Equal(new uint[] { 23, 33 }, TakeQueuedHookNames(obj));
    }

    [Fact]
    public void OneLongStep_CrossesEveryFrameInOrder_AcrossTheLoop()
    {
        AnimSequence seq = Playing(30f, out PhysicsObj obj);
        Frame f = Frame.Identity;
        // 0.25 s = 7.5 frames from frame 0: frames 0, 1, 2 are left (7 m), frame 3 ends the animation (time left
        // (7.5 - 3 - 1) / 30 = 3.5 / 30 s), advance adds frame 0's step (1 m), then 3.5 frames leave 0, 1, 2 (7 m).
        seq.Update(0.25, ref f);
        Assert.Equal(15f, f.Origin.X);
        Assert.Equal(3L, seq.CurrentFrameNumber);
        Assert.Equal(new uint[] { 10, 30, 11, 31, 12, 32, 10, 30, 11, 31, 12, 32 }, TakeQueuedHookNames(obj));
    }

    [Fact]
    public void Velocity_AppliesOneFramesWorthPerFrameLeft_AndAtEachAdvance()
    {
        AnimSequence seq = Playing(30f, out PhysicsObj obj);
        // 30 m/s for 1/30 s per frame: |1/30| * 30 = 1 exactly in double.
        seq.SetVelocity(new Vector3(30f, 0f, 0f));
        Frame f = Frame.Identity;
        seq.Update(Q, ref f); // frame 0 left: 1 m step + 1 m of velocity
        Assert.Equal(2f, f.Origin.X);
        seq.Update(Q, ref f); // frames 1, 2: 6 m + 2 m
        Assert.Equal(10f, f.Origin.X);
        seq.Update(Q, ref f); // advance: 1 m + 1 m; frame 0 left: 1 m + 1 m
        Assert.Equal(14f, f.Origin.X);
        TakeQueuedHookNames(obj);
    }

    [Fact]
    public void NoAnimations_MovesByVelocityTimesQuantum()
    {
        var seq = new AnimSequence(null);
        seq.SetVelocity(new Vector3(1f, 2f, 4f));
        Frame f = Frame.Identity;
        seq.Update(0.5, ref f);
        Assert.Equal(new Vector3(0.5f, 1f, 2f), f.Origin);
        Assert.False(seq.HasAnims);
    }

    [Fact]
    public void ZeroFramerate_CrossesNoFrame_AndMovesByVelocityOverTheWholeStep()
    {
        AnimSequence seq = Playing(0f, out PhysicsObj obj);
        seq.SetVelocity(new Vector3(2f, 0f, 0f));
        Frame f = Frame.Identity;
        // frame_quantum 0: the loop breaks at once and apply_physics(quantum, quantum) moves 2 * 0.5 = 1 m.
        seq.Update(0.5, ref f);
        Assert.Equal(1f, f.Origin.X);
        Assert.Equal(0.0, seq.FrameNumber);
        Assert.Empty(TakeQueuedHookNames(obj));
    }

    [Fact]
    public void QuarterTurnSteps_WalkASquare()
    {
        // Each frame steps 1 m along the body's +x and turns 90 degrees about +z (x turns into y).
        float h = 0.70710677f;
        var b = new AnimationBytes(AnimId);
        for (int k = 0; k < 4; k++)
        {
            b.Frame(new Vector3(1f, 0f, 0f), new Quaternion(0f, 0f, h, h));
        }

        var seq = new AnimSequence(Library(b.Build()));
        seq.AppendAnimation(new AnimData(AnimId, 0, -1, 30f));
        Frame f = Frame.Identity;
        seq.Update(Q, ref f); // frame 0: (1, 0, 0), facing +y
        AssertNear(new Vector3(1f, 0f, 0f), f.Origin);
        seq.Update(Q, ref f); // frames 1, 2: +y then -x
        AssertNear(new Vector3(0f, 1f, 0f), f.Origin);
        // Facing -y after three quarter turns: the local +x axis points to global -y.
        AssertNear(new Vector3(0f, -1f, 0f), f.LocalToGlobalVec(Vector3.UnitX));
    }

    private static void AssertNear(Vector3 expected, Vector3 actual)
    {
        Assert.True(Vector3.Distance(expected, actual) < 1e-5f, $"expected {expected}, got {actual}");
    }
}
