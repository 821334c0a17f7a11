using System;
using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Tests.Replay.Harness;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// The interpolation queue under hostile update streams: overflow (near and far), duplicate, out-of-order and stale reports,
/// and a target exactly at the autonomy blip distance and one float step beyond it
/// (InterpolationManager::InterpolateTo, acclient.c:389016; SmartBox::HandleReceivedPosition, acclient.c:145124).
/// </summary>
public class InterpolationStreamEdgeCasesTests
{
    private static ManagerScene Scene(float y = 50f) => new(new Vector3(50f, y, 0f));

    [Fact]
    public void AThousandNearUpdates_NeverQueueMoreThanTwenty_AndKeepTheNewest()
    {
        // Updates 0.1 m apart marching north: each is 0.1 m from the tail (>= 0.05: no prune) and within 100 m of it (near),
        // so each is appended, evicting the head while 20 are queued (acclient.c:389084). After update i (1-based) the queue
        // holds min(i, 20) nodes, the newest at the tail.
        ManagerScene s = Scene();
        InterpolationManager? im = null;
        for (int i = 1; i <= 1000; i++)
        {
            s.Creature.InterpolateTo(ManagerScene.At(new Vector3(50f, 50f + 0.1f * i, 0f)), false);
            im ??= s.Interpolation!;
            Assert.Equal(Math.Min(i, InterpolationManager.MaxQueueLength), im.Count);
        }

        Position tail = ManagerScene.At(new Vector3(50f, 50f + 0.1f * 1000, 0f));
        Position head = ManagerScene.At(new Vector3(50f, 50f + 0.1f * 981, 0f));
        Assert.Equal(tail, im!.GetNode(19).Position);
        Assert.Equal(head, im.GetNode(0).Position);
        Assert.Equal(0, im.NodeFailCounter);
    }

    [Fact]
    public void ThirtyFarUpdates_StayWithinTheRing_AndTheNextTickBlipsToTheNewest()
    {
        // Alternating between two points 150 m apart: every update is far (> 100 m from the tail), appended without a prune,
        // with the fail counter pre-armed to 4. The ring never exceeds 20 (the head is evicted; divergences.md). UseTime at the
        // end of the next step blips to the tail: the newest update.
        ManagerScene s = Scene(20f);
        for (int i = 0; i < 30; i++)
        {
            float y = (i & 1) == 0 ? 170f : 20f;
            s.Creature.InterpolateTo(ManagerScene.At(new Vector3(50f + 0.01f * i, y, 0f)), false);
            Assert.InRange(s.Interpolation!.Count, 1, InterpolationManager.MaxQueueLength);
        }

        Position newest = ManagerScene.At(new Vector3(50f + 0.01f * 29, 20f, 0f));
        s.World.Tick(s.World.CurrentTime + 0.05);
        Assert.Equal(newest.Frame.Origin, s.Creature.Position.Frame.Origin);
        Assert.Equal(0, s.Interpolation!.Count);
        Assert.Equal(0, s.Interpolation.NodeFailCounter);
    }

    [Fact]
    public void DuplicateUpdate_ReplacesTheTailWithItself_TheQueueDoesNotGrow()
    {
        // The duplicate is 0 m from the tail (< 0.05): the tail is pruned and the same position appended (acclient.c:389062).
        ManagerScene s = Scene();
        Position a = ManagerScene.At(new Vector3(50f, 52f, 0f));
        Position b = ManagerScene.At(new Vector3(50f, 54f, 0f));
        s.Creature.InterpolateTo(a, false);
        s.Creature.InterpolateTo(b, false);
        s.Creature.InterpolateTo(b, false);
        s.Creature.InterpolateTo(b, false);
        Assert.Equal(2, s.Interpolation!.Count);
        Assert.Equal(a, s.Interpolation.GetNode(0).Position);
        Assert.Equal(b, s.Interpolation.GetNode(1).Position);
    }

    [Fact]
    public void DuplicateOutOfOrderAndStaleReports_AreDropped_WithTheStateUnchanged()
    {
        // Position timestamps: 10 then 12 are accepted; a second 12 (duplicate), 11 (out of order) and 10 (older than the
        // current state) are not newer (PhysicsObj::newer_event) and are dropped before touching anything.
        ManagerScene s = Scene();
        s.World.Tick(0.05); // measures the player distance (a report >= 96 m from the player would snap instead)
        Position p10 = ManagerScene.At(new Vector3(50f, 52f, 0f));
        Position p12 = ManagerScene.At(new Vector3(50f, 54f, 0f));
        Assert.True(s.Creature.HandleReceivedPosition(p10, 10, 0, true) >= ReceivedPositionResult.Interpolating);
        Assert.True(s.Creature.HandleReceivedPosition(p12, 12, 0, true) >= ReceivedPositionResult.Interpolating);
        Assert.Equal(2, s.Interpolation!.Count);
        ulong before = SceneTestContext.Hash(s.Creature);
        foreach ((ushort ts, float y) in new (ushort, float)[] { (12, 58f), (11, 53f), (10, 51f) })
        {
            Assert.True(s.Creature.HandleReceivedPosition(ManagerScene.At(new Vector3(50f, y, 0f)), ts, 0, true) < ReceivedPositionResult.Interpolating);
            Assert.Equal(2, s.Interpolation.Count);
            Assert.Equal(p12, s.Interpolation.GetNode(1).Position);
            Assert.Equal((ushort)12, s.Creature.GetUpdateTime(PhysicsTimeStamp.Position));
            Assert.Equal(before, SceneTestContext.Hash(s.Creature));
        }
    }

