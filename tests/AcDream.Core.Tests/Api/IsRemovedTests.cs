using System;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// <see cref="PhysicsObj.IsRemoved"/>: false from creation (before and after <see cref="PhysicsObj.EnterWorld"/>, in a cell or
/// not), true once <see cref="PhysicsWorld.RemoveObject"/> took the object out, also from inside a callback of its own step.
/// </summary>
public sealed class IsRemovedTests
{
    private const int Bx = 0x80;
    private const int By = 0x80;

    private static (PhysicsWorld World, TerrainWorld Terrain) FlatWorld()
    {
        TerrainWorld terrain = SyntheticTerrain.FlatBlock(Bx, By, 10);
        return (new PhysicsWorld(terrain), terrain);
    }

    [Fact]
    public void FalseFromCreation_ThroughEnterWorld_TrueAfterRemoveObject()
    {
        (PhysicsWorld world, TerrainWorld terrain) = FlatWorld();
        PhysicsObj obj = world.CreateObject(1);
        Assert.False(obj.IsRemoved);
        Assert.Equal(0u, obj.CellId);

        obj.PartArray = new SimplePartArray(SetupPhysics.Human, 1);
        Position spawn = SyntheticTerrain.OnGround(terrain, SyntheticTerrain.CellId(Bx, By, 4, 4), 100f, 100f);
        Assert.True(obj.EnterWorld(spawn));
        world.Tick(0.05);
        Assert.False(obj.IsRemoved);

        world.RemoveObject(obj);
        Assert.True(obj.IsRemoved);
        Assert.Equal(0u, obj.CellId);
        Assert.Throws<InvalidOperationException>(() => obj.EnterWorld(spawn));
        Assert.True(obj.IsRemoved);
    }

    [Fact]
    public void NeverPlacedObject_IsNotRemoved_UntilRemoveObject()
    {
        (PhysicsWorld world, _) = FlatWorld();
        PhysicsObj obj = world.CreateObject();
        world.Tick(0.05);
        Assert.False(obj.IsRemoved);
        world.RemoveObject(obj);
        Assert.True(obj.IsRemoved);
    }

    [Fact]
    public void RemovedFromItsOwnStep_ReadsTrueInsideTheCallback()
    {
        (PhysicsWorld world, TerrainWorld terrain) = FlatWorld();
        PhysicsObj obj = world.CreateObject(1);
        obj.PartArray = new SimplePartArray(SetupPhysics.Human, 1);
        Assert.True(obj.EnterWorld(SyntheticTerrain.OnGround(terrain, SyntheticTerrain.CellId(Bx, By, 4, 4), 100f, 100f)));
        var observer = new RemovingObserver(world, obj);
        world.StepObserver = observer;
        world.Tick(0.05);
        Assert.True(observer.Removed);
        Assert.True(observer.SeenAfterRemove);
        Assert.True(obj.IsRemoved);
    }

    private sealed class RemovingObserver(PhysicsWorld world, PhysicsObj target) : IStepObserver
    {
        public bool Removed { get; private set; }

        public bool SeenAfterRemove { get; private set; }

        public void OnStep(PhysicsObj obj, float quantum, double physicsTime)
        {
            if (obj != target || Removed)
            {
                return;
            }

            Assert.False(obj.IsRemoved);
            world.RemoveObject(obj);
            Removed = true;
            SeenAfterRemove = obj.IsRemoved;
        }
    }
}
