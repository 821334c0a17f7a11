using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// The retail sweep over terrain in the hard cases: walking across triangle seams gives no bump; an object resting on flat
/// ground or on a slope one float step on the walkable side of floor_z does not creep in 100,000 ticks, while one step on the
/// other side slides; a walker placed or stored below the surface comes out on it; grazing along a too-steep face neither
/// climbs it nor sinks into it.
/// </summary>
public class TerrainSweepHardCasesTests
{
    private const int Bx = SweepScene.BlockX, By = SweepScene.BlockY;

    [Fact]
    public void WalkingAcrossTriangleSeamsOfOnePlane_FollowsThePlaneWithoutABump()
    {
        // Heights index 20 + 2 vx + vy on the one-metre table: every vertex lies on z = 20 + x/12 + y/24, so both triangles of
        // every cell (whichever way the split rule cuts it) are that plane (N.z = 0.99569, walkable). A walker at 3 m/s heading
        // 50 degrees crosses cell edges and diagonals of both split directions for 1,000 ticks (150 m).
        // Bound: each triangle's plane is the exact one up to make_plane's float rounding (N relative 2^-24 per component,
        // d from a mean of products of coordinates below 192 m and heights below 50 m): |Δz| <= 192 * 3 * 6e-8 + 50 * 6e-8
        // = 3.8e-5 m; the stored origin z rounds by 1.9e-6 m below 64 m. Bound 5e-5 m, on the height and on each tick's rise
        // against the plane's rise over the same horizontal move (a seam bump would show in the latter as a jump).
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, Bx, By, (vx, vy) => 20 + 2 * vx + vy);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        static double Plane(Vector3 o) => 20.0 + o.X / 12.0 + o.Y / 24.0;
        var p = new Position(SweepScene.CellId(Bx, By, 0, 0), Frame.FromHeading(new Vector3(20f, 20f, 0f), 50f));
        p.Frame.Origin = new Vector3(20f, 20f, (float)Plane(new Vector3(20f, 20f, 0f)));
        PhysicsObj obj = SweepScene.Walker(world, p);
        SweepScene.SetWalk(obj, new Vector3(0f, 3f, 0f));
        Vector3 prev = obj.Position.Frame.Origin;
        int cellChanges = 0;
        uint prevCell = obj.Position.ObjCellId;
        SweepScene.Run(world, 1000, i =>
        {
            Vector3 o = obj.Position.Frame.Origin;
            Assert.True(Math.Abs(o.Z - Plane(o)) < 5e-5, $"tick {i}: z {o.Z} vs plane {Plane(o)}");
            double rise = o.Z - prev.Z, planeRise = Plane(o) - Plane(prev);
            Assert.True(Math.Abs(rise - planeRise) < 1e-4, $"tick {i}: rise {rise} vs {planeRise}");
            Assert.True((obj.TransientState & (TransientState.Contact | TransientState.OnWalkable)) == (TransientState.Contact | TransientState.OnWalkable));
            cellChanges += obj.Position.ObjCellId != prevCell ? 1 : 0;
            prevCell = obj.Position.ObjCellId;
            prev = o;
        });

