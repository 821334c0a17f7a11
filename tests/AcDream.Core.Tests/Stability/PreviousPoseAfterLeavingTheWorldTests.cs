using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Stability;

/// <summary>
/// Issue #34, item 7: a walker whose landblock is removed before its first update, re-added and placed again, then ticked
/// once, had <see cref="PhysicsObj.PreviousPose"/> with rotation (0, 0, 0, 0) while
/// <see cref="PhysicsObj.IsPlacedSinceLastUpdate"/> was false: the update consumed no time, so it recorded no pose pair, yet
/// it cleared the placement mark. A pose a client reads directly must be a pose.
/// </summary>
public class PreviousPoseAfterLeavingTheWorldTests
{
    private static float NormSq(in Position p)
    {
        Frame f = p.Frame;
        return f.Qw * f.Qw + f.Qx * f.Qx + f.Qy * f.Qy + f.Qz * f.Qz;
    }

    [Fact]
    public void BlockRemovedBeforeTheFirstUpdate_ReAddedAndPlaced_OneTick_PreviousPoseIsAPose()
    {
        TerrainWorld terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        PhysicsWorld world = SweepScene.Physics(terrain, out RetailSweep _);
        Position at = ObjectScene.At(100f, 100f, heading: 90f);
        PhysicsObj walker = SweepScene.Walker(world, at);
        // The client's clock moves on (SetCurrentTime), and before the tick runs the landblock goes and comes back: the
        // walker, never updated, leaves the world and is placed again, at the new clock (its update time is now).
        world.SetCurrentTime(world.CurrentTime + SweepScene.Dt);
        Assert.True(terrain.RemoveLandBlock(at.ObjCellId));
        Assert.Equal(0u, walker.CellId);
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        Assert.True(walker.EnterWorld(at));
        Assert.Equal(world.CurrentTime, walker.UpdateTime);
        // One tick at that clock: the walker's update consumes no time and runs no step.
        world.UseTime();

        // No pair was recorded: the walker is still "placed since its last update" (drawn at its position, not blended).
        Assert.True(walker.IsPlacedSinceLastUpdate);
        Assert.Equal(walker.Position, walker.GetRenderPose(world.RenderTime));

        // The next update that consumes time records a real pair: it starts from the placement (heading 90°, |q|² = 1 to
        // float rounding, 1e-6), at the placement's time.
        world.Tick(world.CurrentTime + SweepScene.Dt);
        Assert.False(walker.IsPlacedSinceLastUpdate);
        Assert.Equal(1f, NormSq(walker.PreviousPose), 6);
        Assert.Equal(90.0, walker.PreviousPose.Frame.Heading, 3);
        Assert.Equal(at.Frame.Origin, walker.PreviousPose.Frame.Origin);
    }
}