    [Fact]
    public void TimestampWrapAround_NewerAcrossTheWrap_OlderAcrossItIsDropped()
    {
        // 16-bit stamps compare within half the range: the stamp climbs 0 -> 0x7000 -> 0xE000 -> 0xFFFF (each newer by less
        // than 0x8000), then 0x0001 is newer than 0xFFFF across the wrap, and 0xFFFE is older than 0x0001.
        ManagerScene s = Scene();
        s.World.Tick(0.05);
        Assert.True(s.Creature.HandleReceivedPosition(ManagerScene.At(new Vector3(50f, 52f, 0f)), 0x7000, 0, true) >= ReceivedPositionResult.Interpolating);
        Assert.True(s.Creature.HandleReceivedPosition(ManagerScene.At(new Vector3(50f, 51f, 0f)), 0xE000, 0, true) >= ReceivedPositionResult.Interpolating);
        Assert.True(s.Creature.HandleReceivedPosition(ManagerScene.At(new Vector3(50f, 52f, 0f)), 0xFFFF, 0, true) >= ReceivedPositionResult.Interpolating);
        Assert.True(s.Creature.HandleReceivedPosition(ManagerScene.At(new Vector3(50f, 53f, 0f)), 0x0001, 0, true) >= ReceivedPositionResult.Interpolating);
        Assert.True(s.Creature.HandleReceivedPosition(ManagerScene.At(new Vector3(50f, 60f, 0f)), 0xFFFE, 0, true) < ReceivedPositionResult.Interpolating);
        Assert.Equal(4, s.Interpolation!.Count);
        Assert.Equal((ushort)1, s.Creature.GetUpdateTime(PhysicsTimeStamp.Position));
    }

    [Fact]
    public void TargetExactlyAtTheBlipDistance_IsNear_AndIsApproachedAtTheSpeedCap()
    {
        // Creature at (50, 20), target (50, 120): the block-aware offset is (0, 100, 0) exactly and the distance 100.0. Retail
        // tests blip_distance >= (float)distance (acclient.c:389016): 100 >= 100, the near branch: appended, no fail counter.
        ManagerScene s = Scene(20f);
        Position target = ManagerScene.At(new Vector3(50f, 120f, 0f));
        s.Creature.InterpolateTo(target, false);
        Assert.Equal(1, s.Interpolation!.Count);
        Assert.Equal(0, s.Interpolation.NodeFailCounter);

        // One 0.05 s step closes at 2 x the default interpreter's 4 m/s (get_minterp): 0.4 m, no blip. Float rounding of the
        // offset at 20 m adds < 2e-6 m. Bound 0.4 + 1e-5.
        Vector3 o0 = s.Creature.Position.Frame.Origin;
        s.World.Tick(s.World.CurrentTime + 0.05);
        float moved = Vector3.Distance(o0, s.Creature.Position.Frame.Origin);
        Assert.InRange(moved, 0.4f - 1e-5f, 0.4f + 1e-5f);
        Assert.Equal(1, s.Interpolation.Count);
    }

    [Fact]
    public void TargetOneFloatStepBeyondTheBlipDistance_IsFar_AndBlipsOnTheNextTick()
    {
        // Target y = BitIncrement(120f) = 120.00000763: the distance 100.00000763 rounds to the float above 100 -> far branch:
        // appended, fail counter 4 (acclient.c:389164), and the next step's UseTime blips the creature onto it.
        ManagerScene s = Scene(20f);
        Position target = ManagerScene.At(new Vector3(50f, MathF.BitIncrement(120f), 0f));
        s.Creature.InterpolateTo(target, false);
        Assert.Equal(InterpolationManager.FarBranchFailCount, s.Interpolation!.NodeFailCounter);
        s.World.Tick(s.World.CurrentTime + 0.05);
        Assert.Equal(target.Frame.Origin, s.Creature.Position.Frame.Origin);
        Assert.Equal(0, s.Interpolation.Count);
    }
}
