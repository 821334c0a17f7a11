using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

public class CreatureCollisionTests
{
    [Fact]
    public void TwoCreatures_WalkingIntoEachOther_StopAtTheSumOfTheirRadii()
    {
        PhysicsWorld world = ObjectScene.Flat(out _);
        // A at x = 100 facing east, B at x = 104 facing west, both r = 0.5 at 2 m/s: 0.1 m per 0.05 s tick each.
        PhysicsObj a = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f, heading: 90f));
        PhysicsObj b = ObjectScene.Creature(world, 2, ObjectScene.At(104f, 100f, heading: 270f));
        SweepScene.SetWalk(a, new Vector3(0f, 2f, 0f));
        SweepScene.SetWalk(b, new Vector3(0f, 2f, 0f));
        // The spheres collide once the centre distance is <= radsum = 0.5 + 0.5 - EPSILON = 0.9998. After 15 ticks A is at
        // 101.5 and B at 102.5 (gap 1.0); on tick 16 each step would leave a gap of 0.9 and is refused (head on, nothing to
        // slide along): both stop with the gap at 1.0 = the sum of the radii.
        SweepScene.Run(world, 40);

        float gap = b.Position.Frame.Origin.X - a.Position.Frame.Origin.X;
        Assert.InRange(gap, 1.0f - 0.0002f, 1.0f + 0.001f);
        Assert.Equal(101.5f, a.Position.Frame.Origin.X, 3);
        Assert.Equal(102.5f, b.Position.Frame.Origin.X, 3);
        // Still on the ground, not lifted onto each other.
        Assert.Equal(ObjectScene.GroundZ, a.Position.Frame.Origin.Z);
        Assert.Equal(ObjectScene.GroundZ, b.Position.Frame.Origin.Z);
    }

    [Fact]
    public void Creature_FallingOntoASphere_StandsOnItsTop()
    {
        PhysicsWorld world = ObjectScene.Flat(out _);
        // Obstacle: one sphere r = 1 centred 1 m above its origin, resting on the ground at (100, 100): top at z = 22.
        ObjectScene.Obstacle(world, 10, ObjectScene.At(100f, 100f), spheres: new[] { new Sphere(new Vector3(0f, 0f, 1f), 1f) });
        // The creature (r = 0.5) enters 3 m above that top, beyond its 0.6 m step down: it falls.
        PhysicsObj c = ObjectScene.Creature(world, 1, ObjectScene.At(100f, 100f, 25f));
        Assert.True((c.TransientState & TransientState.Contact) == 0);

        SweepScene.Run(world, 60);

        // Straight down onto the apex: the landing contact plane is N = (0, 0, 1) through the touching point (z = 22), so the
        // creature's origin (the bottom of its sphere) rests at 22 and it stands (contact, walkable).
        Vector3 o = c.Position.Frame.Origin;
        Assert.Equal(22f, o.Z, 3);
        Assert.Equal(100f, o.X, 3);
        Assert.True((c.TransientState & (TransientState.Contact | TransientState.OnWalkable)) == (TransientState.Contact | TransientState.OnWalkable));
        Assert.Equal(0f, c.ContactPlaneNormal.X, 3);
        Assert.Equal(1f, c.ContactPlaneNormal.Z, 3);
        // Retail quirk (acclient.c:359156): the contact plane on an object's sphere is recorded as water.
        Assert.True((c.TransientState & TransientState.WaterContact) != 0);
    }

    [Fact]
    public void Creature_FallingOntoACreature_SlidesOffAndLandsBesideIt()
    {
        PhysicsWorld world = ObjectScene.Flat(out _);
        PhysicsObj a = ObjectScene.Creature(world, 2, ObjectScene.At(100f, 100f));
        // Falls from 3 m, 0.2 m off the other's axis. A creature's sphere is no platform: the landing request
        // (land_on_sphere) is answered OK for a creature (acclient.c:359156, is_creature), the collide request then fails
        // (no walkable contact) and the step collides with the normal from the other's centre; the faller bounces and slides
        // off sideways (+x, away from the other's centre) and lands on the ground beside it.
        PhysicsObj b = ObjectScene.Creature(world, 1, ObjectScene.At(100.2f, 100f, 23f));

        SweepScene.Run(world, 80, _ =>
        {
            // Never inside the other: sphere centres (0.5 above each origin) at least radsum = 0.9998 apart.
            Vector3 d = b.Position.Frame.Origin - a.Position.Frame.Origin;
            Assert.True(d.Length() >= 0.9998f - 1e-4f, $"penetration: {d.Length()}");
        });

        Vector3 o = b.Position.Frame.Origin;
        Assert.Equal(ObjectScene.GroundZ, o.Z);
        Assert.True(o.X > 101f);
        Assert.Equal(100f, o.Y, 3);
        Assert.True((b.TransientState & TransientState.OnWalkable) != 0);
        Assert.Equal(new Vector3(100f, 100f, 20f), a.Position.Frame.Origin);
    }
}
