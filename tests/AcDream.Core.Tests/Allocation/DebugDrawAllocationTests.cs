using System.Numerics;
using AcDream.Core.Physics.Debug;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Allocation;

/// <summary>The debug view allocates nothing per call with a struct sink (issue #36 item 4): the whole world and a box.</summary>
public class DebugDrawAllocationTests
{
    [Fact]
    public void Draw_AllocatesNothing()
    {
        PhysicsWorld world = DebugDrawScene.Build(out _);
        world.ObjectMaintenanceActive = false;
        world.Tick(0.1);
        world.Tick(0.2);
        var view = new PhysicsDebugDraw(world);
        DebugDrawRegion all = DebugDrawRegion.Everything(0x8080FFFFu);
        DebugDrawRegion box = DebugDrawRegion.Box(0x8080FFFFu, new Vector2(90f, 90f), new Vector2(160f, 160f));
        var sink = new CountingSink();
        view.Draw(ref sink, DebugDrawFlags.All, all);
        int perCall = sink.Calls;
        Assert.True(perCall > 400, $"the warm-up call should see the scene's shapes, got {perCall}");

        AllocationProbe.AssertSteadyStateAllocatesNothing(() =>
        {
            for (int i = 0; i < 20; i++)
            {
                view.Draw(ref sink, DebugDrawFlags.All, all);
                view.Draw(ref sink, DebugDrawFlags.All, box);
            }
        });
    }
}
