using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Scene;

/// <summary>update_object's bail-outs and the 96 m player-distance gate (acclient.c:323080).</summary>
public class ActivityGateTests
{
    private const double Q = 0.0625;

    private static (PhysicsWorld World, PhysicsObj Player) WorldWithPlayer()
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj player = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f), spheres: 1, id: 0x50000001);
        player.SetState(player.State & ~PhysicsState.Gravity);
        player.CalcAcceleration();
        world.Player = player;
        return (world, player);
    }

    private static PhysicsObj Mover(PhysicsWorld world, Vector3 origin)
    {
        PhysicsObj obj = TickTestContext.CreateObject(world, origin);
        obj.SetState(obj.State & ~PhysicsState.Gravity);
        obj.CalcAcceleration();
        obj.SetVelocity(new Vector3(0f, 2f, 0f));
        return obj;
    }

    [Fact]
    public void ObjectBeyond96m_IsDeactivated_AndDoesNotMove()
    {
        var (world, _) = WorldWithPlayer();
        PhysicsObj far = Mover(world, new Vector3(110f, 10f, 0f)); // 100 m east of the player, same landblock
        PhysicsObj near = Mover(world, new Vector3(60f, 10f, 0f)); // 50 m
        Vector3 farStart = far.Position.Frame.Origin;

        for (int n = 1; n <= 8; n++)
        {
            Assert.True(world.Tick(n * Q));
        }

        Assert.Equal(100f, far.PlayerDistance);
        Assert.Equal(new Vector3(100f, 0f, 0f), far.PlayerVector);
        Assert.False(far.IsActive);
        Assert.Equal(farStart, far.Position.Frame.Origin);
        Assert.True(near.IsActive);
        Assert.Equal(10f + 2f * 8 * 0.0625f, near.Position.Frame.Origin.Y); // 2 m/s for 0.5 s = 1 m
    }

    [Fact]
    public void ObjectBeyond96m_IsKeptActive_WhenObjectMaintenanceIsOff()
    {
        var (world, _) = WorldWithPlayer();
        world.ObjectMaintenanceActive = false; // the gate applies only while obj_maint is active (acclient.c:323080)
        PhysicsObj far = Mover(world, new Vector3(110f, 10f, 0f));
        Assert.True(world.Tick(Q));
        Assert.True(far.IsActive);
        Assert.Equal(10.125f, far.Position.Frame.Origin.Y);
    }

    [Fact]
    public void ObjectComingBackInRange_RestartsItsClock_SoTheAbsenceIsNotSimulated()
    {
        var (world, _) = WorldWithPlayer();
        PhysicsObj obj = Mover(world, new Vector3(110f, 10f, 0f));
        Assert.True(world.Tick(Q));
        Assert.False(obj.IsActive);
        obj.StorePosition(new Position(TickTestContext.OutdoorCell, new Vector3(20f, 10f, 0f)));
        Assert.True(world.Tick(2 * Q));
        // set_active(1) on an inactive object sets update_time = now, so dt = 0 <= EPSILON: nothing simulated this tick.
        Assert.True(obj.IsActive);
        Assert.Equal(2 * Q, obj.UpdateTime);
        Assert.Equal(10f, obj.Position.Frame.Origin.Y);
    }

    [Fact]
    public void FrozenObject_DoesNotMove_AndKeepsItsUpdateTime()
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = Mover(world, new Vector3(10f, 10f, 0f));
        obj.SetState(obj.State | PhysicsState.Frozen);
        Assert.True(world.Tick(Q));
        Assert.False(obj.IsActive);
        Assert.Equal(0.0, obj.UpdateTime);
        Assert.Equal(new Vector3(10f, 10f, 0f), obj.Position.Frame.Origin);
    }

    [Fact]
    public void ParentedObject_DoesNotSimulate_ButFollowsItsParent()
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj parent = Mover(world, new Vector3(10f, 10f, 0f));
        PhysicsObj child = Mover(world, new Vector3(15f, 15f, 0f));
        var offset = new Frame(new Vector3(0f, 0f, 1f), System.Numerics.Quaternion.Identity);
        Assert.True(child.SetParent(parent, 99, offset)); // part 99 does not exist: relative to the parent's frame
        child.SetVelocity(new Vector3(5f, 0f, 0f)); // would move it if it were simulated

        Assert.True(world.Tick(Q));
        Assert.False(child.IsActive);
        Assert.Equal(10.125f, parent.Position.Frame.Origin.Y);
        // set_frame on the parent moved the child to parent frame combined with its offset.
        Assert.Equal(new Vector3(10f, 10.125f, 1f), child.Position.Frame.Origin);
        Assert.Equal(parent.CellId, child.CellId);
    }

    [Fact]
    public void ObjectWithoutPartArray_NeverEntersACell_AndIsNotSimulated()
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = world.CreateObject();
        // enter_cell does nothing without a part array (acclient.c:318201): EnterWorld says so and changes nothing
        Assert.False(obj.EnterWorld(new Position(TickTestContext.OutdoorCell, new Vector3(10f, 10f, 0f))));
        Assert.Equal(0u, obj.CellId);
        obj.StorePosition(new Position(TickTestContext.OutdoorCell, new Vector3(10f, 10f, 0f)));
        obj.SetVelocity(new Vector3(1f, 0f, 0f));
        Assert.True(world.Tick(Q));
        Assert.False(obj.IsActive);
        Assert.Equal(new Vector3(10f, 10f, 0f), obj.Position.Frame.Origin);
    }

    [Fact]
    public void StaticObject_RefusesActivation()
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = world.CreateObject();
        obj.SetState(PhysicsState.Static);
        Assert.False(obj.SetActive(true));
        Assert.False(obj.IsActive);
    }
}
