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

public class PlacementTests
{
    [Fact]
    public void Placement_InWaterNextToDryLand_FailsAtTheInitialTest_EvenWithSlide()
    {
        // Block (bx, by) is entirely water (refuses walkers); block (bx + 1, by) east of it is dry; both flat at 20 m.
        // find_placement_position's initial test (objects skipped) collides with the water, and validate_placement
        // re-inserts only ADJUSTED / SLID results (ts > COLLIDED, acclient.c:312600): the ring search is never reached,
        // although dry land lies 1 m away. (The search resolves object overlaps; see PlacementSearchTests.)
        const int bx = SweepScene.BlockX, by = SweepScene.BlockY;
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, bx, by, (_, _) => 20, (_, _) => 17);
        SweepScene.AddBlock(terrain, bx + 1, by, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        PhysicsObj obj = world.CreateObject(1);
        var parts = new SimplePartArray(1, 0);
        parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) });
        obj.PartArray = parts;
        Assert.False(obj.EnterWorld(new Position(SweepScene.CellId(bx, by, 7, 4), new Vector3(191f, 96f, 20f))));
        Assert.Equal(0u, obj.CellId);
    }

    [Fact]
    public void Placement_WithoutSlide_InWater_Fails()
    {
        const int bx = SweepScene.BlockX, by = SweepScene.BlockY;
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, bx, by, (_, _) => 20, (_, _) => 17);
        SweepScene.AddBlock(terrain, bx + 1, by, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out _);
        PhysicsObj obj = world.CreateObject(1);
        var parts = new SimplePartArray(1, 0);
        parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) });
        obj.PartArray = parts;
        // SetPositionSimple without sliding: placement_allows_sliding = 0, so no ring search: NO_VALID_POSITION.
        SetPositionError e = obj.SetPositionSimple(new Position(SweepScene.CellId(bx, by, 7, 4), new Vector3(191f, 96f, 20f)), false);
        Assert.NotEqual(SetPositionError.Ok, e);
    }
}
