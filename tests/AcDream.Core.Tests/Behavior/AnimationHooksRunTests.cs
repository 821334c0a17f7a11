using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Retail;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// An animation whose frames carry hooks, played on an object: the physics hooks run in the library as retail's Execute
/// does (scale, translucency, ethereal, omega, physics script), the others reach the client's listener, in the order the
/// frames were crossed.
/// </summary>
public class AnimationHooksRunTests
{
    private sealed class Listener : IAnimHookListener
    {
        public List<AnimHookType> Seen { get; } = new();

        public void OnAnimHook(PhysicsObj obj, AnimHook hook) => Seen.Add(hook.HookType);
    }

    private sealed class Scripts : IScriptPlayer
    {
        public List<uint> Played { get; } = new();

        public void PlayScript(PhysicsObj obj, uint scriptId) => Played.Add(scriptId);
    }

    [Fact]
    public void PhysicsHooksRunInTheLibrary_OthersReachTheListener()
    {
        const uint id = 0x03000050;
        var b = new AnimationBytes(id)
            .Frame()
            .Hook(AnimHookType.Scale, AnimHookDirection.Both, w => w.Single(2f).Single(0f))        // at once: scale 2
            .Hook(AnimHookType.Sound, AnimHookDirection.Both, w => w.UInt32(0x0A000001))
            .Hook(AnimHookType.SetOmega, AnimHookDirection.Both, w => w.Single(0f).Single(0f).Single(1.5f))
            .Frame()
            .Hook(AnimHookType.Ethereal, AnimHookDirection.Forward, w => w.Int32(1))
            .Hook(AnimHookType.CreateParticle, AnimHookDirection.Both,
                w => w.UInt32(0x32000001).UInt32(0).Frame(Vector3.Zero, Quaternion.Identity).UInt32(9))
            .Hook(AnimHookType.CallPes, AnimHookDirection.Both, w => w.UInt32(0x33000007).Single(0f))   // at once
            .Hook(AnimHookType.Transparent, AnimHookDirection.Both, w => w.Single(0f).Single(1f).Single(1f)) // a fade
            .Frame();
        PhysicsObj obj = AnimTestSupport.HookObject(out PhysicsWorld world);
        var listener = new Listener();
        var scripts = new Scripts();
        world.AnimHookListener = listener;
        world.ScriptPlayer = scripts;
        var seq = new AnimSequence(AnimTestSupport.Library(b.Build()));
        seq.SetObject(obj);
        seq.AppendAnimation(new AnimData(id, 0, -1, 30f));

        // 5/64 s at 30 fps = 2.34375 frames: frames 0 and 1 are left (the high frame 2 is not passed).
        Frame f = Frame.Identity;
        seq.Update(0.078125, ref f);
        Assert.Equal(7, obj.PendingAnimHookCount); // 3 on frame 0, 4 on frame 1
        Assert.Null(obj.Hooks);
        obj.ProcessHooks();

        Assert.Equal(2f, obj.Scale);
        Assert.Equal(new Vector3(0f, 0f, 1.5f), obj.Omega);
        Assert.True((obj.State & PhysicsState.Ethereal) != 0);
        Assert.Equal(new uint[] { 0x33000007 }, scripts.Played);
        Assert.NotNull(obj.Hooks); // the translucency fade, a pooled FPHook
        Assert.Equal(new[] { AnimHookType.Sound, AnimHookType.CreateParticle }, listener.Seen);
        Assert.Equal(0, obj.PendingAnimHookCount);
    }

    [Fact]
    public void WithoutAHookObject_NothingIsQueued()
    {
        const uint id = 0x03000051;
        var b = new AnimationBytes(id).Frame().Sound(1, AnimHookDirection.Both).Frame();
        PhysicsObj obj = AnimTestSupport.HookObject(out PhysicsWorld _);
        var seq = new AnimSequence(AnimTestSupport.Library(b.Build()));
        seq.AppendAnimation(new AnimData(id, 0, -1, 30f));
        Frame f = Frame.Identity;
        seq.Update(0.0625, ref f);
        Assert.Equal(0, obj.PendingAnimHookCount);
        seq.SetObject(obj);
        seq.Update(0.0625, ref f); // 1.875 -> 3.75 passes the end (high frame 1): nothing left in the loop; after the
                                   // loop to frame 0, 1.75 frames leave frame 0 again: its hook fires
        Assert.Equal(1, obj.PendingAnimHookCount);
    }
}
