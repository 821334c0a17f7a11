using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// The terrain and cell-list computations at the coordinates 0, 191.99998, exactly 192, -0.0 and -1e-7, and a walker swept
/// through a landblock corner on terrain: the four landblocks meeting at a corner agree, the answers are continuous, and a
/// walker crosses without a jump.
/// </summary>
public class LandblockCornerOnTerrainTests
{
    private const int Bx = SweepScene.BlockX, By = SweepScene.BlockY;

    /// <summary>Four landblocks around the corner (Bx+1, By+1)·192, heights a function of the GLOBAL vertex, so shared edges
    /// agree: <paramref name="h"/>(gx, gy) with gx = bx*8 + vx.</summary>
    private static TerrainWorld FourBlocks(Func<int, int, int> h)
    {
        TerrainWorld terrain = SweepScene.Terrain();
        for (int dx = 0; dx <= 1; dx++)
        {
            for (int dy = 0; dy <= 1; dy++)
            {
                int bx = Bx + dx, by = By + dy;
                SweepScene.AddBlock(terrain, bx, by, (vx, vy) => h(bx * 8 + vx, by * 8 + vy));
            }
        }

        return terrain;
    }

    private static int Bumpy(int gx, int gy) => 20 + (gx * 3 + gy * 5) % 4;

    public static IEnumerable<object[]> EdgeValues() =>
    [
        [0f], [191.99998f], [192f], [-0.0f], [-1e-7f],
    ];

    [Theory]
    [MemberData(nameof(EdgeValues))]
    public void HeightPolyAndWaterQueries_AtEdgeCoordinates_AgreeWithTheRehomedPoint(float c)
    {
        // A point (c, c) local to block (Bx, By): 0, -0.0 and -1e-7 (within EPSILON of 0, snapped to +0 by adjust_to_outside)
        // are that block's corner; exactly 192 is the corner (0, 0) of block (Bx+1, By+1); 191.99998 stays in (Bx, By), cell
        // (7, 7). Every query must give bit for bit the answer for the re-homed point.
        TerrainWorld terrain = FourBlocks(Bumpy);
        var p = new Position(SweepScene.CellId(Bx, By, 0, 0), new Vector3(c, c, 0f));
        Position home = p;
        Assert.True(home.TryAdjustToOutside());
        (uint cell, float local) = c == 192f ? (SweepScene.CellId(Bx + 1, By + 1, 0, 0), 0f)
            : c == 191.99998f ? (SweepScene.CellId(Bx, By, 7, 7), 191.99998f)
            : (SweepScene.CellId(Bx, By, 0, 0), 0f);
        Assert.Equal(cell, home.ObjCellId);
        Assert.Equal(BitConverter.SingleToInt32Bits(local), BitConverter.SingleToInt32Bits(home.Frame.Origin.X));

        Assert.True(terrain.TryGetTerrainHeight(p, out float z));
        Assert.True(terrain.TryGetTerrainHeight(home, out float zHome));
        Assert.Equal(BitConverter.SingleToInt32Bits(zHome), BitConverter.SingleToInt32Bits(z));
        Assert.True(terrain.TryFindTerrainPoly(p, out LandCell? lc, out _, out Vector3 loc));
        Assert.Equal(cell, lc!.Id);
        Assert.Equal(home.Frame.Origin, loc);
        Assert.True(terrain.TryGetWaterDepth(p, out float depth));
        Assert.Equal(0f, depth);

        // The global query at the same point agrees: block (Bx, By) starts at Bx * 192 m.
        Assert.True(terrain.TryGetTerrainHeight(Bx * 192.0 + c, By * 192.0 + c, out float zGlobal));
        Assert.Equal(zHome, zGlobal);
    }

    [Theory]
    [MemberData(nameof(EdgeValues))]
    public void OffsetsAndDistances_BetweenAPointAndItsRehomedSelf_AreExactlyZero(float c)
    {
        // get_offset adds the block offset (a multiple of 192, exact in float) to the difference of the local origins: the
        // point (c, c) of block (Bx, By) and the same point re-homed are the same place, so the offset is exactly zero (for
        // 192: 192 - 0 - 192; for -1e-7: snapped to 0, and -1e-7 - 0 is -1e-7, below EPSILON, which is what adjust_to_outside
        // discards). Offsets towards a third point agree to within one float spacing at 200 m (1.5e-5 m).
        var p = new Position(SweepScene.CellId(Bx, By, 0, 0), new Vector3(c, c, 5f));
        Position home = p;
        Assert.True(home.TryAdjustToOutside());
        Vector3 o = p.GetOffset(home);
        float expected = c == -1e-7f ? 1e-7f : 0f;
        Assert.Equal(expected, o.X, 0f);
        Assert.Equal(expected, o.Y, 0f);
        Assert.Equal(0f, o.Z);
        var q = new Position(SweepScene.CellId(Bx + 1, By + 1, 1, 1), new Vector3(30f, 40f, 6f));
        Assert.True(Vector3.Distance(p.GetOffset(q), home.GetOffset(q)) <= 1.6e-5f);
        Assert.Equal(p.Distance(q), home.Distance(q), 1.6e-5f);
    }

