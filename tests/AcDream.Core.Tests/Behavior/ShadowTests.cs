using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class ShadowTests
{
    private static readonly int EastX = SweepScene.BlockX + 1;

    // Every loaded cell of landblocks 0x8080 and 0x8180 that lists a shadow of obj.
    private static List<uint> CellsListing(RetailSweep sweep, PhysicsObj obj)
    {
        var ids = new List<uint>();
        for (int bx = SweepScene.BlockX; bx <= EastX; bx++)
        {
            for (int cx = 0; cx < 8; cx++)
            {
                for (int cy = 0; cy < 8; cy++)
                {
                    uint id = SweepScene.CellId(bx, SweepScene.BlockY, cx, cy);
                    ObjCell? cell = sweep.Cells.GetVisible(id);
                    if (cell is not null && ObjectScene.CellLists(cell, obj))
                    {
                        ids.Add(id);
                    }
                }
            }
        }

        ids.Sort();
        return ids;
    }

    private static List<uint> ShadowCells(PhysicsObj obj)
    {
        var ids = new List<uint>();
        foreach (ShadowObj s in obj.ShadowObjects)
        {
            Assert.Same(obj, s.PhysObj);
            Assert.NotNull(s.Cell);
            Assert.Equal(s.CellId, s.Cell!.Id);
            ids.Add(s.CellId);
        }

        ids.Sort();
        return ids;
    }

    [Fact]
    public void Shadows_FollowTheObject_AcrossCellsAndTheLandblockEdge()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep, twoBlocks: true);
        // Start in the middle of cell (7, 4) of 0x8080 (x = 180) heading east at 2 m/s: after 150 ticks (15 m) it is at world
        // x = 195, 3 m into landblock 0x8180 (cell (0, 4)).
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(180f, 100f, heading: 90f));
        SweepScene.SetWalk(c, new Vector3(0f, 2f, 0f));
        Assert.Equal(new List<uint> { SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 7, 4) }, CellsListing(sweep, c));

        bool sawTwoBlocks = false;
        SweepScene.Run(world, 150, _ =>
        {
            // The cells that list the creature are exactly the cells of its shadows: no stale shadow is left behind.
            List<uint> listed = CellsListing(sweep, c);
            Assert.Equal(ShadowCells(c), listed);
            // The cell it stands in is always one of them.
            Assert.Contains(c.Position.ObjCellId, listed);
            if (listed.Exists(id => id >> 24 == (uint)SweepScene.BlockX) && listed.Exists(id => id >> 24 == (uint)EastX))
            {
                sawTwoBlocks = true;
            }
        });

        // While its sphere (r = 0.5) straddled x = 192 it was shadowed on both sides of the landblock edge.
        Assert.True(sawTwoBlocks);
        uint now = SweepScene.CellId(EastX, SweepScene.BlockY, 0, 4);
        Assert.Equal(now, c.Position.ObjCellId);
        Assert.Equal(3f, c.Position.Frame.Origin.X, 2);
        Assert.Equal(new List<uint> { now }, CellsListing(sweep, c));
    }

    [Fact]
    public void ObjectAcrossTheLandblockEdge_IsCollidedWith()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep, twoBlocks: true);
        // A creature 2.05 m into landblock 0x8180 (world x = 194.05); the walker comes from world x = 188 in 0.1 m steps
        // (float sums, so its x carries ~1e-4 of rounding: the obstacle sits half a step off the knife edge).
        uint eastCell = SweepScene.CellId(EastX, SweepScene.BlockY, 0, 4);
        PhysicsObj other = ObjectScene.Creature(world, 2, new Position(eastCell, Frame.FromHeading(new Vector3(2.05f, 100f, 20f), 0f)));
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(188f, 100f, heading: 90f));
        SweepScene.SetWalk(c, new Vector3(0f, 2f, 0f));

        SweepScene.Run(world, 100);

        // It crosses the edge; the step to x = 1.1 (gap 0.95 < 0.9998) is refused: it stops at x = 1.0 of landblock 0x8180.
        Assert.Equal(eastCell, c.Position.ObjCellId);
        Assert.Equal(1f, c.Position.Frame.Origin.X, 2);
        Assert.Equal(2.05f, other.Position.Frame.Origin.X, 3);
    }

    [Fact]
    public void RemovingAnObject_TakesItsShadowsOutOfTheCells()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        // On the corner of four cells (x = y = 96 is a cell corner): its sphere overlaps all four.
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(96.2f, 96.2f));
        Assert.Equal(4, CellsListing(sweep, c).Count);
        Assert.Equal(4, c.NumShadowObjects);

        world.RemoveObject(c);

        Assert.Empty(CellsListing(sweep, c));
        Assert.Equal(0, c.NumShadowObjects);
    }
}
