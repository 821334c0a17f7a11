using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Allocation;

public class SweepAllocationTests
{
    [Fact]
    public void TickingWalkersThroughTheRetailSweep_AllocatesNothing_AfterWarmUp()
    {
        // Slope, flat part and a landblock edge: every branch of a walking sweep (steps, step down, cell changes).
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (vx, _) => vx <= 4 ? 20 : 20 + 20 * (vx - 4));
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY + 1, (vx, _) => vx <= 4 ? 20 : 20 + 20 * (vx - 4));
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        var walkers = new PhysicsObj[4];
        for (int i = 0; i < walkers.Length; i++)
        {
            uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 3, 7);
            walkers[i] = SweepScene.Walker(world, new Position(cell, Frame.FromHeading(new Vector3(86f + 2f * i, 186f, 20f), 90f * i)), id: (uint)(i + 1));
            SweepScene.SetWalk(walkers[i], new Vector3(0f, 4f, 0f));
            // Circles of 4 / 0.5 = 8 m radius: periodic paths (one lap is 2 pi / 0.5 = 12.6 s = 252 ticks) that cross the
            // landblock edge (y = 192), the foot of the slope (x = 96) and cell edges, so the warm-up visits every branch
            // (and lets tiered compilation settle) before the measured ticks repeat them.
            ((SimplePartArray)walkers[i].PartArray!).SequenceOmega = new Vector3(0f, 0f, 0.5f);
        }

        SweepScene.Run(world, 600);
        Vector3 start = walkers[0].Position.Frame.Origin;
        AllocationProbe.AssertSteadyStateAllocatesNothing(() =>
        {
            for (int i = 0; i < 300; i++)
            {
                world.Tick(world.CurrentTime + SweepScene.Dt);
            }
        });

        // The measured ticks really swept: the walker is somewhere else on its 8 m circle, still in contact with the ground.
        Assert.NotEqual(start, walkers[0].Position.Frame.Origin);
        Assert.True((walkers[0].TransientState & TransientState.Contact) != 0);
    }
}
