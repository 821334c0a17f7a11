using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support;
using Xunit;
using static AcDream.Core.Tests.Support.LandscapeEntries;

namespace AcDream.Core.Tests.Allocation;

/// <summary>The landscape called every frame (as retail's <c>SmartBox::UseTime</c> does) allocates nothing while the player's
/// cell does not change, and the world's tick with a full 3 × 3 allocates nothing.</summary>
public class LandscapeAllocationTests
{
    [Fact]
    public void EveryFrameInTheSameCell_AllocatesNothing()
    {
        Landscape l = Landscape(Source(), out PhysicsWorld world, out _);
        Position p = At(0x80, 0x80, 100f, 100f);
        l.ChangePosition(p);
        PhysicsObj walker = SweepScene.Walker(world, p);
        world.Player = walker;
        SweepScene.SetWalk(walker, new System.Numerics.Vector3(0f, 0.25f, 0f));
        for (int i = 0; i < 600; i++)
        {
            l.ChangePosition(walker.Position);
            world.Tick(world.CurrentTime + SweepScene.Dt);
        }

        int otherStatus = 0;
        AllocationProbe.AssertSteadyStateAllocatesNothing(() =>
        {
            for (int i = 0; i < 10; i++)
            {
                // (no Assert inside the window: xunit's Assert.Equal allocates)
                if (l.ChangePosition(walker.Position).Status != LandscapeStatus.SameCell)
                {
                    otherStatus++;
                }

                world.Tick(world.CurrentTime + SweepScene.Dt);
            }
        });
        Assert.Equal(0, otherStatus);
        Assert.Equal(Cell(0x80, 0x80, 100f, 100f), walker.CellId);
    }

    [Fact]
    public void ACellChangeInsideAFullGrid_AllocatesNothing()
    {
        // Radius 1: the grid is the 3 x 3 and full, so a cell change moves no block; the second pass (adjust_scene_obj_height,
        // the statics' shadows) and the visible-cell table run on scratch the landscape keeps.
        Landscape l = Landscape(Source(), out _, out _, radius: 1);
        Position a = At(0x80, 0x80, 100f, 84f), b = At(0x80, 0x80, 100f, 100f);
        l.ChangePosition(a);
        for (int i = 0; i < 4; i++)
        {
            l.ChangePosition(b);
            l.ChangePosition(a);
        }

        int other = 0;
        AllocationProbe.AssertSteadyStateAllocatesNothing(() =>
        {
            for (int i = 0; i < 5; i++)
            {
                other += l.ChangePosition(b) == LandscapeChange.Moved ? 0 : 1;
                other += l.ChangePosition(a) == LandscapeChange.Moved ? 0 : 1;
            }
        });
        Assert.Equal(0, other);
    }
}
