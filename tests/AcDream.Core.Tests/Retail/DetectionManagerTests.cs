using System;
using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Tests.Replay.Harness;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>Retail <c>DetectionManager</c> (CDetectionCylsphere.c) pinned from the decompiled code.</summary>
public class DetectionManagerTests
{
    [Fact]
    public void Constants()
    {
        // CheckDetection (acclient.c:327672): PhysicsTimer::curr_time - last_update_time >= 1.0
        Assert.Equal(0x3FF0000000000000ul, BitConverter.DoubleToUInt64Bits(DetectionManager.UpdateInterval));
        Assert.Equal(0u, (uint)DetectionStatus.NoChange);
        Assert.Equal(1u, (uint)DetectionStatus.Entered);
        Assert.Equal(2u, (uint)DetectionStatus.Left);
    }

    [Theory]
    // Detector at (96, 96), object radius 0.5, cylinder radius 5: inside iff float distance < 0.5 + 5 = 5.5 (acclient.c:327020:
    // "if (GetRadius + radius <= distance)" is outside).
    [InlineData(5.5f, false, DetectionStatus.NoChange, false)]
    [InlineData(5.4990234f, false, DetectionStatus.Entered, true)]
    [InlineData(5.4990234f, true, DetectionStatus.NoChange, true)]
    [InlineData(5.5f, true, DetectionStatus.Left, false)]
    [InlineData(20f, false, DetectionStatus.NoChange, false)]
    public void CheckDetection_Object(float distance, bool wasDetected, DetectionStatus expected, bool detectedAfter)
    {
        var s = new ManagerScene(new Vector3(96f, 96f + distance, 0f));
        var dm = new DetectionManager(s.Player, new DetectionRecorder());
        s.Player.DetectionManager = dm;
        dm.CreateDetectionCylsphere(3, s.Creature.Id, 5f);
        DetectionCylsphere c = dm.Find(3)!;
        c.ObjectDetected = wasDetected;
        Assert.Equal(expected, dm.CheckDetection(c, s.Creature));
        Assert.Equal(detectedAfter, c.ObjectDetected);
    }

    [Fact]
    public void CheckDetection_AddsTheObjectsRadiusUnrounded()
    {
        // CheckDetection (327020) adds CPhysicsObj::GetRadius straight from st0: CPartArray::GetRadius's setup radius times
        // scale.z unrounded. Radius 0.3f (0x3E99999A) at scale 0x3FC00155 (1.5000406503677368): the product
        // 0.45001221299219907, as a float 0.45001220703125. At distance 5 + 0.45001220703125 (a float; the creature at
        // y = 96 + that, exact) the product plus 5 exceeds the distance: inside, Entered (the float radius would make it
        // equal: outside).
        float scale = BitConverter.Int32BitsToSingle(0x3FC00155);
        var s = new ManagerScene(new Vector3(96f, 96f + 5.45001220703125f, 0f));
        s.Creature.PartArray = new AnimatedPartArray(new SetupPhysics(new[] { new Sphere(new Vector3(0f, 0f, 0.3f), 0.3f) },
            ReadOnlySpan<CylSphere>.Empty, BitConverter.Int32BitsToSingle(0x3E99999A), 1.8f, 0.6f, 0.6f), 1, null, null);
        s.Creature.SetScaleStatic(scale);
        Assert.Equal(0.45001220703125f, s.Creature.Radius);
        var dm = new DetectionManager(s.Player, new DetectionRecorder());
        s.Player.DetectionManager = dm;
        dm.CreateDetectionCylsphere(3, s.Creature.Id, 5f);
        DetectionCylsphere c = dm.Find(3)!;
        Assert.Equal(DetectionStatus.Entered, dm.CheckDetection(c, s.Creature));
        Assert.True(c.ObjectDetected);
    }

