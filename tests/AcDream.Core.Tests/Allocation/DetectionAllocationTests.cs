using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Replay.Harness;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Allocation;

/// <summary>The detection manager allocates nothing per tick once its cylinders exist, reports and deferred deletions
/// included.</summary>
public class DetectionAllocationTests
{
    [Fact]
    public void Ticks_WithDetectionActive_AllocateZeroBytes()
    {
        var s = new ManagerScene(new Vector3(96f, 100f, 0f));
        var rec = new DetectionRecorder();
        var dm = new DetectionManager(s.Player, rec);
        s.Player.DetectionManager = dm;
        dm.CreateDetectionCylsphere(1, s.Creature.Id, 5f);     // creature walks in and out of it
        dm.CreateDetectionCylsphere(2, 0x7777u, 3f);           // an id not in the world: Left at every check
        var near = ManagerScene.At(new Vector3(96f, 98f, 0f));
        var far = ManagerScene.At(new Vector3(96f, 110f, 0f));
        int frame = 0;
        void Run(int frames)
        {
            for (int f = 0; f < frames; f++)
            {
                frame++;
                if (frame % 16 == 0)
                {
                    s.Creature.SetPosition((frame / 16) % 2 == 0 ? near : far, SetPositionFlags.Placement);
                }

                if (frame % 64 == 0)
                {
                    // a destroy and re-create: the cylinder goes back to the pool and comes out of it
                    dm.DestroyDetectionCylsphere(2);
                    s.World.Tick(s.World.CurrentTime + 0.0625);
                    dm.CreateDetectionCylsphere(2, 0x7777u, 3f);
                    continue;
                }

                s.World.Tick(s.World.CurrentTime + 0.0625);
            }
        }

        Run(320);
        int before = rec.Total;
        AllocationProbe.AssertSteadyStateAllocatesNothing(() => Run(1600));
        Assert.True(rec.Total - before >= 100);   // reports were made in the measured window
    }

    [Fact]
    public void Ticks_WithGlobalDetectionCrossingCells_AllocateZeroBytes()
    {
        // A global detector (object id 0, radius 5) hopping between cells (0, 0) and (1, 0) of a flat block, one object in
        // each: every second check its cell list changes, the cells' voyeur tables and the detection objects churn.
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 0);
        PhysicsWorld world = SweepScene.Physics(terrain, out RetailSweep _);
        static Position At(float x, float y) =>
            new(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, (int)(x / 24f), (int)(y / 24f)), new Vector3(x, y, 0f));
        PhysicsObj d = SweepScene.Walker(world, At(12f, 12f), id: 1);
        SweepScene.Walker(world, At(16f, 12f), id: 10);
        SweepScene.Walker(world, At(40f, 12f), id: 11);
        var rec = new DetectionRecorder();
        var dm = new DetectionManager(d, rec);
        d.DetectionManager = dm;
        dm.CreateDetectionCylsphere(1, 0, 5f);
        Position west = At(12f, 12f);
        Position east = At(36f, 12f);
        int frame = 0;
        void Run(int frames)
        {
            for (int f = 0; f < frames; f++)
            {
                frame++;
                if (frame % 16 == 0)
                {
                    d.SetPosition((frame / 16) % 2 == 0 ? west : east, SetPositionFlags.Placement);
                }

                world.Tick(world.CurrentTime + 0.0625);
            }
        }

        Run(320);
        int before = rec.Total;
        AllocationProbe.AssertSteadyStateAllocatesNothing(() => Run(1600));
        Assert.True(rec.Total - before >= 100);   // entered / left reports were made in the measured window
    }
}
