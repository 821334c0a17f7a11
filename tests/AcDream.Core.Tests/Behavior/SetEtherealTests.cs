using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class SetEtherealTests
{
    [Fact]
    public void BecomingSolid_WhileOverlappingAnObject_IsRefusedUntilItMovesAway()
    {
        PhysicsWorld world = ObjectScene.Flat(out _);
        PhysicsObj other = ObjectScene.Creature(world, 2, ObjectScene.At(100.6f, 100f));
        // An ethereal creature placed 0.6 m from the other (radsum 0.9998: overlapping); ethereal placements pass objects.
        var ghostState = (PhysicsState)PhysicsGlobals.DefaultState | PhysicsState.Ethereal;
        PhysicsObj ghost = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f, heading: 270f), state: ghostState);
        Assert.Equal(100f, ghost.Position.Frame.Origin.X, 3);

        // set_ethereal(0): ethereal_check_for_collisions finds the overlap through the shadows of the ghost's cells
        // (check_collision of the other creature at rest): the ghost stays ethereal and CHECK_ETHEREAL is set.
        Assert.False(ghost.SetEthereal(false));
        Assert.True((ghost.State & PhysicsState.Ethereal) != 0);
        Assert.True((ghost.TransientState & TransientState.CheckEthereal) != 0);

        // Walk west 1 m (10 ticks of 0.1 m): the gap becomes 1.6 m. Each step retries set_ethereal(0) (CHECK_ETHEREAL);
        // once clear, it turns solid.
        SweepScene.SetWalk(ghost, new Vector3(0f, 2f, 0f));
        SweepScene.Run(world, 10);
        Assert.Equal(99f, ghost.Position.Frame.Origin.X, 3);
        Assert.True((ghost.State & PhysicsState.Ethereal) == 0);
        Assert.True((ghost.TransientState & TransientState.CheckEthereal) == 0);
        Assert.Equal(100.6f, other.Position.Frame.Origin.X, 3);
    }
}
