using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class RealTerrainSweepTests
{
    [TerrainDataFact]
    public void WalkersOnHoltburg_StayOnTheSurface_AndMostlyInContact()
    {
        // The real Holtburg 3 x 3 landblocks (0xA8B3-0xAAB5). 40 walkers start at fixed spots of the centre block and walk
        // 3.12 m/s in circles of radius 6.24 m for 30 s (600 ticks).
        TerrainWorld terrain = TerrainTestData.SampleWorld(
            0xA8B3FFFF, 0xA8B4FFFF, 0xA8B5FFFF, 0xA9B3FFFF, 0xA9B4FFFF, 0xA9B5FFFF, 0xAAB3FFFF, 0xAAB4FFFF, 0xAAB5FFFF);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        var walkers = new PhysicsObj[40];
        for (int i = 0; i < walkers.Length; i++)
        {
            float x = 24f + 16f * (i % 8), y = 30f + 30f * (i / 8);
            Position p = SyntheticTerrain.OnGround(terrain, Holtburg.CentreCell(x, y), x, y, 45f * i);
            walkers[i] = SweepScene.Walker(world, p, id: (uint)(i + 1));
            SweepScene.SetWalk(walkers[i], new Vector3(0f, 3.12f, 0f));
            ((SimplePartArray)walkers[i].PartArray!).SequenceOmega = new Vector3(0f, 0f, 0.5f);
        }

        int contact = 0, samples = 0;
        SweepScene.Run(world, 600, _ =>
        {
            foreach (PhysicsObj w in walkers)
            {
                // validate_walkable rests the sphere's lowest point (directly under the origin) on the terrain: the origin
                // never ends below the ground under it.
                float ground = SweepScene.Ground(terrain, w.Position);
                Assert.True(w.Position.Frame.Origin.Z >= ground - 0.002f, $"{w} below ground {ground}");
                samples++;
                if ((w.TransientState & TransientState.Contact) != 0)
                {
                    contact++;
                }
            }
        });

        // Holtburg's hills are gentle: walkers keep their footing almost all the time (a stationary fall or a short hop at a
        // crease may lift one for a tick).
        Assert.True(contact > samples * 0.95, $"contact {contact} of {samples}");
    }
}
