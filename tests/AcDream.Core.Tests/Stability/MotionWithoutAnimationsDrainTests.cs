using System;
using System.Diagnostics;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// Issue #33 (audit) and #34 item 2: a cycle with no animations is queued waiting for num_anims = 0 − 1 = 0xFFFFFFFF
/// animations (<c>CMotionTable::SetDefaultState</c>, acclient.c:826; <c>GetObjectSequence</c>'s N − 1 sums). No animation
/// ever ends it in play (retail: it stays pending). <c>MotionTableManager::HandleEnterWorld</c> and <c>HandleExitWorld</c>
/// (acclient.c:329948, 329939) loop <c>AnimationDone(0)</c> until the list is empty: each call only increments the counter
/// until it reaches the count, about 4.3 billion calls (retail stalls too: 104 s in a probe; the port took 25 s). The drain
/// now moves the counter to one below the count and makes the one call that completes the motion: the same end state.
/// </summary>
public class MotionWithoutAnimationsDrainTests
{
    private const uint NonCombat = 0x8000003Du, Ready = 0x41000003u;

    // A generous bound for a drain that takes microseconds; the 2^32 calls took 25 s on the machine that found them.
    private const long DrainBoundMs = 5000;

    private static (PhysicsObj Obj, AnimatedPartArray Parts, MotionDoneRecorder Rec) Create()
    {
        MotionTable table = MotionTable.UnPack(new MotionTableBytes { DefaultStyle = NonCombat }
            .StyleDefault(NonCombat, Ready)
            .Cycle(NonCombat, Ready, new MotionDataSpec(Array.Empty<(uint, int, int, float)>()))
            .ToArray());
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = world.CreateObject(1);
        var setup = new SetupPhysics(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) }, ReadOnlySpan<CylSphere>.Empty, 0.5f, 1f, 0.6f, 0.6f);
        var parts = new AnimatedPartArray(setup, 1, table, new AnimationLibrary());
        obj.PartArray = parts;
        var rec = new MotionDoneRecorder();
        obj.Movement = rec;
        parts.Player!.InitializeMotionTables();   // SetDefaultState: the Ready cycle, no animations: num_anims 0xFFFFFFFF
        obj.CheckForCompletedMotions();
        return (obj, parts, rec);
    }

    [Fact]
    public void InPlay_TheMotionStaysPending_AsInRetail()
    {
        (PhysicsObj obj, AnimatedPartArray parts, MotionDoneRecorder rec) = Create();
        Assert.Equal(1, parts.Player!.PendingMotionCount);
        parts.Player.Manager.AnimationDone(true);   // an animation ending counts 1 of 0xFFFFFFFF
        Assert.Equal(1, parts.Player.PendingMotionCount);
        Assert.Equal(1, parts.Player.Manager.AnimationCounter);
        Assert.Empty(rec.Done);
    }

    [Fact]
    public void HandleEnterWorld_CompletesIt_AtOnce()
    {
        (PhysicsObj obj, AnimatedPartArray parts, MotionDoneRecorder rec) = Create();
        var clock = Stopwatch.StartNew();
        parts.HandleEnterWorld();
        clock.Stop();
        Assert.True(clock.ElapsedMilliseconds < DrainBoundMs, $"the drain took {clock.ElapsedMilliseconds} ms");
        // Retail's end state after its 2^32 calls: the motion done (unsuccessfully), the counter back to 0.
        Assert.Equal(new[] { ((MotionCommand)Ready, false) }, rec.Done);
        Assert.Equal(0, parts.Player!.PendingMotionCount);
        Assert.Equal(0, parts.Player.Manager.AnimationCounter);
    }

    [Fact]
    public void HandleExitWorld_CompletesIt_AtOnce_AfterCountedAnimations()
    {
        (PhysicsObj obj, AnimatedPartArray parts, MotionDoneRecorder rec) = Create();
        parts.Player!.Manager.AnimationDone(true);
        parts.Player.Manager.AnimationDone(true);
        var clock = Stopwatch.StartNew();
        parts.HandleExitWorld();
        clock.Stop();
        Assert.True(clock.ElapsedMilliseconds < DrainBoundMs, $"the drain took {clock.ElapsedMilliseconds} ms");
        Assert.Equal(new[] { ((MotionCommand)Ready, false) }, rec.Done);
        Assert.Equal(0, parts.Player.PendingMotionCount);
        Assert.Equal(0, parts.Player.Manager.AnimationCounter);
    }
}
