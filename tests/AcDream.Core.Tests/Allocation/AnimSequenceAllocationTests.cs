using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Retail;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Allocation;

/// <summary>A playing sequence allocates nothing per update: frames, root motion, hooks queued and run, links played out
/// and new ones queued (the nodes come from the sequence's pool).</summary>
public class AnimSequenceAllocationTests
{
    [Fact]
    public void PlayingAndRequeueing_AllocatesNothing_AfterWarmUp()
    {
        var link = new AnimationBytes(0x03000001);
        var cycle = new AnimationBytes(0x03000002);
        for (int k = 0; k < 4; k++)
        {
            link.Frame(new Vector3(0.1f, 0f, 0f)).Sound((uint)k, AnimHookDirection.Both);
            cycle.Frame(new Vector3(0f, 0.1f, 0f), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.05f))
                .Sound(10u + (uint)k, AnimHookDirection.Forward);
        }

        AnimationLibrary lib = AnimTestSupport.Library(link.Build(), cycle.Build());
        PhysicsObj obj = AnimTestSupport.HookObject(out PhysicsWorld _);
        var seq = new AnimSequence(lib);
        seq.SetObject(obj);
        seq.SetVelocity(new Vector3(0f, 1f, 0f));
        seq.SetOmega(new Vector3(0f, 0f, 0.5f));
        var linkData = new AnimData(0x03000001, 0, -1, 30f);
        var cycleData = new AnimData(0x03000002, 0, -1, 30f);
        Frame f = Frame.Identity;

        void Window()
        {
            for (int i = 0; i < 60; i++)
            {
                if (i % 20 == 0)
                {
                    // A new motion: drop the cycle, queue a link and a cycle (as the motion table does).
                    seq.RemoveCyclicAnims();
                    seq.AppendAnimation(linkData);
                    seq.AppendAnimation(cycleData);
                }

                seq.Update(1.0 / 30.0, ref f);
                obj.ProcessHooks();
                f = Frame.Identity;
            }
        }

        Window();
        AllocationProbe.AssertSteadyStateAllocatesNothing(Window);
    }
}
