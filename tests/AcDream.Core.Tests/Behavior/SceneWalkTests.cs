using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.WorldData;
using AcDream.Core.Tests.Support;
using Xunit;
using static AcDream.Core.Tests.Support.WorldSceneEntries;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// A walker (one sphere, radius 0.5 m, step-up 0.6 m) walks north at 2 m/s into the world's objects built from their data
/// ids by <see cref="WorldLoader"/>: it stops at a pine's cylinder, walks through grass, climbs a low rock GfxObj but not a
/// tall one, and meets a Setup building through its part 0 only.
/// </summary>
public class SceneWalkTests
{
    private const float R = 0.5f;

    private static (PhysicsWorld World, PhysicsObj Walker) Walk((uint Id, Frame Frame)[] objects, float x, float fromY,
        BuildingDef[]? buildings = null, int ticks = 100)
    {
        PhysicsWorld world = World(out _);
        new WorldLoader(world, Source(objects, buildings)).Load(Block);
        PhysicsObj w = SweepScene.Walker(world, new Position(BspScene.OutdoorCell(x, fromY), At(x, fromY)), R);
        SweepScene.SetWalk(w, new Vector3(0f, 2f, 0f));
        SweepScene.Run(world, ticks);
        return (world, w);
    }

    [Fact]
    public void AWalker_StopsAtAPine_ItsCylinderRadius_PlusItsOwn_ShortOfTheTrunk()
    {
        // 100 ticks of 0.05 s at 2 m/s would carry it 10 m, from y 90 to 100, in steps of 0.1 m; the cylinder (r 1.53,
        // reaching from z -3.8 to 30.8 around the trunk at y 100) blocks a step that ends within 1.53 + 0.5 - EPSILON =
        // 2.0298 m of the axis: the step to 98.0 (2.0 m) is refused, so the walker stays at 97.9.
        (_, PhysicsObj w) = Walk([(Pine, At(100f, 100f))], 100f, 90f);
        Assert.Equal(97.9f, w.Position.Frame.Origin.Y, 2);
    }

    [Fact]
    public void AWalker_PassesThroughGrass()
    {
        (_, PhysicsObj w) = Walk([(Grass, At(100f, 100f))], 100f, 95f);
        Assert.Equal(105f, w.Position.Frame.Origin.Y, 2);
    }

    [Fact]
    public void AWalker_ClimbsALowRock_WithinItsStepUp()
    {
        // The rock's top is 0.4 m up, within the step-up of 0.6 m: the walker crosses it (2 m wide, centred on y 100) and goes
        // on to y 105, back on the ground.
        (_, PhysicsObj w) = Walk([(LowRock, At(100f, 100f))], 100f, 95f);
        Assert.Equal(105f, w.Position.Frame.Origin.Y, 1);
        Assert.Equal(BspScene.Ground, w.Position.Frame.Origin.Z, 2);
    }

    [Fact]
    public void AWalker_StopsAtATallRock_AboveItsStepUp()
    {
        // 1.2 m is above the step-up: the sphere stops against the rock's south face at y 99, its centre 0.5 m short: 98.5.
        (_, PhysicsObj w) = Walk([(TallRock, At(100f, 100f))], 100f, 95f);
        Assert.Equal(98.5f, w.Position.Frame.Origin.Y, 1);
    }

    [Fact]
    public void ASetupBuilding_CollidesThroughPart0_Only()
    {
        // Part 0: a 2 m box at the building's origin (100, 100); part 1: the same box at (100, 110). The walker from y 90
        // stops at part 0's south face (y 99, centre 98.5); the one from y 104 walks through part 1 to y 114.
        BuildingDef b = new(Building, At(100f, 100f), 0, []);
        (_, PhysicsObj stopped) = Walk([], 100f, 90f, [b]);
        Assert.Equal(98.5f, stopped.Position.Frame.Origin.Y, 1);
        (_, PhysicsObj through) = Walk([], 100f, 104f, [b]);
        Assert.Equal(114f, through.Position.Frame.Origin.Y, 1);
    }
}
