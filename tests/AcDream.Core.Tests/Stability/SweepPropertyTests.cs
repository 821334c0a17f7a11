using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using FsCheck;
using FsCheck.Fluent;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// Property-based (FsCheck) invariants of the retail sweep over random terrain and random walkers: no walker is lost (it keeps
/// a cell, and its cell id is the outdoor cell that contains its origin), none ends a tick below the surface or with NaN, and
/// one standing on walkable ground stands on the surface.
/// </summary>
public class SweepPropertyTests
{
    private readonly record struct Case(int Seed, int Roughness, int Speed, int Turn, int Heading, int Jump, int Dt);

    private static readonly Gen<Case> Cases =
        from seed in Gen.Choose(0, int.MaxValue - 1)
        from rough in Gen.Elements(0, 3, 10, 30)       // height index steps per vertex: flat, gentle, walkable, cliffs
        from speed in Gen.Choose(0, 100)               // 0 .. 10 m/s of root motion
        from turn in Gen.Choose(-100, 100)             // -1 .. 1 rad/s
        from heading in Gen.Choose(0, 359)
        from jump in Gen.Choose(0, 40)                 // a 4 m/s jump every `jump` ticks (0: never)
        from dt in Gen.Elements(34, 50, 100, 200, 450) // ms per tick (450: two slices and a remainder)
        select new Case(seed, rough, speed, turn, heading, jump, dt);

    private static Config Cfg => PropertyAssert.Replayable(60, 20261122UL, 0x5851F42D4C957F2DUL);

    [Fact]
    public void RandomWalkers_OnRandomTerrain_AreNeverLostNorBelowTheSurface()
    {
        // Bound on "below the surface" and "on the surface": OBJECTINFO::validate_walkable (acclient.c, ObjectInfo.cs) accepts
        // the sphere's lowest point (under the origin) within EPSILON of the triangle's plane along its normal (depth >=
        // -EPSILON is not pushed; within +-EPSILON is contact), i.e. EPSILON / N.z vertically; on top of that the height query
        // and the stored origin round by 1.5e-5 m below 256 m, and make_plane's rounding of the plane is 5e-5 m at 192 m
        // (TerrainSweepHardCasesTests): bound EPSILON / N.z + 1e-4 m, N.z of the triangle under the origin.
        PropertyAssert.Holds(Cfg, Prop.ForAll(Cases.ToArbitrary(), c =>
        {
            TerrainWorld terrain = SweepScene.Terrain();
            for (int bx = SweepScene.BlockX - 1; bx <= SweepScene.BlockX + 1; bx++)
            {
                for (int by = SweepScene.BlockY - 1; by <= SweepScene.BlockY + 1; by++)
                {
                    int cbx = bx, cby = by;
                    SweepScene.AddBlock(terrain, bx, by, (vx, vy) => 40 + Noise(c.Seed, cbx * 8 + vx, cby * 8 + vy) % (c.Roughness + 1));
                }
            }

            PhysicsWorld world = SweepScene.Physics(terrain, out _);
            var p = new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4), Frame.FromHeading(new Vector3(100f, 100f, 0f), c.Heading));
            p.Frame.Origin = new Vector3(100f, 100f, SweepScene.Ground(terrain, p) + 0.01f);
            PhysicsObj w = SweepScene.Walker(world, p);
            SweepScene.SetWalk(w, new Vector3(0f, c.Speed / 10f, 0f));
            ((SimplePartArray)w.PartArray!).SequenceOmega = new Vector3(0f, 0f, c.Turn / 100f);
            double t = 0.0;
            for (int tick = 1; tick <= 150; tick++)
            {
                if (c.Jump > 0 && tick % c.Jump == 0 && (w.TransientState & TransientState.Contact) != 0)
                {
                    w.SetVelocity(new Vector3(0f, 0f, 4f));
                }

                t += c.Dt / 1000.0;
                world.Tick(t);
                Position pos = w.Position;
                if (w.CellId == 0 || !VectorMath.IsFinite(pos.Frame.Origin) || !VectorMath.IsFinite(w.Velocity) || !pos.Frame.IsValid())
                {
                    throw new InvalidOperationException($"tick {tick}: lost or non-finite: {pos}");
                }

                Position home = pos;
                if (!home.TryAdjustToOutside() || home.ObjCellId != pos.ObjCellId)
                {
                    throw new InvalidOperationException($"tick {tick}: cell id {pos.ObjCellId:X8} does not contain {pos.Frame.Origin}");
                }

                float ground = SweepScene.Ground(terrain, pos);
                Assert.True(terrain.TryFindTerrainPoly(pos, out _, out Polygon? under, out _));
                double bound = PhysicsGlobals.Epsilon / under!.Plane.N.Z + 1e-4;
                if (pos.Frame.Origin.Z < ground - bound)
                {
                    throw new InvalidOperationException($"tick {tick}: below the surface ({pos.Frame.Origin.Z} < {ground} - {bound})");
                }

                if ((w.TransientState & TransientState.OnWalkable) != 0 && Math.Abs(pos.Frame.Origin.Z - ground) > bound)
                {
                    throw new InvalidOperationException($"tick {tick}: walkable but {pos.Frame.Origin.Z} vs ground {ground}");
                }
            }

            return true;
        }));
    }

    // A deterministic hash of (seed, global vertex): the terrain is continuous across landblocks by construction.
    private static int Noise(int seed, int gx, int gy)
    {
        uint h = (uint)seed * 0x9E3779B1u ^ (uint)gx * 0x85EBCA77u ^ (uint)gy * 0xC2B2AE3Du;
        h ^= h >> 15;
        h *= 0x2C1B3C6Du;
        h ^= h >> 12;
        return (int)(h & 0x7FFF);
    }
}
