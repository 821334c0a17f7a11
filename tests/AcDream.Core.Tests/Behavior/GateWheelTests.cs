using System;
using System.Collections.Generic;
using AcDream.Core.Physics;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>The gate's timing wheel gives out exactly the entries whose key the clock has reached, across both levels, the
/// overflow bucket and jumps of the clock (teleports), and stops allocating once grown.</summary>
public class GateWheelTests
{
    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    [InlineData(3)]
    public void PopDue_GivesExactlyTheEntriesWhoseKeyTheClockReached(int seed)
    {
        var rng = new Random(seed);
        var wheel = new GateWheel(new GateQueue());
        var pending = new Dictionary<int, double>(); // id -> key
        var due = new GateEntry[4];
        double clock = rng.NextDouble() * 100.0;
        int nextId = 0;
        for (int step = 0; step < 3000; step++)
        {
            // Add a few entries: mostly near (a few metres), some far (up to 20 km, beyond the far level's 8 km span).
            int adds = rng.Next(0, 6);
            for (int a = 0; a < adds; a++)
            {
                double margin = rng.Next(4) switch
                {
                    0 => rng.NextDouble() * 0.1,
                    1 => rng.NextDouble() * 8.0,
                    2 => rng.NextDouble() * 300.0,
                    _ => rng.NextDouble() * 20_000.0,
                };
                int id = nextId++;
                pending[id] = clock + margin;
                wheel.Push(new GateEntry { X = id }, clock + margin);
            }

            // Advance: usually a walking step, sometimes standing still, now and then a teleport of kilometres.
            int kind = rng.Next(100);
            clock += kind < 10 ? 0.0 : kind < 97 ? rng.NextDouble() * 0.4 : rng.NextDouble() * 12_000.0;
            int n = wheel.PopDue(clock, ref due, 0);
            var popped = new HashSet<int>();
            for (int i = 0; i < n; i++)
            {
                int id = (int)due[i].X;
                Assert.True(pending.TryGetValue(id, out double key), $"step {step}: entry {id} popped twice");
                Assert.True(key <= clock, $"step {step}: entry {id} with key {key} popped at clock {clock}");
                Assert.Equal(key, due[i].Key);
                popped.Add(id);
                pending.Remove(id);
            }

            foreach (KeyValuePair<int, double> p in pending)
            {
                Assert.True(p.Value > clock, $"step {step}: entry {p.Key} with key {p.Value} not popped at clock {clock}");
            }

            Assert.Equal(pending.Count, wheel.Count);
        }
    }

    [Fact]
    public void SteadyRequeueing_StopsAllocating()
    {
        // 5,000 entries re-queued as they come due, over many revolutions of both levels: after warm-up, no allocation.
        var rng = new Random(7);
        var wheel = new GateWheel(new GateQueue());
        var due = new GateEntry[16];
        double clock = 0.0;
        for (int i = 0; i < 5000; i++)
        {
            wheel.Push(new GateEntry { X = i }, rng.NextDouble() * 50.0);
        }

        void Run(int steps)
        {
            for (int s = 0; s < steps; s++)
            {
                clock += 0.07;
                int n = wheel.PopDue(clock, ref due, 0);
                for (int i = 0; i < n; i++)
                {
                    wheel.Push(due[i], clock + 0.05 + (due[i].X * 7919 % 5000) * 0.01); // 0.05 .. 50 m ahead
                }
            }
        }

        Run(20_000);
        long before = GC.GetAllocatedBytesForCurrentThread();
        Run(20_000);
        Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
        Assert.Equal(5000, wheel.Count);
    }
}