    [Fact]
    public void HeightIsContinuous_AcrossEveryCellAndLandblockEdge_OfTheFourBlocks()
    {
        // At every vertex line x = 24k of the 16 x 16 cells around the corner, the height just west (24k - 2e-5, one float step
        // below 192) and at the line differ by at most slope * 2e-5 + rounding: the steepest bumpy slope is 3 m per 24 m
        // (0.125), so 2.5e-6 m, plus the height query's float rounding at ~25 m (two roundings of 1.9e-6). Bound 1e-5 m.
        TerrainWorld terrain = FourBlocks(Bumpy);
        for (int k = 1; k < 16; k++)
        {
            for (int j = 0; j < 16; j++)
            {
                double x = Bx * 192.0 + 24.0 * k, y = By * 192.0 + 24.0 * j + 7.25;
                double xBelow = x - 2e-5;
                Assert.True(terrain.TryGetTerrainHeight(x, y, out float at));
                Assert.True(terrain.TryGetTerrainHeight(xBelow, y, out float below));
                Assert.True(Math.Abs(at - below) < 1e-5, $"x {x}, y {y}: {below} vs {at}");
                Assert.True(terrain.TryGetTerrainHeight(y, x, out float atT));
                Assert.True(terrain.TryGetTerrainHeight(y, xBelow, out float belowT));
                Assert.True(Math.Abs(atT - belowT) < 1e-5, $"y {x}, x {y}: {belowT} vs {atT}");
            }
        }
    }

    [Theory]
    [MemberData(nameof(EdgeValues))]
    public void CellList_OfASphereAtTheCorner_IsTheFourCellsAroundIt(float c)
    {
        // A 0.5 m sphere centred at (c, c) local to block (Bx, By): whichever block it is re-homed into, its centre lies within
        // 0.5 m of both edges through the corner (192 - 191.99998 = 2e-5 < 0.5; 0 - (-1e-7) likewise), so add_all_outside_cells
        // adds the corner cell and its three neighbours across the edges and the diagonal: the four cells meeting at the corner.
        // For 0, -0.0 and -1e-7 that is the block's own south-west corner; for 191.99998 and 192 the north-east one.
        TerrainWorld terrain = FourBlocks(Bumpy);
        for (int bx = Bx - 1; bx <= Bx; bx++)
        {
            for (int by = By - 1; by <= By; by++)
            {
                if (bx < Bx || by < By)
                {
                    SweepScene.AddBlock(terrain, bx, by, (vx, vy) => Bumpy(bx * 8 + vx, by * 8 + vy));
                }
            }
        }

        // Global cell columns/rows just west/south (k - 1) and east/north (k) of the corner.
        int kx = c < 1f ? Bx * 8 : Bx * 8 + 8, ky = c < 1f ? By * 8 : By * 8 + 8;
        var expected = new HashSet<uint>
        {
            LandDefs.LCoordToGid(kx - 1, ky - 1), LandDefs.LCoordToGid(kx, ky - 1),
            LandDefs.LCoordToGid(kx - 1, ky), LandDefs.LCoordToGid(kx, ky),
        };
        var p = new Position(SweepScene.CellId(Bx, By, 0, 0), new Vector3(c, c, 30f));
        Vector3[] centers = [new(c, c, 30.5f)];
        float[] radii = [0.5f];
        var ids = new uint[16];
        int n = terrain.FindCellList(p, centers, radii, ids, out LandCell? current);
        var got = new HashSet<uint>();
        for (int i = 0; i < n; i++)
        {
            got.Add(ids[i]);
        }

        Assert.Equal(expected, got);
        Assert.NotNull(current);
        Assert.Contains(current!.Id, expected);
    }

