using System;
using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// Issue #34, item 4: a stick's step is bounded by <see cref="StickyManager.MaxStep"/> (100 m), as root motion is by
/// <c>PhysicsObj.BoundRootMotion</c>: retail's step (<c>StickyManager::adjust_offset</c>, acclient.c:388518) is the gap to the
/// standoff point or 5 × max speed × quantum, unbounded, and a target radius of 300 m with a run rate of 50 made it 200 m,
/// longer than the sweep takes (192 m): the tick threw.
/// </summary>
public class StickyStepBoundTests
{
    // A remote creature (run rate from MyRunRate) at (100, 100) stuck to a target 5 m north whose bounding radius is 300 m.
    private static (PhysicsWorld World, PhysicsObj Obj, PhysicsObj Target) Stuck(float runRate)
    {
        PhysicsWorld world = MoveToScene.FlatWorld();
        PhysicsObj obj = MoveToScene.Creature(world, 5, RemoteCreatureWeenie.Creature, new Vector3(100f, 100f, 20f));
        MovementManager.Of(obj).GetOrCreateMotionInterpreter().MyRunRate = runRate;
        PhysicsObj target = world.CreateObject(7);
        target.PartArray = new SimplePartArray(1, 1) { Radius = 300f };
        Assert.True(target.EnterWorld(MoveToScene.At(100f, 105f)));
        obj.StickToObject(7);
        obj.HandleUpdateTarget(new TargetInfo { ObjectId = 7, Status = TargetStatus.Ok, TargetPosition = target.Position });
        return (world, obj, target);
    }

    [Theory]
    // mag = 5 - (0.5 + 300) - 0.3 = -295.8 m; speed = get_max_speed (4 × 50 = 200) × 5 = 1,000 m/s. The step
    // 1,000 × quantum is below |mag|, so retail moves that far towards the target (acclient.c:388600-388605):
    [InlineData(0.2, 100f)]   // retail 200 m: shortened to 100 m along its direction (k = 100 / 200 = 0.5, exact)
    [InlineData(0.1, 100f)]   // retail 100 m: at the bound, unchanged
    [InlineData(0.05, 50f)]   // retail 50 m: unchanged
    public void Step_IsRetailsUpToTheBound_ThenShortenedAlongItsDirection(double quantum, float expected)
    {
        (_, PhysicsObj obj, _) = Stuck(50f);
        Frame offset = Frame.Identity;
        obj.PositionManager!.StickyManager!.AdjustOffset(ref offset, quantum);
        Assert.Equal(0f, offset.Origin.X);
        Assert.Equal(expected, offset.Origin.Y);
        Assert.Equal(0f, offset.Origin.Z);
    }

    [Fact]
    public void RadiusThreeHundred_RunRateFifty_TicksAtFiveHertz_NeverThrow()
    {
        (PhysicsWorld world, PhysicsObj obj, _) = Stuck(50f);
        for (int i = 1; i <= 10; i++)
        {
            world.Tick(world.CurrentTime + 0.2);
            Vector3 o = obj.Position.Frame.Origin;
            Assert.True(float.IsFinite(o.X) && float.IsFinite(o.Y) && float.IsFinite(o.Z));
        }
    }
}
