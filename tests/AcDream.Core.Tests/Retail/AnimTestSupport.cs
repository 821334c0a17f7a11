using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;

namespace AcDream.Core.Tests.Retail;

/// <summary>Shared pieces of the animation tests: an object to queue hooks on and the queue read back as names.</summary>
internal static class AnimTestSupport
{
    /// <summary>The name <see cref="QueuedHookNames"/> gives the sequence's AnimDone hook.</summary>
    public const uint AnimDone = 999;

    public static PhysicsObj HookObject(out PhysicsWorld world)
    {
        world = new PhysicsWorld(0.0);
        return TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f), spheres: 0);
    }

    /// <summary>The queued anim hooks as names (a sound hook by its sound id, the AnimDone hook as 999), then the queue is run
    /// and emptied.</summary>
    public static uint[] TakeQueuedHookNames(PhysicsObj obj)
    {
        var names = new List<uint>();
        foreach (IAnimHook? h in obj.PendingAnimHooks)
        {
            names.Add(h switch
            {
                SoundHook s => s.SoundId,
                AnimDoneHook => AnimDone,
                _ => throw new InvalidOperationException($"unexpected hook {h}"),
            });
        }

        obj.ProcessHooks();
        return names.ToArray();
    }

    public static AnimationLibrary Library(params AnimClip[] clips)
    {
        var lib = new AnimationLibrary();
        foreach (AnimClip c in clips)
        {
            lib.Add(c);
        }

        return lib;
    }
}
