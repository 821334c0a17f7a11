using System;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Retail;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// Issue #34 item 1: the physics hooks' durations have their setters' domain at unpack. <c>AnimClip.UnPack</c> checked
/// only that a hook's time is finite; a scale, fade (object or part) or CallPES duration of 2^40 s or more was accepted,
/// and the setter (<c>SetScale</c>, <c>SetTranslucency2</c>, the fades, <c>CallPES</c>: |delta| &lt; 2^40 s) refused it
/// inside <c>process_hooks</c>, so every tick crossing that frame threw. The unpacker now refuses what the setter would
/// (<c>InputLimits.IsClockTimeInDomain</c>, the setters' own predicate); every value it accepts runs.
/// </summary>
public class AnimationHookDomainTests
{
    private const uint Id = 0x03000060;

    // 2^40 s, the first duration the setters refuse, and the float just below it (2^40 - 2^16: floats below 2^40 are
    // 2^16 apart), the last they accept.
    private const float TooLong = 1099511627776f;
    private const float Longest = 1099511562240f;

    private static readonly (AnimHookType Type, Action<RetailDataWriter, float> Fields)[] Timed =
    {
        (AnimHookType.Scale, (w, t) => w.Single(2f).Single(t)),
        (AnimHookType.Transparent, (w, t) => w.Single(0f).Single(1f).Single(t)),
        (AnimHookType.Luminous, (w, t) => w.Single(0f).Single(1f).Single(t)),
        (AnimHookType.Diffuse, (w, t) => w.Single(0f).Single(1f).Single(t)),
        (AnimHookType.TransparentPart, (w, t) => w.UInt32(0).Single(0f).Single(1f).Single(t)),
        (AnimHookType.LuminousPart, (w, t) => w.UInt32(0).Single(0f).Single(1f).Single(t)),
        (AnimHookType.DiffusePart, (w, t) => w.UInt32(0).Single(0f).Single(1f).Single(t)),
        (AnimHookType.CallPes, (w, t) => w.UInt32(0x33000001).Single(t)),
    };

    private static byte[] Clip(AnimHookType type, Action<RetailDataWriter, float> fields, float time) =>
        new AnimationBytes(Id).Frame().Hook(type, AnimHookDirection.Both, w => fields(w, time)).Frame().ToArray();

    [Fact]
    public void ADurationOf2To40SecondsOrMore_IsAFormatError_ForEveryTimedHook()
    {
        foreach ((AnimHookType type, Action<RetailDataWriter, float> fields) in Timed)
        {
            foreach (float t in new[] { TooLong, -TooLong, 2e12f, float.MaxValue })
            {
                var ex = Assert.Throws<RetailDataFormatException>(() => AnimClip.UnPack(Clip(type, fields, t)));
                Assert.Contains("2^40", ex.Message);
            }
        }
    }

    [Fact]
    public void TheLongestAcceptedDuration_Runs_AndLaterTicksDoNotThrow()
    {
        foreach ((AnimHookType type, Action<RetailDataWriter, float> fields) in Timed)
        {
            foreach (float t in new[] { Longest, -Longest })
            {
                AnimClip clip = AnimClip.UnPack(Clip(type, fields, t));
                PhysicsObj obj = AnimTestSupport.HookObject(out PhysicsWorld world);
                var seq = new AnimSequence(AnimTestSupport.Library(clip));
                seq.SetObject(obj);
                seq.AppendAnimation(new AnimData(Id, 0, -1, 30f));
                Frame f = Frame.Identity;
                seq.Update(0.05, ref f);   // 1.5 frames: frame 0 and its hook are left
                Assert.Equal(1, obj.PendingAnimHookCount);
                obj.ProcessHooks();        // the setter accepts it (a negative time sets at once)
                for (int i = 1; i <= 10; i++)
                {
                    world.Tick(i / 30.0);
                }
            }
        }
    }

    [Fact]
    public void TheIssueRepro_AWalkClipWithAScaleHookOf2e12Seconds_IsRefusedWhenRead()
    {
        // A walk clip with a scale hook (end 2, time 2e12 s): before, it was read, and DoMotion(WalkForward) then every tick
        // crossing the frame threw ArgumentException from SetScale inside process_hooks.
        byte[] bytes = new AnimationBytes(Id).Frame(new Vector3(0f, 0.1f, 0f))
            .Hook(AnimHookType.Scale, AnimHookDirection.Both, w => w.Single(2f).Single(2e12f))
            .Frame(new Vector3(0f, 0.1f, 0f)).ToArray();
        Assert.Throws<RetailDataFormatException>(() => AnimClip.UnPack(bytes));
    }
}
