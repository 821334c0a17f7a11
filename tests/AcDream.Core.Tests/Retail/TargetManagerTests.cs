using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

/// <summary>TargetManager (PORTAL/cphysobj/CTargetting.c, acclient.c:327973–328643) and its CPhysicsObj wrappers.</summary>
public class TargetManagerTests
{
    private static (PhysicsWorld World, PhysicsObj A, PhysicsObj B) TwoObjects()
    {
        PhysicsWorld world = MoveToScene.FlatWorld();
        PhysicsObj a = MoveToScene.Creature(world, 1, RemoteCreatureWeenie.Creature, new Vector3(100f, 40f, 20f));
        PhysicsObj b = MoveToScene.Creature(world, 2, RemoteCreatureWeenie.Creature, new Vector3(100f, 50f, 20f));
        return (world, a, b);
    }

    [Fact]
    public void SetTarget_RegistersAsVoyeur_AndTheFirstReportArrivesAtOnce()
    {
        (PhysicsWorld world, PhysicsObj a, PhysicsObj b) = TwoObjects();
        world.SetCurrentTime(3.0);
        a.SetTarget(0, 2, 0.5f, 0.25);
        TargetManager tm = a.TargetManager!;
        Assert.True(tm.HasTarget);
        // add_voyeur takes the quantum as a float (acclient.c:316056); AddVoyeur's SendVoyeurUpdate reports b's position.
        TargettedVoyeurInfo v = b.TargetManager!.FindVoyeur(1)!;
        Assert.Equal(0.5f, v.Radius);
        Assert.Equal(0.25, v.Quantum);
        Assert.Equal(b.Position, v.LastSentPosition);
        Assert.Equal(TargetStatus.Ok, tm.TargetInfo.Status);
        Assert.Equal(b.Position, tm.TargetInfo.TargetPosition);
        Assert.Equal(3.0, tm.TargetInfo.LastUpdateTime);
        // interpolated_heading: the unit offset to the predicted position (10 m north).
        Assert.Equal(new Vector3(0f, 1f, 0f), tm.TargetInfo.InterpolatedHeading);
        Assert.Equal(0.25, a.TargetQuantum);
    }

    [Fact]
    public void AddVoyeur_Again_UpdatesRadiusAndQuantum_WithoutAReport()
    {
        (_, PhysicsObj a, PhysicsObj b) = TwoObjects();
        a.SetTarget(0, 2, 0.5f, 0.0);
        TargettedVoyeurInfo v = b.TargetManager!.FindVoyeur(1)!;
        Position sent = v.LastSentPosition;
        b.SetPositionSimple(MoveToScene.At(100f, 55f), true);
        a.SetTargetQuantum(2.0);   // set_target_quantum -> add_voyeur on the existing entry
        Assert.Equal(2.0, v.Quantum);
        Assert.Equal(sent, v.LastSentPosition);
        Assert.Equal(1, b.TargetManager.VoyeurCount);
    }

    [Fact]
    public void CheckAndUpdateVoyeur_ReportsOnlyBeyondTheRadius_AtThePredictedPosition()
    {
        (_, PhysicsObj a, PhysicsObj b) = TwoObjects();
        a.SetTarget(0, 2, 0.5f, 0.0);
        TargetManager tb = b.TargetManager!;
        TargettedVoyeurInfo v = tb.FindVoyeur(1)!;
        b.SetPositionSimple(MoveToScene.At(100f, 50.4f), true);   // 0.4 m: not more than 0.5
        tb.CheckAndUpdateVoyeur(v);
        Assert.Equal(50f, v.LastSentPosition.Frame.Origin.Y);
        b.SetPositionSimple(MoveToScene.At(100f, 50.6f), true);   // 0.6 m > 0.5: reported
        tb.CheckAndUpdateVoyeur(v);
        Assert.Equal(50.6f, v.LastSentPosition.Frame.Origin.Y, 5);
        Assert.Equal(50.6f, a.TargetManager!.TargetInfo.TargetPosition.Frame.Origin.Y, 5);
    }