        // 150 m at 50 degrees: 115 m east, 96 m north from (20, 20): about 9 cell changes. Moving on the plane (uphill steps
        // are projected onto it), it went at least 100 m.
        Assert.True(cellChanges >= 8, $"{cellChanges} cell changes");
        Assert.True(Vector3.Distance(p.Frame.Origin, obj.Position.Frame.Origin) > 100f);
    }

    /// <summary>Landblock (Bx, By) with vertex heights vx * r + vy * s (a plane rising r metres per 24 m east and s per 24 m
    /// north), through a height table whose entry vx + 9 vy is (float)(vx * r) + (float)(vy * s).</summary>
    private static TerrainWorld SlopeOf(float r, float s)
    {
        var table = new float[LandHeightTable.Count];
        for (int i = 0; i < 81; i++)
        {
            table[i] = (float)(i % 9 * r) + (float)(i / 9 * s);
        }

        var terrain = new TerrainWorld(new LandHeightTable(table));
        SweepScene.AddBlock(terrain, Bx, By, (vx, vy) => vx + 9 * vy);
        return terrain;
    }

    private static readonly Vector3 RestPoint = new(84f, 108f, 0f); // cell (3, 4)

    private static float NormalZUnder(TerrainWorld terrain)
    {
        Assert.True(terrain.TryFindTerrainPoly(new Position(SweepScene.CellId(Bx, By, 3, 4), RestPoint), out _, out Polygon? poly, out _));
        return poly!.Plane.N.Z;
    }

    /// <summary>
    /// A terrain whose triangle under <see cref="RestPoint"/> has N.z exactly <paramref name="target"/>. make_plane gives
    /// N.z = fl(fl(1/|c|) * 576) for a 24 m right triangle (the cross product's z is 24 * 24), and |c| moves in steps of the
    /// float spacing of the cross product's x and y (6.1e-5 near 650): with a slope along x only, N.z skips some float values
    /// (floor_z ± 1 ulp among them). Adding a slope s along y moves |c| by other steps, so for each s in a short list: a
    /// bisection over r's bit pattern (N.z falls as r grows), then a scan of r's neighbours for an exact hit.
    /// </summary>
    private static TerrainWorld SlopeWithNormalZ(float target)
    {
        foreach (float s in new[] { 0f, 0.5f, 1f, 1.5f, 2f, 3f })
        {
            int lo = BitConverter.SingleToInt32Bits(20f), hi = BitConverter.SingleToInt32Bits(35f);
            while (hi - lo > 1)
            {
                int mid = lo + (hi - lo) / 2;
                if (NormalZUnder(SlopeOf(BitConverter.Int32BitsToSingle(mid), s)) > target)
                {
                    lo = mid;
                }
                else
                {
                    hi = mid;
                }
            }

            for (int b = lo - 16; b <= hi + 16; b++)
            {
                TerrainWorld t = SlopeOf(BitConverter.Int32BitsToSingle(b), s);
                if (NormalZUnder(t) == target)
                {
                    return t;
                }
            }
        }

        throw new InvalidOperationException($"No slope gives N.z = {target:R}.");
    }

    [Theory]
    [InlineData(1)]   // floor_z plus one ulp: walkable
    [InlineData(0)]   // exactly floor_z: walkable (N.z >= floor_z)
    public void RestingOnASlopeAtFloorZ_ForOneHundredThousandTicks_DoesNotCreep(int ulps)
    {
        float target = ulps == 1 ? MathF.BitIncrement(PhysicsGlobals.FloorZ) : PhysicsGlobals.FloorZ;
        TerrainWorld terrain = SlopeWithNormalZ(target);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        var p = new Position(SweepScene.CellId(Bx, By, 3, 4), RestPoint);
        p.Frame.Origin = new Vector3(RestPoint.X, RestPoint.Y, SweepScene.Ground(terrain, p));
        // A walker has a movement manager, so it never self-deactivates: every one of the 100,000 ticks runs its step.
        PhysicsObj obj = SweepScene.Walker(world, p);
        Assert.Equal(target, obj.ContactPlaneNormal.Z);
        Assert.True((obj.TransientState & TransientState.OnWalkable) != 0);
        Position start = obj.Position;
        AssertNoCreep(world, obj, start);
    }

    [Fact]
    public void RestingOnFlatGround_ForOneHundredThousandTicks_DoesNotCreep()
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, Bx, By, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        PhysicsObj obj = SweepScene.Walker(world, new Position(SweepScene.CellId(Bx, By, 3, 4), new Vector3(RestPoint.X, RestPoint.Y, 20f)));
        Assert.True((obj.TransientState & TransientState.OnWalkable) != 0);
        AssertNoCreep(world, obj, obj.Position);
    }

    private static void AssertNoCreep(PhysicsWorld world, PhysicsObj obj, Position start)
    {
        // No creep means bit-identical: on walkable ground calc_acceleration zeroes gravity, the velocity is zero, and an
        // unmoved origin skips the sweep. Any drift at all would change a bit. Time: 0.05 s ticks from a clock that is exact
        // in binary steps of 1/20 s (no slicing), 100,000 ticks = 5,000 s.
        var steps = new StepRecorder();
        for (int i = 1; i <= 100_000; i++)
        {
            world.Tick(i * 0.05);
            if ((i & 4095) == 0)
            {
                Assert.Equal(start, obj.Position);
            }
        }

        Assert.Equal(start, obj.Position);
        Assert.Equal(Vector3.Zero, obj.Velocity);
        Assert.True(obj.IsActive);
        Assert.True((obj.TransientState & TransientState.OnWalkable) != 0);
    }

    [Fact]
    public void PlacedOnASlopeOneUlpBelowFloorZ_IsNotWalkable_AndSlidesDownhill()
    {
        // N.z = floor_z - 1 ulp fails N.z >= floor_z: the placement still takes the plane as contact (any plane outside of
        // walking), but not as walkable ground, so gravity stays on and the object slides down the slope (-x, and -y when the search tilted it north).
        float target = MathF.BitDecrement(PhysicsGlobals.FloorZ);
        TerrainWorld terrain = SlopeWithNormalZ(target);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        var p = new Position(SweepScene.CellId(Bx, By, 3, 4), RestPoint);
        p.Frame.Origin = new Vector3(RestPoint.X, RestPoint.Y, SweepScene.Ground(terrain, p));
        PhysicsObj obj = SweepScene.Walker(world, p);
        Assert.True((obj.TransientState & TransientState.OnWalkable) == 0);
        Vector3 o0 = obj.Position.Frame.Origin;
        SweepScene.Run(world, 20, _ =>
            Assert.True(obj.Position.Frame.Origin.Z >= SweepScene.Ground(terrain, obj.Position) - 2e-3f));
        Vector3 o = obj.Position.Frame.Origin;
        Assert.True(o.X < o0.X - 0.1f && o.Z < o0.Z - 0.1f, $"{o} from {o0}");
    }

    [Theory]
    [InlineData(0.3f)]
    [InlineData(0.05f)]
    public void PlacedBelowTheSurface_ComesOutOnIt(float depth)
    {
        // validate_walkable pushes the sphere's lowest point (the origin, for a sphere resting on it) onto the plane; the
        // placement then stands there. Bound: the plane's height query rounds within 1e-4 m (see the seam test: 5e-5 m).
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, Bx, By, (vx, vy) => 20 + 2 * vx + vy);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        var p = new Position(SweepScene.CellId(Bx, By, 3, 4), RestPoint);
        float ground = SweepScene.Ground(terrain, p);
        p.Frame.Origin = new Vector3(RestPoint.X, RestPoint.Y, ground - depth);
        PhysicsObj obj = SweepScene.Walker(world, p);
        Assert.Equal(ground, obj.Position.Frame.Origin.Z, 1e-4f);
        Assert.True((obj.TransientState & TransientState.OnWalkable) != 0);
    }

    [Fact]
    public void StoredBelowTheSurface_TheFirstSweepLiftsItOntoTheSurface()
    {
        // store_position bypasses collision: the walker is left 0.3 m under a gentle plane. Its first swept step starts in
        // penetration; the terrain test pushes the low point onto the plane, so from the first tick on it is on the surface
        // (within 1e-4 m) and it keeps walking on it.
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, Bx, By, (vx, vy) => 20 + 2 * vx + vy);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        var p = new Position(SweepScene.CellId(Bx, By, 3, 4), Frame.FromHeading(RestPoint, 90f));
        p.Frame.Origin = new Vector3(RestPoint.X, RestPoint.Y, SweepScene.Ground(terrain, p));
        PhysicsObj obj = SweepScene.Walker(world, p);
        Position below = obj.Position;
        below.Frame.Origin -= new Vector3(0f, 0f, 0.3f);
        obj.StorePosition(below);
        SweepScene.SetWalk(obj, new Vector3(0f, 2f, 0f));
        SweepScene.Run(world, 50, i =>
        {
            float ground = SweepScene.Ground(terrain, obj.Position);
            Assert.True(Math.Abs(obj.Position.Frame.Origin.Z - ground) < 1e-4f, $"tick {i}: z {obj.Position.Frame.Origin.Z} ground {ground}");
        });
        Assert.True(obj.Position.Frame.Origin.X > RestPoint.X + 4f);
    }

    /// <summary>Flat at 10 m for x &lt;= 96, then rising 40 m per 24 m (N.z = 0.51, a wall to walkers).</summary>
    private static TerrainWorld FaceTerrain()
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, Bx, By, (vx, _) => vx <= 4 ? 10 : 10 + 40 * (vx - 4));
        return terrain;
    }

    [Fact]
    public void GrazingParallelToASteepFace_WalksOnUndisturbed()
    {
        // 0.1 m from the foot of the face, walking north: the terrain test looks under the sphere's lowest point (over the
        // flat), so nothing touches: x and z stay exactly, y advances 3 m/s * 0.05 s = 0.15 m per tick (float sums of y below
        // 192 m round by 7.6e-6 m per tick: 200 ticks, 1.6e-3 m).
        TerrainWorld terrain = FaceTerrain();
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        PhysicsObj obj = SweepScene.Walker(world, new Position(SweepScene.CellId(Bx, By, 3, 1), new Vector3(95.9f, 30f, 10f)));
        SweepScene.SetWalk(obj, new Vector3(0f, 3f, 0f));
        SweepScene.Run(world, 200, _ =>
        {
            Assert.Equal(95.9f, obj.Position.Frame.Origin.X);
            Assert.Equal(10f, obj.Position.Frame.Origin.Z);
        });
        Assert.Equal(30.0 + 200 * 0.15, obj.Position.Frame.Origin.Y, 1.6e-3);
    }

    [Fact]
    public void GrazingIntoASteepFaceAtTwoDegrees_NeverClimbsNorSinks()
    {
        // Heading 2 degrees east of north: the walker reaches the foot of the face (x = 96) after ~ (96 - 95.5) / (0.15 sin 2°)
        // = 96 ticks, then spends 500 more along it. It must never stand over the face (its low point at x > 96 would meet N.z = 0.51 < floor_z: a wall),
        // never leave z = 10, and keep walkable contact.
        TerrainWorld terrain = FaceTerrain();
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        PhysicsObj obj = SweepScene.Walker(world, new Position(SweepScene.CellId(Bx, By, 3, 0), Frame.FromHeading(new Vector3(95.5f, 5f, 10f), 2f)));
        SweepScene.SetWalk(obj, new Vector3(0f, 3f, 0f));
        SweepScene.Run(world, 600, i =>
        {
            Vector3 o = obj.Position.Frame.Origin;
            Assert.True(o.X <= 96f, $"tick {i}: x {o.X}");
            Assert.Equal(10f, o.Z);
            Assert.True((obj.TransientState & TransientState.OnWalkable) != 0);
        });
    }
}
