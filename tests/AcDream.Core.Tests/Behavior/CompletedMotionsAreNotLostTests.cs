using System;
using System.Linq;
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

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// Issue #33: one <c>AnimationDone</c> or <c>HandleEnterWorld</c> can finish the whole pending list, and retail calls
/// <c>CPhysicsObj::MotionDone</c> for each. The port queues them for the object, which drains the queue in the same call;
/// the queue held 32 and dropped the oldest past that (41 motions finishing together reported 32, and the interpreter kept
/// 9 stale pending motions). It now grows with the pending list (in <c>add_to_queue</c>, where the list grows) and loses
/// none.
/// </summary>
public class CompletedMotionsAreNotLostTests
{
    private const uint NonCombat = 0x8000003Du, Ready = 0x41000003u, Wave = 0x13000087u;
    private const uint ReadyClip = 0x03000001, WaveClip = 0x03000002;

    [Fact]
    public void FortyOneWavesEndedByHandleEnterWorld_AreAllReportedDone_InOrder()
    {
        MotionTable table = MotionTable.UnPack(new MotionTableBytes { DefaultStyle = NonCombat }
            .StyleDefault(NonCombat, Ready)
            .Cycle(NonCombat, Ready, MotionDataSpec.One(ReadyClip, 0, -1, 10f))
            .Link(NonCombat, Ready, Wave, MotionDataSpec.One(WaveClip, 0, -1, 10f))
            .ToArray());
        var lib = new AnimationLibrary();
        lib.Add(new AnimationBytes(ReadyClip).Frame().Build());
        lib.Add(new AnimationBytes(WaveClip).Frame().Frame().Frame().Build());
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = world.CreateObject(1);
        var setup = new SetupPhysics(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) }, ReadOnlySpan<CylSphere>.Empty, 0.5f, 1f, 0.6f, 0.6f);
        var parts = new AnimatedPartArray(setup, 1, table, lib);
        obj.PartArray = parts;
        var rec = new MotionDoneRecorder();
        obj.Movement = rec;
        MotionTablePlayer player = parts.Player!;
        player.InitializeMotionTables();
        obj.CheckForCompletedMotions();
        rec.Done.Clear();

        // Each wave: an action with the Ready->Wave link (1 animation), queued waiting for it (num_anims 1).
        for (int i = 0; i < 41; i++)
        {
            Assert.Equal(MotionError.None, player.DoInterpretedMotion((MotionCommand)Wave, new MovementParameters { Speed = 1f }));
        }

        // 41 pending waves plus the initial Ready (num_anims 0: done at the CheckForCompletedMotions above).
        Assert.Equal(41, player.PendingMotionCount);
        Assert.True(player.Manager.CompletedCapacity >= 41);   // grown in add_to_queue, before any tick needs it

        parts.HandleEnterWorld();   // the links go; every pending motion is done, unsuccessfully
        Assert.Equal(41, rec.Done.Count);
        Assert.All(rec.Done, d => Assert.Equal(((MotionCommand)Wave, false), d));
        Assert.Equal(0, player.PendingMotionCount);
        Assert.False(player.TryTakeCompletedMotion(out _, out _));
    }
}
