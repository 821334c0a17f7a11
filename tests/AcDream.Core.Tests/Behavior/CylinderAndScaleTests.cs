using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class CylinderAndScaleTests
{
    [Fact]
    public void Creature_FallingOntoACylinder_StandsOnItsTopDisc()
    {
        PhysicsWorld world = ObjectScene.Flat(out _);
        // A cylinder r = 1, h = 1.5 standing at (100, 100): top disc at z = 21.5. The creature falls from 24 onto it off the
        // axis (x = 100.6): land_on_cylinder, then the landing puts the sphere's bottom on the disc with the flat plane z = 21.5.
        ObjectScene.Obstacle(world, 10, ObjectScene.At(100f, 100f), cyl: new[] { new CylSphere(Vector3.Zero, 1f, 1.5f) });
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(100.6f, 100f, 24f));

        SweepScene.Run(world, 60);

        Vector3 o = c.Position.Frame.Origin;
        Assert.Equal(21.5f, o.Z, 3);
        Assert.Equal(100.6f, o.X, 3);
        Assert.Equal(new Vector3(0f, 0f, 1f), c.ContactPlaneNormal);
        Assert.Equal(-21.5f, c.ContactPlaneD, 3);
        Assert.True((c.TransientState & TransientState.OnWalkable) != 0);
    }

    [Fact]
    public void PerfectClipMissile_HitsACylinderSide_AtTheTimeOfImpact()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        // Cylinder r = 0.5, h = 2 at (100, 100); missile sphere r = 0.1 at height 21 moving +x from 99.25 to 99.75.
        ObjectScene.Obstacle(world, 10, ObjectScene.At(100f, 100f), cyl: new[] { new CylSphere(Vector3.Zero, 0.5f, 2f) });
        PhysicsObj m = ObjectScene.Obstacle(world, 50, ObjectScene.At(99.25f, 100f, 21f), spheres: new[] { new Sphere(Vector3.Zero, 0.1f) },
            extra: PhysicsState.Missile);
        // Steps of 0.1 (radsum = 0.5 + 0.1 - EPSILON = 0.5998): the first (to 99.35, |dx| = 0.65) is clear, the second (to
        // 99.45, |dx| = 0.55) overlaps the side. From 99.35 the side is touched at r = 0.5998 + 0.0002 = 0.6:
        // t = (0.065 - sqrt(0.065^2 - (0.4225 - 0.36) * 0.01)) / 0.01 = (0.065 - 0.06) / 0.01 = 0.5 -> x = 99.40.
        Assert.Equal(99.4f, MissileCollisionTests.Sweep(sweep, m, ObjectInfoState.PathClipped | ObjectInfoState.PerfectClip, 99.25f, 99.75f), 3);
    }

    [Fact]
    public void ObstacleScale_ScalesItsSpheres()
    {
        PhysicsWorld world = ObjectScene.Flat(out _);
        // Sphere r = 0.5 centred 0.5 above the origin, object scale 2: r = 1 centred 1 above (resting on the ground). The
        // walker (r = 0.5, centre 0.5 up) meets it where |(dx, 0, -0.5)| <= 1.4998: dx <= 1.4132. From 100 in 0.1 m steps
        // towards the obstacle at 104: 102.5 leaves dx = 1.5, 102.6 leaves 1.4 (blocked), so it stops at 102.5.
        PhysicsObj big = ObjectScene.Obstacle(world, 10, ObjectScene.At(104f, 100f), spheres: new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) });
        big.SetScaleStatic(2f);
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f, heading: 90f));
        SweepScene.SetWalk(c, new Vector3(0f, 2f, 0f));

        SweepScene.Run(world, 60);

        Assert.Equal(102.5f, c.Position.Frame.Origin.X, 3);
    }
}
