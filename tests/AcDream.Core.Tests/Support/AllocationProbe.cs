using System;
using Xunit;

namespace AcDream.Core.Tests.Support;

/// <summary>
/// Zero-allocation checks of a steady state. A window of work is measured with
/// <see cref="GC.GetAllocatedBytesForCurrentThread"/>; if it allocated, up to two further windows are measured. A real per-tick
/// allocation repeats in every window; a one-time event (a type's static initialiser first reached on this thread while other
/// tests run in parallel) does not. So the check passes when any window allocates nothing, and reports the smallest count.
/// </summary>
internal static class AllocationProbe
{
    public static void AssertSteadyStateAllocatesNothing(Action window, int attempts = 3)
    {
        long smallest = long.MaxValue;
        for (int i = 0; i < attempts; i++)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            window();
            long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
            if (allocated == 0)
            {
                return;
            }

            smallest = Math.Min(smallest, allocated);
        }

        Assert.Equal(0L, smallest);
    }
}
