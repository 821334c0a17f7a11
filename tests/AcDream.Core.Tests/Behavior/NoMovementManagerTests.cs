using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// A creature walked by root motion without a movement manager (what <c>docs/getting-started.md</c> and
/// <see cref="ObjectSetupIssues.NoMovementManager"/> describe). Retail behaviour, kept: each step that begins at rest on
/// walkable ground clears ACTIVE when the object has no movement manager; only <c>update_object</c>'s player-distance check
/// sets it again. The half-speed case (a player within 96 m) is <c>FirstSceneTests.Creature_WithoutAMovementManager_WalksHalfSpeed_AndSaysSo</c>.
/// </summary>
public sealed class NoMovementManagerTests
{
    private const int Bx = 0x80;
    private const int By = 0x80;

    [Fact]
    public void Creature_WithoutAMovementManager_InAWorldWithoutAPlayer_TakesOneStepAndStops()
    {
        // No player: nothing reactivates the creature, so after the first step (0.05 s at 3 m/s: 0.15 m north) it is inactive
        // for good and the next 19 ticks leave it where it is.
        TerrainWorld terrain = SyntheticTerrain.Metres();
        SyntheticTerrain.AddBlock(terrain, Bx, By, (_, _) => 10);
        var world = new PhysicsWorld(terrain);
        PhysicsObj creature = world.CreateObject(2);
        var body = new SimplePartArray(SetupPhysics.Human);
        creature.PartArray = body;
        Assert.True(creature.EnterWorld(SyntheticTerrain.OnGround(terrain, SyntheticTerrain.CellId(Bx, By, 4, 4), 100f, 100f)));
        Assert.Null(world.Player);
        // Root motion is set directly here (no motion commands), so the missing motion table is reported beside it.
        Assert.Equal(ObjectSetupIssues.NoMovementManager | ObjectSetupIssues.NoMotionTable | ObjectSetupIssues.NoWeenie,
            creature.SetupIssues);
        body.SequenceVelocity = new Vector3(0f, 3f, 0f);

        world.Tick(0.05);
        float afterFirst = creature.Position.Frame.Origin.Y;
        for (int k = 2; k <= 20; k++)
        {
            world.Tick(k * 0.05);
        }

        Assert.Equal(100.15f, afterFirst, 4);
        Assert.Equal(afterFirst, creature.Position.Frame.Origin.Y);
        Assert.False(creature.IsActive);
    }
}
