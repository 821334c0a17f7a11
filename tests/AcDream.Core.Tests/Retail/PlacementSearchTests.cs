using System;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class PlacementSearchTests
{
    private const uint Cell = 0x80800012; // cell (2, 1) of block 0x8080: x 48..72, y 24..48

    // A test cell standing in for an object that the initial placement ignores (retail skips object collisions on
    // INITIAL_PLACEMENT): blocked within 0.9 m of (60, 36) and everywhere north of y = 35.5.
    private sealed class BlockedCell : ObjCell
    {
        public override uint Id => Cell;

        public override bool PointInCell(Vector3 point) => true;

        internal override TransitionState FindEnvCollisions(Transition transition) => TransitionState.Ok;

        internal override TransitionState FindCollisions(Transition transition)
        {
            if (transition.SpherePath.InsertType == InsertType.InitialPlacement)
            {
                return TransitionState.Ok;
            }

            Vector3 c = transition.SpherePath.GlobalSphere[0].Center;
            double dx = c.X - 60.0, dy = c.Y - 36.0;
            return dx * dx + dy * dy < 0.81 || c.Y > 35.5 ? TransitionState.Collided : TransitionState.Ok;
        }

        internal override void FindTransitCells(ICellSource cells, in Position p, ReadOnlySpan<Sphere> spheres, CellArray cellArray, SpherePath? path)
        {
        }
    }

    private sealed class OneCell : ICellSource
    {
        public readonly BlockedCell Cell = new();

        public ObjCell? GetVisible(uint cellId) => cellId == PlacementSearchTests.Cell ? Cell : null;
    }

    [Fact]
    public void FindPlacementPosition_SearchesRingsClockwiseFromNorth()
    {
        var cells = new OneCell();
        var pool = new TransitionPool(cells);
        Transition t = pool.Make()!;
        t.InitSphere(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) }, 1f);
        t.InitPlacementPath(cells.Cell, new Position(Cell, new Vector3(60f, 36f, 0f)));

        // r = 0.5 (at least 0.48, so kept): n = ceil(4 / 0.5) = 8 rings 4 / 8 = 0.5 m apart; ring k has
        // 2 ceil(k * 0.5 / 0.5 * 3.1415999) headings, evenly spaced clockwise from north: ring 1 (0.5 m) 2 * 4 = 8,
        // ring 2 (1.0 m) 2 * ceil(6.2832) = 14 (every 360 / 14 = 25.714 degrees). Ring 1 lies in the disc. Ring 2, heading j:
        // y = 36 + cos(25.714 j): j = 0..4 give 37, 36.90, 36.62, 36.22, 35.78 (north of 35.5); j = 5 (128.57 degrees) gives
        // 36 - 0.6235 = 35.3765 and x = 60 + sin 128.57° = 60.7818: the first free spot.
        Assert.True(t.FindValidPosition());
        Vector3 o = t.SpherePath.CurrPos.Frame.Origin;
        double a = 5.0 * 2.0 * Math.PI / 14.0;
        Assert.Equal(60.0 + Math.Sin(a), o.X, 4);
        Assert.Equal(36.0 + Math.Cos(a), o.Y, 4);
    }

    [Fact]
    public void FindPlacementPosition_WithoutSliding_FailsWhereItDoesNotFit()
    {
        var cells = new OneCell();
        var pool = new TransitionPool(cells);
        Transition t = pool.Make()!;
        t.InitSphere(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) }, 1f);
        t.InitPlacementPath(cells.Cell, new Position(Cell, new Vector3(60f, 36f, 0f)));
        t.SpherePath.PlacementAllowsSliding = false;
        Assert.False(t.FindValidPosition());
    }
}
