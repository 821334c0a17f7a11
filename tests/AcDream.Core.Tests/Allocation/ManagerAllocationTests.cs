using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Tests.Replay.Harness;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Allocation;

/// <summary>The managers allocate nothing per update or per tick once the object and its managers exist.</summary>
public class ManagerAllocationTests
{
    [Fact]
    public void UpdatesAndTicks_AfterWarmUp_AllocateZeroBytes()
    {
        var s = new ManagerScene(new Vector3(60f, 40f, 0f));
        s.CreatureParts.SequenceVelocity = new Vector3(0f, 4f, 0f);
        s.Managers.StickTo(99, 0.5f, 1f);
        var positions = new Position[64];
        for (int i = 0; i < positions.Length; i++)
        {
            positions[i] = ManagerScene.At(new Vector3(60f, 40f + (i * 0.4f), 0f));
        }

        var far = ManagerScene.At(new Vector3(60f, 190f, 0f));
        double now = 0;
        ushort stamp = 0;
        void Run(int frames)
        {
            for (int f = 0; f < frames; f++)
            {
                now += 1.0 / 30.0;
                int k = f % positions.Length;
                stamp++;
                s.Creature.HandleReceivedPosition(positions[k], stamp, 0, true);
                if (f % 50 == 49)
                {
                    stamp++;
                    s.Creature.HandleReceivedPosition(far, stamp, 0, true);   // far branch + blip
                }

                s.World.Tick(now);
            }
        }

        Run(300);
        AllocationProbe.AssertSteadyStateAllocatesNothing(() => Run(1000));
    }

    [Fact]
    public void InterpolationRing_NeverGrowsPastTwentyNodes()
    {
        var s = new ManagerScene(new Vector3(60f, 40f, 0f));
        for (int i = 1; i <= 200; i++)
        {
            s.Creature.InterpolateTo(ManagerScene.At(new Vector3(60f, 40f + (i * 0.3f), 0f)), false);
            Assert.InRange(s.Interpolation!.Count, 1, InterpolationManager.MaxQueueLength);
        }

        // Far updates (150 m from the tail each time) append without retail's cap; the ring evicts the head instead.
        for (int i = 0; i < 30; i++)
        {
            float y = i % 2 == 0 ? 240f : 40f;
            s.Creature.InterpolateTo(ManagerScene.At(new Vector3(60f, y, 0f)), false);
            Assert.Equal(InterpolationManager.FarBranchFailCount, s.Interpolation!.NodeFailCounter);
        }

        Assert.Equal(InterpolationManager.MaxQueueLength, s.Interpolation!.Count);
        Assert.Equal(40f, s.Interpolation!.GetNode(19).Position.Frame.Origin.Y, 3);
    }
}
