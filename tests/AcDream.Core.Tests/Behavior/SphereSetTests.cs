using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class SphereSetTests
{
    private static PhysicsWorld Flat(out TerrainWorld terrain)
    {
        terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (vx, _) => 20 + 5 * vx);
        return SweepScene.Physics(terrain, out _);
    }

    [Fact]
    public void ObjectWithoutSpheres_IsPlacedWithTheDummySphere()
    {
        // No collision spheres: SetPosition sweeps retail's dummy sphere (r = 0.1, centre (0, 0, 0.1)); its low point is the
        // origin, so an object requested on the ground stays there, in contact. (The tick never sweeps it afterwards: an object
        // without spheres keeps its origin, see the tick's docs.)
        PhysicsWorld world = Flat(out TerrainWorld terrain);
        PhysicsObj obj = world.CreateObject(1);
        obj.PartArray = new SimplePartArray(1, 0);
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4);
        var p = new Position(cell, new Vector3(100f, 100f, 0f));
        p.Frame.Origin = new Vector3(100f, 100f, SweepScene.Ground(terrain, p));
        Assert.True(obj.EnterWorld(p));
        // (Within float rounding: the low point may be nudged by an ulp onto the plane.)
        Assert.Equal(p.Frame.Origin.X, obj.Position.Frame.Origin.X);
        Assert.Equal(p.Frame.Origin.Z, obj.Position.Frame.Origin.Z, 4);
        Assert.True((obj.TransientState & TransientState.Contact) != 0);
    }

    [Fact]
    public void TwoSphereWalker_TerrainFollowsTheFirstSphereOnly()
    {
        // The terrain test uses the path's low point and first sphere (find_env_collisions); a second (head) sphere only
        // widens the cell list. A walker with spheres (0,0,0.5) r 0.5 and (0,0,1.5) r 0.5 walks up the gentle slope
        // (5 m per 24 m) exactly as the one-sphere walker does.
        PhysicsWorld world1 = Flat(out _);
        PhysicsWorld world2 = Flat(out _);
        uint cell = SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 3, 4);
        var start = new Position(cell, Frame.FromHeading(new Vector3(80f, 100f, (float)(20 + 5.0 / 24.0 * 80.0)), 90f));
        PhysicsObj one = SweepScene.Walker(world1, start);
        PhysicsObj two = SweepScene.Walker(world2, start);
        ((SimplePartArray)two.PartArray!).SetSpheres(new[]
        {
            new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f),
            new Sphere(new Vector3(0f, 0f, 1.5f), 0.5f),
        });
        SweepScene.SetWalk(one, new Vector3(0f, 3f, 0f));
        SweepScene.SetWalk(two, new Vector3(0f, 3f, 0f));
        for (int i = 0; i < 200; i++)
        {
            world1.Tick(world1.CurrentTime + SweepScene.Dt);
            world2.Tick(world2.CurrentTime + SweepScene.Dt);
            Assert.Equal(one.Position, two.Position);
        }

        Assert.True(one.Position.Frame.Origin.X > 100f);
    }
}
