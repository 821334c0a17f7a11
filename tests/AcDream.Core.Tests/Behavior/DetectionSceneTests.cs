using System;
using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Tests.Replay.Harness;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// An object watching another with a detection cylinder (retail <c>DetectionManager</c>). The scene: the player (id 1, radius
/// 0.5) at (96, 96, 0) is the detector; the creature (id 2, radius 0.5) stands north of it at a distance set by placement.
/// The world ticks every 1/16 s (one step each: 1/30 &lt; 1/16 &lt;= 0.1 s), so the physics time of each step is exact and
/// the detection check runs at the first step with time - last check &gt;= 1.0: t = 1, 2, 3 ... s. Inside when the float
/// centre distance is below cylinder radius 5 + creature radius 0.5 = 5.5 m.
/// </summary>
public class DetectionSceneTests
{
    private const uint Context = 7;

    private static (ManagerScene s, DetectionManager dm, DetectionRecorder rec) Scene(float creatureDistance)
    {
        var s = new ManagerScene(new Vector3(96f, 96f + creatureDistance, 0f));
        var rec = new DetectionRecorder();
        var dm = new DetectionManager(s.Player, rec);
        s.Player.DetectionManager = dm;
        dm.CreateDetectionCylsphere(Context, s.Creature.Id, 5f);
        return (s, dm, rec);
    }

    // Ticks from the last tick time (16 per second) up to `until`, placing the creature `distance` north of the player first.
    private static void RunTo(ManagerScene s, double until, float? distance = null)
    {
        if (distance is float d)
        {
            s.Creature.SetPosition(ManagerScene.At(new Vector3(96f, 96f + d, 0f)), SetPositionFlags.Placement);
        }

        while (s.World.CurrentTime < until)
        {
            s.World.Tick(s.World.CurrentTime + 0.0625);
        }
    }

    [Fact]
    public void CreatureWalkingInAndOut_ReportsEnteredThenLeft_AtTheOnceASecondChecks()
    {
        var (s, dm, rec) = Scene(10f);
        RunTo(s, 1.5);                 // t = 1: 10 >= 5.5 and not detected: no change
        RunTo(s, 2.5, 5.5f);           // t = 2: 5.5 <= 5.5 counts as outside: no change
        Assert.Equal(0, rec.Count);
        RunTo(s, 3.5, 5.25f);          // t = 3: 5.25 < 5.5: entered
        RunTo(s, 4.5, 1f);             // t = 4: still inside: no change
        RunTo(s, 5.5, 8f);             // t = 5: 8 >= 5.5 and detected: left
        RunTo(s, 6.5);                 // t = 6: outside, not detected: no change

        Assert.Equal(2, rec.Count);
        Assert.Equal(3.0, rec.Time(0));
        Assert.Equal(Context, rec.Context(0));
        Assert.Equal(2u, rec.Info(0).ObjectId);
        Assert.Equal(DetectionStatus.Entered, rec.Info(0).Status);
        Assert.Equal(5.0, rec.Time(1));
        Assert.Equal(DetectionStatus.Left, rec.Info(1).Status);
        Assert.Equal(6.0, dm.LastUpdateTime);
    }

    [Fact]
    public void DestroyedCylinder_ReportsNothing_AndIsDroppedAtTheNextCheck()
    {
        var (s, dm, rec) = Scene(10f);
        RunTo(s, 1.5);
        Assert.True(dm.DestroyDetectionCylsphere(Context));
        Assert.False(dm.DestroyDetectionCylsphere(99));
        Assert.Equal(1, dm.Count);     // deferred: retail's pending deletions
        RunTo(s, 3.5, 1f);             // the next step drops it; no check reports the creature inside
        Assert.Equal(0, dm.Count);
        Assert.Equal(0, rec.Count);

        // The context id is free again.
        dm.CreateDetectionCylsphere(Context, s.Creature.Id, 5f);
        RunTo(s, 4.5);                 // t = 4: inside: entered
        Assert.Equal(1, rec.Count);
        Assert.Equal(DetectionStatus.Entered, rec.Info(0).Status);
    }

    [Fact]
    public void WatchedObjectRemoved_ReportsLeftAtEveryCheckWhileAbsent()
    {
        var (s, _, rec) = Scene(2f);
        RunTo(s, 1.5);                 // t = 1: entered
        s.World.RemoveObject(s.Creature);
        RunTo(s, 3.5);                 // t = 2 and 3: not in the world: retail sets LeftDetection and reports it each check

        Assert.Equal(3, rec.Count);
        Assert.Equal(DetectionStatus.Entered, rec.Info(0).Status);
        Assert.Equal(DetectionStatus.Left, rec.Info(1).Status);
        Assert.Equal(2.0, rec.Time(1));
        Assert.Equal(DetectionStatus.Left, rec.Info(2).Status);
        Assert.Equal(3.0, rec.Time(2));
    }

    [Fact]
    public void ListenerRemovingTheDetector_EndsThePass_AndTheDetectorsCylindersAreGone()
    {
        var (s, dm, rec) = Scene(2f);
        dm.CreateDetectionCylsphere(Context + 1, s.Creature.Id, 5f);
        rec.OnReport = (detector, _) => detector.World.RemoveObject(detector);
        RunTo(s, 2.5);

        Assert.Equal(1, rec.Count);    // the second cylinder's report was dropped with the detector
        Assert.True(s.Player.RemovedFromWorld);
        Assert.Equal(0, dm.Count);
    }

    [Fact]
    public void ListenerRemovingTheWatchedObject_IsSafe()
    {
        var (s, _, rec) = Scene(2f);
        rec.OnReport = (detector, info) =>
        {
            PhysicsObj? o = detector.World.GetObjectById(info.ObjectId);
            if (o is not null)
            {
                detector.World.RemoveObject(o);
            }
        };
        RunTo(s, 2.5);                 // t = 1: entered (creature removed); t = 2: left

        Assert.Equal(2, rec.Count);
        Assert.Equal(DetectionStatus.Left, rec.Info(1).Status);
    }

    [Fact]
    public void DetectorRemovedFromWorld_DropsItsCylinders()
    {
        var (s, dm, _) = Scene(2f);
        s.World.RemoveObject(s.Player);
        Assert.Equal(0, dm.Count);
        Assert.Throws<InvalidOperationException>(() => dm.CreateDetectionCylsphere(1, 2, 1f));
    }
}