    [Fact]
    public void ReceiveDetectionUpdate_WithoutGlobalDetection_DoesNothing()
    {
        var s = new ManagerScene(new Vector3(96f, 100f, 0f));
        var dm = new DetectionManager(s.Player, new DetectionRecorder());
        s.Player.DetectionManager = dm;
        dm.ReceiveDetectionUpdate(new DetectionInfo(5, DetectionStatus.Entered));
        Assert.Equal(0u, dm.NumPendingGlobalDetectUpdates);
        Assert.Null(dm.GlobalDetectionStatus(5));
    }

    [Fact]
    public void ReceiveDetectionUpdate_StateMachine()
    {
        // acclient.c:327242: new id -> stored as sent, pending + 1; entered on left -> no change, pending - 1; entered otherwise
        // -> entered, pending + 1; left on entered -> removed, pending - 1; left otherwise -> left, pending + 1.
        var s = new ManagerScene(new Vector3(96f, 100f, 0f));
        var dm = new DetectionManager(s.Player, new DetectionRecorder());
        s.Player.DetectionManager = dm;
        Assert.True(dm.InitializeGlobalDetectionObjects());
        Assert.False(dm.InitializeGlobalDetectionObjects());

        dm.ReceiveDetectionUpdate(new DetectionInfo(5, DetectionStatus.Entered));
        Assert.Equal(DetectionStatus.Entered, dm.GlobalDetectionStatus(5));
        Assert.Equal(1u, dm.NumPendingGlobalDetectUpdates);

        dm.ReceiveDetectionUpdate(new DetectionInfo(5, DetectionStatus.Left));   // entered then left: gone
        Assert.Null(dm.GlobalDetectionStatus(5));
        Assert.Equal(0u, dm.NumPendingGlobalDetectUpdates);

        dm.ReceiveDetectionUpdate(new DetectionInfo(6, DetectionStatus.Left));
        Assert.Equal(DetectionStatus.Left, dm.GlobalDetectionStatus(6));
        Assert.Equal(1u, dm.NumPendingGlobalDetectUpdates);
        dm.ReceiveDetectionUpdate(new DetectionInfo(6, DetectionStatus.Entered)); // left then entered: no change
        Assert.Equal(DetectionStatus.NoChange, dm.GlobalDetectionStatus(6));
        Assert.Equal(0u, dm.NumPendingGlobalDetectUpdates);
        dm.ReceiveDetectionUpdate(new DetectionInfo(6, DetectionStatus.Entered)); // no change then entered
        Assert.Equal(DetectionStatus.Entered, dm.GlobalDetectionStatus(6));
        Assert.Equal(1u, dm.NumPendingGlobalDetectUpdates);
        dm.ReceiveDetectionUpdate(new DetectionInfo(6, DetectionStatus.Entered)); // entered again: stays, pending + 1
        Assert.Equal(2u, dm.NumPendingGlobalDetectUpdates);
    }

    [Fact]
    public void ReceiveDetectionUpdate_OnTheObject_ActivatesIt()
    {
        // acclient.c:317646: with a detection manager, an object not static is made active (update time = now if it was not).
        var s = new ManagerScene(new Vector3(96f, 100f, 0f));
        var dm = new DetectionManager(s.Player, new DetectionRecorder());
        s.Player.DetectionManager = dm;
        dm.InitializeGlobalDetectionObjects();
        s.World.Tick(0.5);
        s.Player.SetActive(false);
        s.World.SetCurrentTime(0.75);
        s.Player.ReceiveDetectionUpdate(new DetectionInfo(9, DetectionStatus.Entered));
        Assert.True(s.Player.IsActive);
        Assert.Equal(0.75, s.Player.UpdateTime);
        Assert.Equal(DetectionStatus.Entered, dm.GlobalDetectionStatus(9));

        // Without a detection manager: nothing (stays inactive).
        s.Creature.SetActive(false);
        s.Creature.ReceiveDetectionUpdate(new DetectionInfo(9, DetectionStatus.Entered));
        Assert.False(s.Creature.IsActive);
    }
}
