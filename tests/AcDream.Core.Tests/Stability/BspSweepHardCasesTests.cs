using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// The retail sweep against BSP geometry in the hard cases: a sphere moving many radii per step into a 0.1 m wall never
/// passes through; grazing motion along a face; starting in penetration; seams between coplanar BSP polygons give no bump;
/// pinned in a wedge and sliding between two walls without jitter. Tolerance for "never penetrates": 1 mm, the margin the
/// BSP behaviour tests use for float rounding of the centre (positions near 100 m round by 7.6e-6 m; the sphere tests
/// themselves work to EPSILON = 0.0002 m).
/// </summary>
public class BspSweepHardCasesTests
{
    private const float Tol = 0.001f;

    private static PhysicsObj Walker(PhysicsWorld world, float x, float y, float heading, float r = 0.5f, float speed = 3f)
    {
        PhysicsObj obj = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(x, y), Frame.FromHeading(new Vector3(x, y, BspScene.Ground), heading)), r);
        SweepScene.SetWalk(obj, new Vector3(0f, speed, 0f));
        return obj;
    }

    [Theory]
    [InlineData(0.5f, 40f, 0.05)]   // 2 m per step: 4 radii
    [InlineData(0.1f, 40f, 0.05)]   // 2 m per step: 20 radii of a 0.1 m sphere
    [InlineData(0.5f, 40f, 0.2)]    // 8 m per step: 16 radii (MaxQuantum ticks)
    public void FastSphere_IntoATenCentimetreWall_NeverPassesThrough(float r, float speed, double dt)
    {
        // A wall 0.1 m thick (y 110..110.1), 40 m long, 3 m high. calc_num_steps cuts each move into ceil(|offset| / r) steps
        // of at most one radius, so no step can carry the sphere past a face it would overlap: the centre stays south of
        // 110 - r (within Tol) for every tick, however fast.
        WorldCells cells = BspScene.FlatWorld();
        BspScene.AddBoxes(cells, new Vector3(100f, 110f, BspScene.Ground), (new Vector3(-20f, 0f, 0f), new Vector3(20f, 0.1f, 3f)));
        PhysicsWorld world = BspScene.Physics(cells);
        PhysicsObj obj = Walker(world, 100f, 95f, 0f, r, speed);
        double t = 0;
        for (int i = 0; i < 40; i++)
        {
            t += dt;
            world.Tick(t);
            Vector3 c = BspScene.SphereCenter(obj, r);
            Assert.True(c.Y <= 110f - r + Tol, $"tick {i}: centre {c} is in or past the wall");
        }

        // It reached the wall (15 m in at most 8 ticks) and stays against it.
        Assert.True(BspScene.SphereCenter(obj, r).Y > 110f - r - 2f * r - 0.01f);
    }

    [Fact]
    public void FlyingObject_AtFiftyMetresPerSecond_IntoATenCentimetreWall_NeverPassesThrough()
    {
        // An airborne object (no movement manager; gravity on) launched horizontally at 50 m/s (the clamp) 1 m above the ground
        // into the same wall: 2.5 m per 0.05 s step, 5 radii of its 0.5 m sphere. It bounces or stops; never past the wall.
        WorldCells cells = BspScene.FlatWorld();
        BspScene.AddBoxes(cells, new Vector3(100f, 110f, BspScene.Ground), (new Vector3(-20f, 0f, 0f), new Vector3(20f, 0.1f, 3f)));
        PhysicsWorld world = BspScene.Physics(cells);
        PhysicsObj obj = world.CreateObject(7);
        var parts = new SimplePartArray(1, 0);
        parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) });
        obj.PartArray = parts;
        Assert.True(obj.EnterWorld(new Position(BspScene.OutdoorCell(100f, 90f), new Vector3(100f, 90f, BspScene.Ground + 1f))));
        obj.SetVelocity(new Vector3(0f, 50f, 0f));
        SweepScene.Run(world, 60, i =>
        {
            Vector3 c = BspScene.SphereCenter(obj, 0.5f);
            Assert.True(c.Y <= 110f - 0.5f + Tol, $"tick {i}: centre {c} is in or past the wall");
            Assert.True(VectorMath.IsFinite(obj.Velocity));
        });
    }

    [Fact]
    public void GrazingAlongAWallFace_AtExactlyTheRadius_KeepsFullSpeedAndDistance()
    {
        // The wall's south face is y = 110; the walker's centre runs along y = 109.5 (touching, distance exactly r) heading
        // east. Retail's sphere-polygon tests work with EPSILON, so the touching sphere neither collides nor is pushed: every
        // tick it advances the whole 0.15 m (x sums at ~100 m round by 7.6e-6 m per tick: 200 ticks 1.5e-3 m) and y never
        // changes.
        WorldCells cells = BspScene.FlatWorld();
        BspScene.AddBoxes(cells, new Vector3(100f, 110f, BspScene.Ground), (new Vector3(-40f, 0f, 0f), new Vector3(40f, 0.5f, 3f)));
        PhysicsWorld world = BspScene.Physics(cells);
        PhysicsObj obj = Walker(world, 70f, 109.5f, 90f);
        Assert.Equal(109.5f, obj.Position.Frame.Origin.Y);
        SweepScene.Run(world, 200, i => Assert.Equal(109.5f, obj.Position.Frame.Origin.Y));
        Assert.Equal(70.0 + 200 * 0.15, obj.Position.Frame.Origin.X, 1.5e-3);
    }

    [Fact]
    public void StartingInPenetration_WalkingAway_LeavesWithoutAJump_AndNeverGoesDeeper()
    {
        // The walker is stored (no collision test) with its sphere 0.2 m into the wall's face (centre y = 109.7, face 110).
        // Walking into the wall it must not go deeper; walking away it leaves. In both, no tick moves it more than one step of
        // root motion (0.15 m) plus Tol: no explosion out of the overlap.
        foreach (float heading in new[] { 0f, 180f })
        {
            WorldCells cells = BspScene.FlatWorld();
            BspScene.AddBoxes(cells, new Vector3(100f, 110f, BspScene.Ground), (new Vector3(-20f, 0f, 0f), new Vector3(20f, 0.5f, 3f)));
            PhysicsWorld world = BspScene.Physics(cells);
            PhysicsObj obj = Walker(world, 100f, 105f, heading);
            Position inWall = obj.Position;
            inWall.Frame.Origin = new Vector3(100f, 109.7f, BspScene.Ground);
            obj.StorePosition(inWall);
            Vector3 prev = obj.Position.Frame.Origin;
            SweepScene.Run(world, 40, i =>
            {
                Vector3 o = obj.Position.Frame.Origin;
                Assert.True(Vector3.Distance(prev, o) <= 0.15f + Tol, $"heading {heading}, tick {i}: jumped {prev} -> {o}");
                Assert.True(o.Y <= 109.7f + Tol, $"heading {heading}, tick {i}: deeper, y {o.Y}");
                Assert.True(VectorMath.IsFinite(o));
                prev = o;
            });

            if (heading == 180f)
            {
                Assert.True(obj.Position.Frame.Origin.Y < 109.5f - 1f, $"did not leave: {obj.Position.Frame.Origin}");
            }
        }
    }

    [Fact]
    public void FloorOfManyCoplanarQuads_WalkingAcrossTheSeams_GivesNoBump()
    {
        // A 12 x 12 m slab 0.5 m high whose top is 144 coplanar 1 m quads (z = 0.5 exactly: every vertex has z = 0.5, so
        // every plane is N = (0, 0, 1), d = -0.5 without rounding). A walker on it heading 37 degrees crosses about 20 seams.
        // Its height must stay exactly Ground + 0.5 (floats: 20.5 is exact), with walkable contact, on every tick.
        WorldCells cells = BspScene.FlatWorld();
        var polys = new List<Polygon>();
        for (int i = 0; i < 12; i++)
        {
            for (int j = 0; j < 12; j++)
            {
                polys.Add(BspScene.Quad(new(i, j, 0.5f), new(i + 1, j, 0.5f), new(i + 1, j + 1, 0.5f), new(i, j + 1, 0.5f), (short)polys.Count));
            }
        }

        var box = new List<Polygon>();
        BspScene.AddBox(box, new Vector3(0f, 0f, 0f), new Vector3(12f, 12f, 0.5f));
        for (int k = 0; k < box.Count; k++)
        {
            if (k != 4)
            {
                // Every face but the +Z top, which the quads replace.
                Polygon f = box[k];
                polys.Add(BspScene.Quad(f.Vertices[0], f.Vertices[1], f.Vertices[2], f.Vertices[3], (short)polys.Count));
            }
        }

        BspScene.AddBuilding(cells, new Vector3(100f, 100f, BspScene.Ground), polys);
        PhysicsWorld world = BspScene.Physics(cells);
        PhysicsObj obj = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(101f, 101f), Frame.FromHeading(new Vector3(101.3f, 101.1f, BspScene.Ground + 0.5f), 37f)));
        SweepScene.SetWalk(obj, new Vector3(0f, 3f, 0f));
        Assert.Equal(BspScene.Ground + 0.5f, obj.Position.Frame.Origin.Z);
        SweepScene.Run(world, 70, i =>
        {
            Vector3 o = obj.Position.Frame.Origin;
            Assert.Equal(BspScene.Ground + 0.5f, o.Z);
            Assert.True((obj.TransientState & TransientState.OnWalkable) != 0, $"tick {i}: lost the floor at {o}");
        });

        // 70 ticks * 0.15 m = 10.5 m along 37 degrees: still on the slab (x 101.3 + 6.32, y 101.1 + 8.39).
        Assert.InRange(obj.Position.Frame.Origin.X, 107.5f, 107.7f);
    }

    /// <summary>Appends an axis-aligned box (min..max, local) rotated by <paramref name="degrees"/> counter-clockwise about z
    /// through the local origin.</summary>
    private static void AddRotatedBox(List<Polygon> polys, Vector3 min, Vector3 max, float degrees)
    {
        var box = new List<Polygon>();
        BspScene.AddBox(box, min, max);
        double a = degrees * Math.PI / 180.0;
        float c = (float)Math.Cos(a), s = (float)Math.Sin(a);
        Vector3 Rot(Vector3 v) => new(v.X * c - v.Y * s, v.X * s + v.Y * c, v.Z);
        foreach (Polygon f in box)
        {
            polys.Add(BspScene.Quad(Rot(f.Vertices[0]), Rot(f.Vertices[1]), Rot(f.Vertices[2]), Rot(f.Vertices[3]), (short)polys.Count));
        }
    }

    [Fact]
    public void PinnedInAWedge_StopsWithoutJitter_AndTouchesNeitherWallTooDeep()
    {
        // Two walls meet at the apex (100, 110) in a V opening south, each inner face at 15 degrees from the y axis. A walker
        // heading north walks into the V. It fits until its sphere touches both faces: centre distance to the apex d with
        // d sin 15 = r = 0.5, d = 1.932 m (centre y = 108.07). It must never come closer than r - Tol to either face, and once
        // stopped (the last 60 ticks) it must not move by more than 1 mm on any axis.
        WorldCells cells = BspScene.FlatWorld();
        var polys = new List<Polygon>();
        AddRotatedBox(polys, new Vector3(0f, -20f, 0f), new Vector3(0.3f, 0f, 3f), 15f);     // east wall: inner face x' = 0
        AddRotatedBox(polys, new Vector3(-0.3f, -20f, 0f), new Vector3(0f, 0f, 3f), -15f);   // west wall: inner face x' = 0
        BspScene.AddBuilding(cells, new Vector3(100f, 110f, BspScene.Ground), polys);
        PhysicsWorld world = BspScene.Physics(cells);
        PhysicsObj obj = Walker(world, 100f, 100f, 0f);
        double s15 = Math.Sin(15 * Math.PI / 180), c15 = Math.Cos(15 * Math.PI / 180);
        Vector3 min = new(float.MaxValue), max = new(float.MinValue);
        SweepScene.Run(world, 160, i =>
        {
            Vector3 o = obj.Position.Frame.Origin;
            double dx = o.X - 100.0, dy = o.Y - 110.0;
            // Distance from the centre (in plan) to each inner face line through the apex: east face normal (-cos15, -sin15)
            // pointing into the V... measured as the signed distance inside the V.
            double toEast = -(dx * c15 + dy * s15), toWest = dx * c15 - dy * s15;
            Assert.True(toEast >= 0.5 - Tol && toWest >= 0.5 - Tol, $"tick {i}: centre {o} within r of a wall ({toEast}, {toWest})");
            if (i >= 100)
            {
                min = Vector3.Min(min, o);
                max = Vector3.Max(max, o);
            }
        });

        Vector3 spread = max - min;
        Assert.True(spread.X < 0.001f && spread.Y < 0.001f && spread.Z < 0.001f, $"jitter {spread}");
        // Stopped within one step (0.15 m) of the pinned position y = 110 - 0.5 / sin 15 = 108.068.
        Assert.InRange(obj.Position.Frame.Origin.Y, 108.068f - 0.15f - Tol, 108.068f + Tol);
    }

    [Fact]
    public void SlidingBetweenTwoWalls_OfACorridor_KeepsMovingWithoutJitter()
    {
        // A corridor 1.2 m wide (faces x = 99.4 and 100.6) for a 1 m sphere. Heading 10 degrees east of north the walker meets
        // the east face after (100.1 - 100) / (0.15 sin 10) = 4 ticks, then slides north along it (centre never closer than r
        // to either face), y advancing the parallel component 0.15 cos 10 = 0.1477 m per tick
        // (1 % tolerance for the slide's projection and float sums).
        WorldCells cells = BspScene.FlatWorld();
        BspScene.AddBoxes(cells, new Vector3(100f, 100f, BspScene.Ground),
            (new Vector3(-1.1f, -10f, 0f), new Vector3(-0.6f, 30f, 3f)),
            (new Vector3(0.6f, -10f, 0f), new Vector3(1.1f, 30f, 3f)));
        PhysicsWorld world = BspScene.Physics(cells);
        PhysicsObj obj = Walker(world, 100f, 95f, 10f);
        // A blocked step returns to the current position and the collision normal becomes the sliding normal, which removes
        // the x component from every later step: the walker slides at the x where it was blocked, within one step's lateral
        // component (0.15 sin 10 = 0.026 m) of touching, and that x must not change any more (no jitter: spread < 1 mm).
        float y50 = 0f, xMin = float.MaxValue, xMax = float.MinValue;
        SweepScene.Run(world, 150, i =>
        {
            Vector3 o = obj.Position.Frame.Origin;
            Assert.True(o.X <= 100.1f + Tol && o.X >= 99.9f - Tol, $"tick {i}: centre x {o.X}");
            if (i >= 20)
            {
                Assert.True(o.X >= 100.1f - 0.027f, $"tick {i}: x {o.X} not against the east wall");
                xMin = MathF.Min(xMin, o.X);
                xMax = MathF.Max(xMax, o.X);
            }

            if (i == 49)
            {
                y50 = o.Y;
            }
        });

        Assert.True(xMax - xMin < 0.001f, $"lateral jitter {xMax - xMin}");
        float progress = obj.Position.Frame.Origin.Y - y50;
        Assert.InRange(progress, 100 * 0.1477f * 0.99f, 100 * 0.1477f * 1.01f);
    }
}
