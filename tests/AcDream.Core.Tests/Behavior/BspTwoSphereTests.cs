using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class BspTwoSphereTests
{
    // A beam across the path: x 104..105, y 90..110, between heights lo and hi above the ground.
    private static PhysicsObj BeamScene(float lo, float hi, out PhysicsWorld world)
    {
        WorldCells cells = BspScene.FlatWorld();
        BspScene.AddBoxes(cells, new Vector3(104f, 100f, BspScene.Ground), (new Vector3(0f, -10f, lo), new Vector3(1f, 10f, hi)));
        world = BspScene.Physics(cells);
        PhysicsObj obj = BspScene.TwoSphereWalker(world, new Position(BspScene.OutdoorCell(100f, 100f), Frame.FromHeading(new Vector3(100f, 100f, BspScene.Ground), 90f)));
        SweepScene.SetWalk(obj, new Vector3(0f, 2f, 0f));
        return obj;
    }

    [Fact]
    public void HeadSphereHittingALowBeam_StopsTheWalker()
    {
        // Beam 1.2..1.7 m: the head sphere (centre 1.5, r 0.5) meets its west face (x = 104); the feet (top at 1.0) pass
        // under. The second sphere's hit slides along the face (normal -x) on the ground plane: the crease runs along y,
        // the eastward step has nothing along it, so the step collides.
        PhysicsObj obj = BeamScene(1.2f, 1.7f, out PhysicsWorld world);
        SweepScene.Run(world, 60, _ => Assert.True(obj.Position.Frame.Origin.X <= 104f - 0.5f + 0.001f, $"passed under: {obj.Position.Frame.Origin}"));
        // It got there (0.1 m per tick: within one step of touching).
        Assert.True(obj.Position.Frame.Origin.X >= 104f - 0.5f - 0.1f - 0.001f);
        Assert.Equal(BspScene.Ground, obj.Position.Frame.Origin.Z, 3);
    }

    [Fact]
    public void AHighBeam_LetsTheWalkerPassUnder()
    {
        // Beam 2.5..3 m: above the head sphere's top (1.5 + 0.5 = 2.0).
        PhysicsObj obj = BeamScene(2.5f, 3f, out PhysicsWorld world);
        SweepScene.Run(world, 60);
        // 60 ticks * 0.1 m = 6 m: from x 100 to 106, past the beam.
        Assert.Equal(106f, obj.Position.Frame.Origin.X, 2);
    }
}
