using System;
using System.Linq;
using System.Reflection;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Tests.Support;
using AcDream.Core.Physics.Data;
using Xunit;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Tests.Api;

/// <summary>The animation types' public contract: what they refuse, and that what a client reads cannot be changed by it.</summary>
public class AnimationApiTests
{
    [Fact]
    public void Library_RefusesNull_AndBadBytes_WithoutChange()
    {
        var lib = new AnimationLibrary();
        Assert.Throws<ArgumentNullException>(() => lib.Add((AnimClip)null!));
        Assert.Throws<RetailDataFormatException>(() => lib.Add(ReadOnlySpan<byte>.Empty));
        Assert.Equal(0, lib.Count);
        Assert.Null(lib.GetAnimation(0));
    }

    [Fact]
    public void HooksAndClips_HaveNoPublicSetters()
    {
        // Hooks and animations are shared by every object that plays them: a client reads them and cannot change them (the
        // engine-run hooks too, internal as they are: a client sees them as AnimHook).
        Type[] types = typeof(AnimHook).Assembly.GetTypes()
            .Where(t => typeof(AnimHook).IsAssignableFrom(t) || t == typeof(AnimClip) || t == typeof(AnimFrame))
            .ToArray();
        Assert.True(types.Length >= 32);
        foreach (Type t in types)
        {
            foreach (PropertyInfo p in t.GetProperties(BindingFlags.Public | BindingFlags.Instance))
            {
                Assert.False(p.SetMethod?.IsPublic == true, $"{t.Name}.{p.Name} has a public setter");
            }

            Assert.DoesNotContain(t.GetConstructors(BindingFlags.Public | BindingFlags.Instance), c => true);
        }
    }

    [Fact]
    public void ListenerHooks_ArePublic_EngineRunHooksInternal()
    {
        // What IAnimHookListener.OnAnimHook receives (the hooks whose Execute notifies the listener) is public, with the
        // fields retail reads; the hooks the engine executes itself (fades, scale, physics script, ethereal, omega, animation
        // done) are internal.
        string[] publicHooks = typeof(AnimHook).Assembly.GetExportedTypes()
            .Where(t => typeof(AnimHook).IsAssignableFrom(t)).Select(t => t.Name).Order(StringComparer.Ordinal).ToArray();
        Assert.Equal(new[]
        {
            "AnimHook", "AttackHook", "CreateBlockingParticleHook", "CreateParticleHook", "DefaultScriptHook", "DefaultScriptPartHook",
            "DestroyParticleHook", "NoDrawHook", "NoOpHook", "ReplaceObjectHook", "SetLightHook", "SoundHook", "SoundTableHook",
            "SoundTweakedHook", "StopParticleHook", "TextureVelocityHook", "TextureVelocityPartHook",
        }, publicHooks);
        Assert.False(typeof(ScaleHook).IsPublic);
        Assert.False(typeof(FadeHook).IsPublic);
        Assert.False(typeof(PartFadeHook).IsPublic);
        Assert.False(typeof(AnimDoneHook).IsPublic);
    }

    [Fact]
    public void AnimationSequence_IsReadOnlyToTheClient()
    {
        Assert.Empty(typeof(AnimSequence).GetConstructors(BindingFlags.Public | BindingFlags.Instance));
        Assert.DoesNotContain(typeof(AnimSequence).GetMethods(BindingFlags.Public | BindingFlags.Instance | BindingFlags.DeclaredOnly),
            m => !m.IsSpecialName);
    }

    [Fact]
    public void UnPack_NamesTheStructureAndTheOffset()
    {
        byte[] bytes = new AnimationBytes(1).Frame().ToArray();
        RetailDataFormatException e = Assert.Throws<RetailDataFormatException>(() => AnimClip.UnPack(bytes.AsSpan(0, bytes.Length - 2)));
        Assert.Equal("CAnimation", e.Structure);
        // 46 of the 48 bytes: after the 16-byte header 30 remain, fewer than the 4 + 28 one frame of one part needs: the
        // count is refused where it stands, at byte 12.
        Assert.Equal(12, e.Offset);
        Assert.Contains("CAnimation", e.Message);
    }
}