    [Fact]
    public void WalkerThroughTheExactCorner_OnAPlane_CrossesWithoutAJump()
    {
        // The plane z = 20 + (gx + gy) in vertex units (1 m per 24 m in each axis, N.z = 576 / sqrt(576² + 2·24²) = 0.99913:
        // walkable) is symmetric in x and y, and heading exactly 45 degrees gives equal float x and y steps, so the walker's path is the
        // diagonal through (192, 192): it steps through the corner itself. Per tick it advances 0.15 m of root motion; uphill
        // steps are projected onto the plane: horizontal 0.15 * N.z^2-ish, the same every tick. A jump at the corner would
        // show as a tick whose global displacement differs from the first tick's: bound 1e-4 m (positions below 200 m round by
        // 1.5e-5 m, re-homing at 192 is exact).
        TerrainWorld terrain = FourBlocks((gx, gy) => 20 + (gx + gy - (Bx + By) * 8));
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        var start = new Position(SweepScene.CellId(Bx, By, 7, 7), Frame.FromHeading(new Vector3(188f, 188f, 0f), 45f));
        start.Frame.Origin = new Vector3(188f, 188f, SweepScene.Ground(terrain, start));
        PhysicsObj obj = SweepScene.Walker(world, start);
        SweepScene.SetWalk(obj, new Vector3(0f, 3f, 0f));
        Vector3 Global(in Position p) => new((float)((p.ObjCellId >> 24) * 192.0 - Bx * 192.0 + p.Frame.Origin.X),
            (float)(((p.ObjCellId >> 16) & 0xFF) * 192.0 - By * 192.0 + p.Frame.Origin.Y), p.Frame.Origin.Z);
        Vector3 prev = Global(obj.Position);
        float first = -1f;
        var blocks = new List<uint>();
        SweepScene.Run(world, 60, i =>
        {
            Vector3 g = Global(obj.Position);
            float d = Vector3.Distance(prev, g);
            first = first < 0f ? d : first;
            Assert.True(Math.Abs(d - first) < 1e-4f, $"tick {i}: step {d} vs {first}");
            Assert.Equal(g.X, g.Y);
            Assert.True((obj.TransientState & TransientState.OnWalkable) != 0);
            uint block = obj.Position.ObjCellId >> 16;
            if (blocks.Count == 0 || blocks[^1] != block)
            {
                blocks.Add(block);
            }

            prev = g;
        });

        // Along the exact diagonal it goes straight from block (Bx, By) into (Bx+1, By+1): x and y reach 192 together.
        Assert.Equal(new[] { (uint)((Bx << 8) | By), (uint)(((Bx + 1) << 8) | (By + 1)) }, blocks);
        Assert.Equal(SweepScene.CellId(Bx + 1, By + 1, 0, 0), obj.Position.ObjCellId);
    }

    [Fact]
    public void WalkerNearTheCorner_OnBumpyTerrain_StaysOnTheSurfaceInEveryBlock()
    {
        // Continuous bumpy terrain (steepest 3 m per 24 m), heading 40 degrees from (186, 187): it passes 0.7 m from the corner,
        // through three of the four blocks (it crosses y = 192 at x = 190.2, then x = 192). On every tick its origin is on the
        // terrain under it: retail puts the sphere's lowest point (under the origin) on the triangle's plane, the plane the
        // height query evaluates; both round at ~25 m by 1.9e-6 m, and a triangle's plane differs from the exact one by
        // make_plane's rounding (5e-5 m, see TerrainSweepHardCasesTests). Bound 1e-4 m.
        TerrainWorld terrain = FourBlocks(Bumpy);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        var start = new Position(SweepScene.CellId(Bx, By, 7, 7), Frame.FromHeading(new Vector3(186f, 187f, 0f), 40f));
        start.Frame.Origin = new Vector3(186f, 187f, SweepScene.Ground(terrain, start));
        PhysicsObj obj = SweepScene.Walker(world, start);
        SweepScene.SetWalk(obj, new Vector3(0f, 3f, 0f));
        var blocks = new HashSet<uint>();
        SweepScene.Run(world, 80, i =>
        {
            float ground = SweepScene.Ground(terrain, obj.Position);
            Assert.True(Math.Abs(obj.Position.Frame.Origin.Z - ground) < 1e-4f, $"tick {i}: z {obj.Position.Frame.Origin.Z} ground {ground}");
            Assert.True((obj.TransientState & TransientState.Contact) != 0);
            blocks.Add(obj.Position.ObjCellId >> 16);
        });

        Assert.True(blocks.Count >= 3, $"{blocks.Count} blocks");
    }
}
