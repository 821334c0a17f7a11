using System;
using AcDream.Core.Physics.World;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// <see cref="PhysicsWorld.MaxConsecutiveDiscardedFrames"/>: the opt-in strict clock check (issue #33). Off by default
/// (retail discards a frame longer than 2 s silently, so a clock in milliseconds freezes the world); when set, the tick that
/// makes that many consecutive discarded frames throws after finishing as retail does.
/// </summary>
public sealed class DiscardedFrameLimitTests
{
    [Fact]
    public void Default_IsRetails_DiscardedFramesAreOnlyCounted()
    {
        var world = new PhysicsWorld(0.0);
        Assert.Equal(0, world.MaxConsecutiveDiscardedFrames);
        for (int f = 1; f <= 10; f++)
        {
            world.Tick(f * 16.7);                                // a clock in milliseconds: every frame 16.7 "s" long
        }

        Assert.Equal(10, world.DiscardedFrames);
    }

    [Fact]
    public void Limit_ThrowsOnTheFrameThatReachesIt_AfterTheTick()
    {
        var world = new PhysicsWorld(0.0) { MaxConsecutiveDiscardedFrames = 3 };
        world.Tick(16.7);
        world.Tick(33.4);
        var e = Assert.Throws<InvalidOperationException>(() => world.Tick(50.1));
        Assert.Contains("3 consecutive frames were discarded", e.Message);
        Assert.Contains("milliseconds", e.Message);
        Assert.Equal(3, world.DiscardedFrames);
        Assert.Equal(50.1, world.LastUpdate);                    // the tick finished as retail's before the throw
        Assert.Throws<InvalidOperationException>(() => world.Tick(66.8));   // still over the limit: throws again
    }

    [Fact]
    public void Limit_CountsOnlyConsecutiveFrames()
    {
        // 16.7 s gaps are discarded; a 0.05 s frame runs the objects and resets the run; a clock going back is discarded.
        var world = new PhysicsWorld(0.0) { MaxConsecutiveDiscardedFrames = 2 };
        world.Tick(16.7);
        world.Tick(16.75);
        world.Tick(33.45);
        world.Tick(33.5);
        Assert.Equal(2, world.DiscardedFrames);
        Assert.Throws<InvalidOperationException>(() =>
        {
            world.Tick(20.0);                                    // back in time: discarded (1)
            world.Tick(40.0);                                    // 20 s: discarded (2), throws
        });
        Assert.Equal(4, world.DiscardedFrames);
    }

    [Fact]
    public void Limit_Negative_IsRefused()
    {
        var world = new PhysicsWorld(0.0) { MaxConsecutiveDiscardedFrames = 5 };
        Assert.Throws<ArgumentOutOfRangeException>(() => world.MaxConsecutiveDiscardedFrames = -1);
        Assert.Equal(5, world.MaxConsecutiveDiscardedFrames);
    }
}
