using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>MoveOrTeleport (acclient.c:323450) and newer_event (acclient.c:143014).</summary>
public class MoveOrTeleportTests
{
    private static Position At(float x, float y) => new(TickTestContext.OutdoorCell, new Vector3(x, y, 0f));

    [Fact]
    public void NewerEvent_IsWrapAroundAware()
    {
        var world = new PhysicsWorld();
        PhysicsObj obj = world.CreateObject();
        Assert.True(obj.NewerEvent(PhysicsTimeStamp.Teleport, 5));    // 0 -> 5: newer, stored
        Assert.False(obj.NewerEvent(PhysicsTimeStamp.Teleport, 5));   // equal: not newer
        Assert.False(obj.NewerEvent(PhysicsTimeStamp.Teleport, 3));   // older
        Assert.True(obj.NewerEvent(PhysicsTimeStamp.Teleport, 0x8004)); // |0x8004 - 5| = 0x7FFF: not wrapped, larger: newer
        Assert.True(obj.NewerEvent(PhysicsTimeStamp.Teleport, 2));    // |2 - 0x8004| = 0x8002 > 0x7FFF: wrapped, 2 < 0x8004: newer
        Assert.Equal((ushort)2, obj.GetUpdateTime(PhysicsTimeStamp.Teleport));
    }

    [Fact]
    public void NewerTeleportStamp_Teleports_StaleStampIsIgnored()
    {
        var world = new PhysicsWorld();
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f));
        Assert.True(obj.MoveOrTeleport(At(20f, 20f), 1, contact: false));
        Assert.Equal(new Vector3(20f, 20f, 0f), obj.Position.Frame.Origin);
        Assert.False(obj.MoveOrTeleport(At(5f, 5f), 0, contact: true)); // stamp 0 is older than 1
        Assert.Equal(new Vector3(20f, 20f, 0f), obj.Position.Frame.Origin);
    }

    [Fact]
    public void SameStamp_WithoutContact_IsRefused_WithContactNear_Interpolates_Far_Snaps()
    {
        var world = new PhysicsWorld();
        PhysicsObj obj = TickTestContext.CreateObject(world, new Vector3(10f, 10f, 0f));
        Assert.False(obj.MoveOrTeleport(At(11f, 10f), 0, contact: false));

        obj.UpdateObject(); // no player: player_distance stays FLT_MAX (>= 96) -> snap
        Assert.True(obj.MoveOrTeleport(At(12f, 10f), 0, contact: true));
        Assert.Equal(new Vector3(12f, 10f, 0f), obj.Position.Frame.Origin);

        world.Player = obj; // distance 0 after the next update_object
        obj.UpdateObject();
        Assert.Equal(0f, obj.PlayerDistance);
        Assert.True(obj.MoveOrTeleport(At(13f, 10f), 0, contact: true));
        Assert.NotNull(obj.PositionManager); // InterpolateTo created the position manager
        Assert.Equal(new Vector3(12f, 10f, 0f), obj.Position.Frame.Origin);
    }
}
