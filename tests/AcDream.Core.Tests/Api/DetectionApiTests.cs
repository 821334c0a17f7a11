using System;
using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Tests.Replay.Harness;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>Misuse of the detection manager's public calls: refused before anything changes.</summary>
public class DetectionApiTests
{
    private static (ManagerScene s, DetectionManager dm) Scene()
    {
        var s = new ManagerScene(new Vector3(96f, 100f, 0f));
        var dm = new DetectionManager(s.Player, new DetectionRecorder());
        s.Player.DetectionManager = dm;
        return (s, dm);
    }

    [Theory]
    [InlineData(float.NaN)]
    [InlineData(float.PositiveInfinity)]
    [InlineData(float.NegativeInfinity)]
    [InlineData(-1f)]
    [InlineData(0f)]
    [InlineData(65537f)]
    public void BadRadius_Throws_NothingChanged(float radius)
    {
        var (s, dm) = Scene();
        var ex = Assert.Throws<ArgumentException>(() => dm.CreateDetectionCylsphere(1, s.Creature.Id, radius));
        Assert.Equal("radius", ex.ParamName);
        Assert.Equal(0, dm.Count);
        Assert.False(dm.Contains(1));
    }

    [Fact]
    public void LargestRadius_IsAccepted()
    {
        var (s, dm) = Scene();
        dm.CreateDetectionCylsphere(1, s.Creature.Id, 65536f);
        Assert.True(dm.Contains(1));
    }

    [Fact]
    public void GlobalDetection_ObjectIdZero_IsAccepted()
    {
        // Object id 0 is retail's global detection (DetectionManager::CheckDetection 327546), now that cells keep voyeurs.
        var (_, dm) = Scene();
        dm.CreateDetectionCylsphere(1, 0, 5f);
        Assert.True(dm.Contains(1));
        Assert.Equal(1, dm.Count);
    }

    [Fact]
    public void DuplicateContextId_Throws_FirstKept()
    {
        var (s, dm) = Scene();
        dm.CreateDetectionCylsphere(1, s.Creature.Id, 5f);
        var ex = Assert.Throws<ArgumentException>(() => dm.CreateDetectionCylsphere(1, s.Creature.Id, 9f));
        Assert.Equal("contextId", ex.ParamName);
        Assert.Equal(1, dm.Count);
        Assert.Equal(5f, dm.Find(1)!.Radius);
    }

    [Fact]
    public void ManagerOfAnotherObject_IsRefusedBySetter()
    {
        var (s, dm) = Scene();
        var ex = Assert.Throws<ArgumentException>(() => s.Creature.DetectionManager = dm);
        Assert.Equal("value", ex.ParamName);
        Assert.Null(s.Creature.DetectionManager);
    }

    [Fact]
    public void NullArguments_Throw()
    {
        var (s, _) = Scene();
        Assert.Throws<ArgumentNullException>(() => new DetectionManager(null!, new DetectionRecorder()));
        Assert.Throws<ArgumentNullException>(() => new DetectionManager(s.Player, null!));
    }

    [Fact]
    public void WatchingAnAbsentId_IsAccepted_AndReportsLeftAtTheCheck()
    {
        // Retail looks the object up at each check; an id not in the world is LeftDetection (reported each check).
        var (s, dm) = Scene();
        var rec = (DetectionRecorder)dm.Listener;
        dm.CreateDetectionCylsphere(1, 0x12345678u, 5f);
        for (int k = 1; k <= 16; k++)
        {
            s.World.Tick(k * 0.0625);
        }

        Assert.Equal(1, rec.Count);
        Assert.Equal(DetectionStatus.Left, rec.Info(0).Status);
        Assert.Equal(0x12345678u, rec.Info(0).ObjectId);
    }
}
