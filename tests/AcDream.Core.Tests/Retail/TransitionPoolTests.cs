using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class TransitionPoolTests
{
    [Fact]
    public void SweepNestedPastTen_Fails_AndTheWalkerKeepsItsOrigin()
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out RetailSweep sweep);
        PhysicsObj obj = SweepScene.Walker(world, new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4), new Vector3(100f, 100f, 20f)));
        SweepScene.SetWalk(obj, new Vector3(0f, 3f, 0f));

        // Ten sweeps already in progress (as if nested in callbacks): makeTransition returns null, the sweep fails, and
        // UpdateObjectInternal keeps the origin with a zero cached velocity.
        for (int i = 0; i < TransitionPool.Capacity; i++)
        {
            Assert.NotNull(sweep.Pool.Make());
        }

        Vector3 before = obj.Position.Frame.Origin;
        SweepScene.Run(world, 1);
        Assert.Equal(before, obj.Position.Frame.Origin);
        Assert.Equal(Vector3.Zero, obj.CachedVelocity);
        Assert.Equal(TransitionPool.Capacity, sweep.Pool.Level);

        // Given back, the next tick moves 3 * 0.05 = 0.15 m north.
        for (int i = 0; i < TransitionPool.Capacity; i++)
        {
            sweep.Pool.Cleanup();
        }

        SweepScene.Run(world, 1);
        Assert.Equal(before.Y + 0.15f, obj.Position.Frame.Origin.Y, 4);
        Assert.Equal(0, sweep.Pool.Level);
    }
}
