using System.Collections.Generic;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Retail;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// <c>ReplaceObjectHook::Execute</c> does nothing in retail: in the PDB it shares its address (0x00508950) and its 3-byte
/// size with <c>NOOPHook::Execute</c>, a lone <c>ret 4</c>. The port used to hand it to the client's listener.
/// </summary>
public class ReplaceObjectHookDoesNothingTests
{
    private sealed class Listener : IAnimHookListener
    {
        public List<AnimHookType> Seen { get; } = new();

        public void OnAnimHook(PhysicsObj obj, AnimHook hook) => Seen.Add(hook.HookType);
    }

    [Fact]
    public void AReplaceObjectHookFires_AndTheListenerHearsOnlyTheSoundBesideIt()
    {
        const uint id = 0x03000070;
        var b = new AnimationBytes(id)
            .Frame()
            .Hook(AnimHookType.ReplaceObject, AnimHookDirection.Both, w => w.Byte(1).UInt16(0x0123))
            .Hook(AnimHookType.Sound, AnimHookDirection.Both, w => w.UInt32(0x0A000001))
            .Hook(AnimHookType.NoOp, AnimHookDirection.Both)
            .Frame();
        PhysicsObj obj = AnimTestSupport.HookObject(out PhysicsWorld world);
        var listener = new Listener();
        world.AnimHookListener = listener;
        AnimClip clip = b.Build();
        var seq = new AnimSequence(AnimTestSupport.Library(clip));
        seq.SetObject(obj);
        seq.AppendAnimation(new AnimData(id, 0, -1, 30f));
        Frame f = Frame.Identity;
        seq.Update(0.05, ref f);   // 1.5 frames: frame 0 is left, its three hooks queued
        Assert.Equal(3, obj.PendingAnimHookCount);
        obj.ProcessHooks();
        Assert.Equal(new[] { AnimHookType.Sound }, listener.Seen);

        // The data stays readable: the part and the GfxObj id (0x01000000 + 0x0123).
        var r = (ReplaceObjectHook)clip.PartFrames[0].Hooks!;
        Assert.Equal(1u, r.PartIndex);
        Assert.Equal(0x01000123u, r.PartId);
    }
}