    [Fact]
    public void GetInterpolatedPosition_IsPositionPlusVelocityTimesTheFloatQuantum()
    {
        (PhysicsWorld world, _, PhysicsObj b) = TwoObjects();
        MovementManager.Of(b).DoMotion(MotionCommand.WalkForward, new MovementParameters { HoldKeyToApply = HoldKey.None });
        SweepScene.Run(world, 2);
        Vector3 vel = b.CachedVelocity;   // 3.12 m/s north
        Assert.Equal(3.12f, vel.Y, 3);
        b.SetTarget(0, 1, 0.5f, 0.0);     // any target: b gets its manager
        Position p = b.TargetManager!.GetInterpolatedPosition(2.0);
        // (float)2.0 * v, x and y summed in double, z's product rounded to float first (acclient.c:328130).
        Assert.Equal((float)(2.0 * vel.Y + b.Position.Frame.Origin.Y), p.Frame.Origin.Y);
        Assert.Equal(b.Position.Frame.Origin.X, p.Frame.Origin.X);
    }

    [Fact]
    public void HandleTargetting_RunsAtMostEveryHalfSecondOfPhysicsTime()
    {
        (PhysicsWorld world, PhysicsObj a, PhysicsObj b) = TwoObjects();
        a.SetTarget(0, 2, 0.5f, 0.0);
        TargetManager tb = b.TargetManager!;
        world.PhysicsTime = 0.4;
        tb.HandleTargetting();
        Assert.Equal(0.0, tb.LastUpdateTime);   // 0.4 - 0 < 0.5
        world.PhysicsTime = 0.5;
        tb.HandleTargetting();
        Assert.Equal(0.5, tb.LastUpdateTime);
    }

    [Fact]
    public void SetTargetZero_ReportsTimedOut_AndClearTarget_Unregisters()
    {
        (_, PhysicsObj a, PhysicsObj b) = TwoObjects();
        a.SetTarget(0, 2, 0.5f, 0.0);
        Assert.Equal(1, b.TargetManager!.VoyeurCount);
        a.SetTarget(0, 0, 0.5f, 0.0);   // drops target 2 (remove_voyeur), then reports TimedOut
        Assert.False(a.TargetManager!.HasTarget);
        Assert.Equal(0, b.TargetManager.VoyeurCount);
        a.SetTarget(0, 2, 0.5f, 0.0);
        a.ClearTarget();
        Assert.Equal(0, b.TargetManager.VoyeurCount);
        Assert.False(a.RemoveVoyeur(99));
    }

    [Fact]
    public void Voyeurs_AreVisitedInRetailHashOrder()
    {
        // LongNIHash, 4 buckets: bucket (id ^ id >> 16) % 4, each bucket newest first. Ids 5 (bucket 1), 4 (bucket 0),
        // 9 (bucket 1, newer than 5), 2 (bucket 2): order 4, 9, 5, 2.
        (_, _, PhysicsObj b) = TwoObjects();
        b.AddVoyeur(5, 0.5f, 0f);
        b.AddVoyeur(4, 0.5f, 0f);
        b.AddVoyeur(9, 0.5f, 0f);
        b.AddVoyeur(2, 0.5f, 0f);
        TargetManager tm = b.TargetManager!;
        Assert.Equal(new uint[] { 4, 9, 5, 2 }, new[] { tm.GetVoyeur(0).ObjectId, tm.GetVoyeur(1).ObjectId, tm.GetVoyeur(2).ObjectId, tm.GetVoyeur(3).ObjectId });
        Assert.True(b.RemoveVoyeur(9));
        Assert.Equal(3, tm.VoyeurCount);
    }

    [Fact]
    public void TeleportHook_TellsVoyeurs_Teleported()
    {
        (_, PhysicsObj a, PhysicsObj b) = TwoObjects();
        a.SetTarget(0, 2, 0.5f, 0.0);
        b.TeleportHook();
        Assert.Equal(TargetStatus.Teleported, a.TargetManager!.TargetInfo.Status);
    }
}
