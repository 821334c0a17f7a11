using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Allocation;

public class ObjectCollisionAllocationTests
{
    [Fact]
    public void TickingACrowdThatKeepsBumping_AllocatesNothing_AfterWarmUp()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        var listener = new RecordingListenerNoAlloc();
        sweep.ObjectCollisionListener = listener;
        // 25 creatures in a 5 x 5 grid, 1.2 m apart, turning while they walk: they keep meeting, sliding and parting,
        // crossing the cell corner at (96, 96).
        for (int i = 0; i < 5; i++)
        {
            for (int j = 0; j < 5; j++)
            {
                PhysicsObj c = ObjectScene.Creature(world, (uint)(1 + i * 5 + j), ObjectScene.At(93.6f + 1.2f * i, 93.6f + 1.2f * j, heading: 72f * (i + j)));
                SweepScene.SetWalk(c, new Vector3(0f, 1.5f, 0f));
                ((SimplePartArray)c.PartArray!).SequenceOmega = new Vector3(0f, 0f, 0.3f * (1 + (i + j) % 3));
            }
        }

        // The crowd's cells are sized up front (a cell's shadow list otherwise grows, once, whenever more creatures crowd into
        // it than ever before).
        for (int cx = 0; cx < 8; cx++)
        {
            for (int cy = 0; cy < 8; cy++)
            {
                sweep.Cells.GetVisible(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, cx, cy))!.ReserveShadowCapacity(32);
            }
        }

        SweepScene.Run(world, 200);
        int reportsBefore = listener.Count;
        AllocationProbe.AssertSteadyStateAllocatesNothing(() => SweepScene.Run(world, 200));
        // The measured ticks really had object collisions (contacts starting and ending).
        Assert.True(listener.Count > reportsBefore);
    }

    private sealed class RecordingListenerNoAlloc : IObjectCollisionListener
    {
        public int Count;

        public void OnObjectCollision(PhysicsObj obj, in ObjCollisionProfile profile) => Count++;

        public void OnAttackCollision(PhysicsObj obj, in AtkCollisionProfile profile) => Count++;

        public void OnObjectCollisionEnd(PhysicsObj obj, uint otherId) => Count++;
    }
}
