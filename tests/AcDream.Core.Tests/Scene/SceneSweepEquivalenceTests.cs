using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Scene;

/// <summary>
/// Skipping dormant objects stays bit-identical with the retail sweep and object collisions in play: walkers on sloped
/// terrain run into resting items, items dropped from a height land and fall asleep, a player walks among them.
/// </summary>
[Trait("Category", "Determinism")]
public class SceneSweepEquivalenceTests
{
    private static PhysicsWorld Build(bool visitEveryObject, out PhysicsObj[] walkers)
    {
        TerrainWorld terrain = SweepScene.Terrain();
        // Block (0x20, 0x20): a gentle slope rising eastwards (1 m per vertex column) and its neighbours flat.
        SweepScene.AddBlock(terrain, 0x20, 0x20, (x, y) => x);
        SweepScene.AddBlock(terrain, 0x21, 0x20, (x, y) => 8);
        var world = new PhysicsWorld(0.0) { VisitEveryObject = visitEveryObject };
        world.Sweep = new RetailSweep(terrain);
        walkers = new PhysicsObj[4];
        for (int i = 0; i < walkers.Length; i++)
        {
            var p = new Position(SweepScene.CellId(0x20, 0x20, 1, 1 + i), new Vector3(30f, 30f + i * 24f, 20f));
            walkers[i] = SweepScene.Walker(world, p, id: (uint)(10 + i));
            SweepScene.SetWalk(walkers[i], new Vector3(0f, 2f, 0f));
            walkers[i].SetHeading(90f);
        }

        world.Player = walkers[0];
        // Items on the walkers' paths (no movement manager: they rest and sleep), and items dropped from 3 m.
        for (int i = 0; i < 24; i++)
        {
            float x = 40f + (i % 6) * 8f;
            float y = 30f + (i / 6) * 24f + ((i & 1) == 0 ? 0f : 0.3f);
            var p = new Position(SweepScene.CellId(0x20, 0x20, (int)(x / 24f), (int)(y / 24f)), new Vector3(x, y, 40f));
            PhysicsObj item = world.CreateObject((uint)(100 + i));
            var parts = new SimplePartArray(1, 0);
            parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, 0.3f), 0.3f) });
            item.PartArray = parts;
            Assert.True(item.EnterWorld(p));
            if (i % 4 == 3)
            {
                // Lift it 3 m: it falls, lands, and comes to rest.
                Position up = item.Position;
                up.Frame.Origin += new Vector3(0f, 0f, 3f);
                item.SetPositionSimple(up, sliding: false);
            }
        }

        return world;
    }

    [Fact]
    public void WalkersItemsAndFalls_OnTheRetailSweep_AreBitIdenticalWithAndWithoutDormancy()
    {
        PhysicsWorld full = Build(true, out PhysicsObj[] fw);
        PhysicsWorld scene = Build(false, out PhysicsObj[] sw);
        int maxDormant = 0;
        for (int tick = 1; tick <= 400; tick++)
        {
            if (tick == 200)
            {
                // Turn round and walk back through the items.
                for (int i = 0; i < fw.Length; i++)
                {
                    fw[i].SetHeading(270f);
                    sw[i].SetHeading(270f);
                }
            }

            double t = tick * SweepScene.Dt;
            full.Tick(t);
            scene.Tick(t);
            Assert.True(SceneTestContext.HashWorld(full) == SceneTestContext.HashWorld(scene), $"tick {tick}");
            maxDormant = Math.Max(maxDormant, scene.DormantCount);
        }

        // The test is not vacuous: most items slept at some point.
        Assert.True(maxDormant >= 12, $"at most {maxDormant} dormant");
    }
}
