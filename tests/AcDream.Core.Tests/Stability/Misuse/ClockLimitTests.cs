using System;
using System.Linq;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability.Misuse;

/// <summary>
/// Issue #15 item 15: clock times from 2^40 s on are refused (the world constructor, SetCurrentTime, Tick), state unchanged;
/// just below the limit a 1/30 s tick still runs a step. Before the fix 1e15 s was accepted and the world silently stopped:
/// the double spacing there is 0.125 s, so now − last_update is 0 or 0.125 and the 1/30 s gate no longer resolves.
/// </summary>
public class ClockLimitTests
{
    // 2^40 s; the double just below it is 2^40 − 2^-13 (the spacing in [2^39, 2^40) is 2^(39−52) = 2^-13 s).
    private const double Limit = 1099511627776.0;
    private const double BelowLimit = Limit - 1.0 / 8192.0;

    [Fact]
    public void MaxClockTime_Is2To40Seconds()
    {
        Assert.Equal(Limit, InputLimits.MaxClockTime);
        Assert.Equal(0x4270000000000000L, BitConverter.DoubleToInt64Bits(InputLimits.MaxClockTime)); // 2^40
        Assert.Equal(BelowLimit, Math.BitDecrement(Limit));
    }

    [Theory]
    [InlineData(Limit)]
    [InlineData(-Limit)]
    [InlineData(1e15)]
    [InlineData(double.MaxValue)]
    public void ClockAtOrBeyondTheLimit_IsRefused_StateUnchanged(double t)
    {
        Assert.Throws<ArgumentException>(() => new PhysicsWorld(t));
        var s = new MisuseScene();
        PublicState before = PublicState.Capture(s);
        Assert.Throws<ArgumentException>(() => s.World.Tick(t));
        Assert.Throws<ArgumentException>(() => s.World.SetCurrentTime(t));
        Assert.Empty(PublicState.Diff(before, PublicState.Capture(s)));
    }

    [Fact]
    public void JustBelowTheLimit_A30HzTickStillSteps()
    {
        // Start 1 s below the limit: t0 = 2^40 − 1 (exact). There each tick's + 1/30 s rounds to 273 spacings of 2^-13 s
        // (1/30 s = 273.07 spacings) = 0.0333252 s, just below the 1/30 s gate (0.0333333 s), so the world refuses it; the next
        // tick has 546 spacings = 0.0666504 s and runs. 20 ticks of 1/30 s give 10 world updates, each stepping the object
        // once (EPSILON < dt <= MaxQuantum): the clock still resolves the tick, though coarsely (retail arithmetic).
        // (Every object visited: the object comes to rest on the floor by friction after 9 steps, and the scene would then skip
        // its inactive visit as dormant, unseen by the step observer.)
        double t0 = Limit - 1.0;
        var world = new PhysicsWorld(t0) { Sweep = new FlatGroundSweep(), VisitEveryObject = true };
        var steps = new StepRecorder();
        world.StepObserver = steps;
        TickTestContext.CreateObject(world, new System.Numerics.Vector3(50f, 50f, 100f)).SetVelocity(new System.Numerics.Vector3(1f, 0f, 0f));
        int updates = 0;
        double now = t0;
        for (int i = 0; i < 20; i++)
        {
            now += 1.0 / 30.0;
            if (world.Tick(now))
            {
                updates++;
            }
        }

        Assert.True(now < Limit);
        Assert.Equal(10, updates);
        Assert.True(steps.Count == 10, $"{steps.Count} steps: " + string.Join(", ", Enumerable.Range(0, steps.Count).Select(i => $"{steps.Quantum(i)}@{steps.Time(i) - t0}")));
    }
}
