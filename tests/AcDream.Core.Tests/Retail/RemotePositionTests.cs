using System;
using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Replay.Harness;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>The remote update path: MoveOrTeleport (acclient.c:323450) and SmartBox::HandleReceivedPosition (acclient.c:145124).</summary>
public class RemotePositionTests
{
    private static readonly Vector3 Start = new(50f, 50f, 0f);

    [Fact]
    public void ReceiveRemotePosition_InContactNearThePlayer_QueuesAndRearmsTheConstraintAtTheBody()
    {
        var s = new ManagerScene(Start);
        s.World.Tick(0.1);   // update_object measures player_distance (float.MaxValue until then, which would snap)
        Assert.True(s.Creature.PlayerDistance < 96f);
        Assert.True(s.Creature.ReceiveRemotePosition(ManagerScene.At(Start + new Vector3(0f, 2f, 0f)), false, true));
        Assert.Equal(1, s.Interpolation!.Count);
        ConstraintManager cm = s.Managers.ConstraintManager!;
        Assert.True(cm.IsConstrained);
        Assert.Equal(0f, cm.ConstraintPosOffset);
        Assert.Equal(10f, cm.ConstraintDistanceStart);
        Assert.Equal(50f, cm.ConstraintDistanceMax);
    }

    [Fact]
    public void ReceiveRemotePosition_WithoutContact_IsIgnored()
    {
        var s = new ManagerScene(Start);
        Assert.False(s.Creature.ReceiveRemotePosition(ManagerScene.At(Start + new Vector3(0f, 2f, 3f)), false, false));
        Assert.False(s.Creature.IsInterpolating());
        Assert.Null(s.Creature.PositionManager?.ConstraintManager);
    }

    [Fact]
    public void ReceiveRemotePosition_NinetySixMetresFromThePlayer_Snaps()
    {
        var s = new ManagerScene(new Vector3(96f, 96f + 100f, 0f));
        s.World.Tick(0.1);   // measures player_distance = 100
        Assert.True(s.Creature.PlayerDistance >= 96f);
        Position p = ManagerScene.At(new Vector3(96f, 196f + 2f, 0f));
        Assert.True(s.Creature.ReceiveRemotePosition(p, false, true));
        Assert.False(s.Creature.IsInterpolating());
        Assert.Equal(p.Frame.Origin, s.Creature.Position.Frame.Origin);
    }

    [Fact]
    public void ReceiveRemotePosition_Teleport_StopsInterpolatingAndPlaces()
    {
        var s = new ManagerScene(Start);
        s.Creature.ReceiveRemotePosition(ManagerScene.At(Start + new Vector3(0f, 2f, 0f)), false, true);
        Position p = ManagerScene.At(Start + new Vector3(30f, 0f, 0f));
        Assert.True(s.Creature.ReceiveRemotePosition(p, true, false));
        Assert.False(s.Creature.IsInterpolating());
        Assert.Equal(p.Frame.Origin, s.Creature.Position.Frame.Origin);
        Assert.Equal(0x1012u, (uint)s.Ground.LastPlacementFlags);
    }

    [Fact]
    public void ReceiveRemotePosition_BadPosition_Throws()
    {
        var s = new ManagerScene(Start);
        Position bad = ManagerScene.At(Start);
        bad.Frame.Origin = new Vector3(0f, float.NaN, 0f);
        Assert.Throws<ArgumentException>(() => s.Creature.ReceiveRemotePosition(bad, false, true));
        Assert.False(s.Creature.IsInterpolating());
    }
}
