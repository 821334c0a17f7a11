using System;
using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Tests.Replay.Harness;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>The remote update path: SmartBox::HandleReceivedPosition (acclient.c:145124) through MoveOrTeleport (acclient.c:323450).</summary>
public class RemotePositionTests
{
    private static readonly Vector3 Start = new(50f, 50f, 0f);

    private static Position North(float metres, float z = 0f) => ManagerScene.At(Start + new Vector3(0f, metres, z));

    private static ManagerScene Measured()
    {
        var s = new ManagerScene(Start);
        s.World.Tick(0.1);   // update_object measures player_distance (float.MaxValue until then, which would snap)
        Assert.True(s.Creature.PlayerDistance < 96f);
        return s;
    }

    [Fact]
    public void Report_InContactNearThePlayer_QueuesAndRearmsTheConstraintAtTheBody()
    {
        ManagerScene s = Measured();
        Assert.Equal(ReceivedPositionResult.Interpolating, s.Creature.HandleReceivedPosition(North(2f), 1, 0, true));
        Assert.Equal(1, s.Interpolation!.Count);
        ConstraintManager cm = s.Managers.ConstraintManager!;
        Assert.True(cm.IsConstrained);
        Assert.Equal(0f, cm.ConstraintPosOffset);   // distance(body, body)
        Assert.Equal(10f, cm.ConstraintDistanceStart);
        Assert.Equal(50f, cm.ConstraintDistanceMax);
    }

    [Fact]
    public void Report_NotNewerThanTheLastPositionTimestamp_IsDropped()
    {
        ManagerScene s = Measured();
        Assert.Equal(ReceivedPositionResult.Interpolating, s.Creature.HandleReceivedPosition(North(2f), 5, 0, true));
        Assert.Equal(ReceivedPositionResult.Stale, s.Creature.HandleReceivedPosition(North(4f), 5, 0, true));   // duplicate
        Assert.Equal(ReceivedPositionResult.Stale, s.Creature.HandleReceivedPosition(North(6f), 4, 0, true));   // late
        Assert.Equal(1, s.Interpolation!.Count);
        // 16-bit wrap (newer_event): 0 -> 30000 -> 60000 are newer (gaps <= 0x7FFF); then 2 is newer than 60000 because the
        // gap 59998 exceeds 0x7FFF and 2 < 60000.
        var w = Measured();
        Assert.Equal(ReceivedPositionResult.Interpolating, w.Creature.HandleReceivedPosition(North(2f), 30000, 0, true));
        Assert.Equal(ReceivedPositionResult.Interpolating, w.Creature.HandleReceivedPosition(North(3f), 60000, 0, true));
        Assert.Equal(ReceivedPositionResult.Interpolating, w.Creature.HandleReceivedPosition(North(4f), 2, 0, true));
    }

    [Fact]
    public void Report_WithoutContact_IsIgnoredButConsumesItsTimestamp()
    {
        ManagerScene s = Measured();
        Assert.Equal(ReceivedPositionResult.NoContact, s.Creature.HandleReceivedPosition(North(2f, 3f), 1, 0, false));
        Assert.False(s.Creature.IsInterpolating);
        Assert.Null(s.Creature.PositionManager?.ConstraintManager);
        Assert.Equal((ushort)1, s.Creature.GetUpdateTime(PhysicsTimeStamp.Position));
    }

    [Fact]
    public void Report_NinetySixMetresFromThePlayer_Snaps()
    {
        var s = new ManagerScene(new Vector3(96f, 196f, 0f));
        s.World.Tick(0.1);   // player_distance = 100
        Assert.True(s.Creature.PlayerDistance >= 96f);
        Position p = ManagerScene.At(new Vector3(96f, 198f, 0f));
        Assert.Equal(ReceivedPositionResult.Placed, s.Creature.HandleReceivedPosition(p, 1, 0, true));
        Assert.False(s.Creature.IsInterpolating);
        Assert.Equal(p.Frame.Origin, s.Creature.Position.Frame.Origin);
    }

    [Fact]
    public void Report_NewerTeleport_StopsInterpolatingAndPlaces_OlderTeleportIsDroppedAndRestoresTheStamp()
    {
        ManagerScene s = Measured();
        s.Creature.HandleReceivedPosition(North(2f), 1, 0, true);
        Position p = ManagerScene.At(Start + new Vector3(30f, 0f, 0f));
        Assert.Equal(ReceivedPositionResult.Placed, s.Creature.HandleReceivedPosition(p, 2, 1, false));
        Assert.False(s.Creature.IsInterpolating);
        Assert.Equal(p.Frame.Origin, s.Creature.Position.Frame.Origin);
        Assert.Equal(0x1012u, (uint)s.Ground.LastPlacementFlags);
        Assert.Equal(ReceivedPositionResult.StaleTeleport, s.Creature.HandleReceivedPosition(North(5f), 3, 0, true));
        Assert.Equal((ushort)2, s.Creature.GetUpdateTime(PhysicsTimeStamp.Position));
    }

    [Fact]
    public void Report_BadPosition_ThrowsAndKeepsTheTimestamp()
    {
        ManagerScene s = Measured();
        Position bad = North(1f);
        bad.Frame.Origin = new Vector3(0f, float.NaN, 0f);
        Assert.Throws<ArgumentException>(() => s.Creature.HandleReceivedPosition(bad, 1, 0, true));
        Assert.False(s.Creature.IsInterpolating);
        Assert.Equal((ushort)0, s.Creature.GetUpdateTime(PhysicsTimeStamp.Position));
    }
}
