using System;
using System.Numerics;
using AcDream.Core.Physics.Collision;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;
using Xunit;

namespace AcDream.Core.Tests.Retail;

public class FindObjCollisionsRulesTests
{
    // A sweep of `mover` against `obstacle` alone, the mover's first sphere overlapping it: the mover is placed 0.5 m from
    // the obstacle's centre (radsum 0.9998) and the check position is that overlap (a transition at rest, insert_type
    // TRANSITION, no step down).
    private static (TransitionState State, Transition T) Hit(RetailSweep sweep, PhysicsObj mover, PhysicsObj obstacle,
        ObjectInfoState state)
    {
        Transition t = sweep.Pool.Make()!;
        try
        {
            Position p = obstacle.Position;
            p.Frame.Origin += new Vector3(-0.5f, 0f, 0f);
            t.InitObject(mover, state);
            t.InitSphere(mover.PartArray!.Spheres, mover.Scale);
            t.InitPath(sweep.Cells.GetVisible(p.ObjCellId), p, p);
            t.SpherePath.SetCheckPos(p, t.SpherePath.CurrCell);
            return (obstacle.FindObjCollisions(t), t);
        }
        finally
        {
            sweep.Pool.Cleanup();
        }
    }

    private static PhysicsObj Ball(PhysicsWorld world, uint id, float x, PhysicsState extra = PhysicsState.None, IWeenieObject? weenie = null) =>
        ObjectScene.Obstacle(world, id, ObjectScene.At(x, 100f), spheres: new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) }, extra: extra,
            weenie: weenie);

    [Fact]
    public void EtherealIgnoringCollisions_IsSkippedEntirely()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        PhysicsObj mover = Ball(world, 1, 50f);
        PhysicsObj o = Ball(world, 2, 100f, PhysicsState.Ethereal | PhysicsState.IgnoreCollisions);
        var (state, t) = Hit(sweep, mover, o, ObjectInfoState.None);
        Assert.Equal(TransitionState.Ok, state);
        Assert.Equal(0, t.CollisionInfo.NumCollideObject);
    }

    [Fact]
    public void SolidObject_IsRecordedAsTheLastCollidedObject_StaticOneAsTheEnvironment()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        PhysicsObj mover = Ball(world, 1, 50f);
        PhysicsObj solid = Ball(world, 2, 100f);
        PhysicsObj rock = Ball(world, 3, 110f, PhysicsState.Static);

        // Not in contact (falling): land_on_sphere asks for the landing test -> Adjusted, recorded with that state.
        var (s1, t1) = Hit(sweep, mover, solid, ObjectInfoState.None);
        Assert.Equal(TransitionState.Adjusted, s1);
        Assert.Equal(solid, t1.CollisionInfo.LastCollidedObject);
        Assert.False(t1.CollisionInfo.CollidedWithEnvironment);
        // land_on_sphere: set_collide (backup of the check position, walk_interp = 1) and walkable_allowance = z_for_landing_0
        // = 0.0871557f (acclient_data.h:2442).
        Assert.True(t1.SpherePath.Collide);
        Assert.Equal(1f, t1.SpherePath.WalkInterp);
        Assert.Equal(0.0871557f, t1.SpherePath.WalkableAllowance);
        Assert.Equal(BitConverter.SingleToInt32Bits(0.0871557f), BitConverter.SingleToInt32Bits(t1.SpherePath.WalkableAllowance));

        var (s2, t2) = Hit(sweep, mover, rock, ObjectInfoState.None);
        Assert.Equal(TransitionState.Adjusted, s2);
        Assert.Equal(0, t2.CollisionInfo.NumCollideObject);
        Assert.True(t2.CollisionInfo.CollidedWithEnvironment);
        // In contact with the ground the static hit does not count as an environment collision.
        var (_, t3) = Hit(sweep, mover, rock, ObjectInfoState.Contact);
        Assert.False(t3.CollisionInfo.CollidedWithEnvironment);
    }

    [Fact]
    public void IgnoreCreatures_PassesCreaturesAndMissiles_NotPlainObjects()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        PhysicsObj mover = Ball(world, 1, 50f);
        PhysicsObj creature = Ball(world, 2, 100f, weenie: WeenieTraits.Creature);
        PhysicsObj missile = Ball(world, 3, 110f);
        PhysicsObj plain = Ball(world, 4, 120f);
        // Retail's is_creature is "MISSILE or the weenie says creature" (acclient.c:316158).
        missile.SetState(missile.State | PhysicsState.Missile);
        var (s1, t1) = Hit(sweep, mover, creature, ObjectInfoState.IgnoreCreatures);
        Assert.Equal(TransitionState.Ok, s1);
        Assert.Equal(creature, t1.CollisionInfo.CollideObjects[0]);
        Assert.False(t1.CollisionInfo.CollisionNormalValid);
        Assert.Equal(TransitionState.Ok, Hit(sweep, mover, missile, ObjectInfoState.IgnoreCreatures).State);
        Assert.NotEqual(TransitionState.Ok, Hit(sweep, mover, plain, ObjectInfoState.IgnoreCreatures).State);
    }

    [Fact]
    public void Viewer_PassesCreatures()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        PhysicsObj mover = Ball(world, 1, 50f);
        PhysicsObj creature = Ball(world, 2, 100f, weenie: WeenieTraits.Creature);
        Assert.Equal(TransitionState.Ok, Hit(sweep, mover, creature, ObjectInfoState.IsViewer).State);
        Assert.NotEqual(TransitionState.Ok, Hit(sweep, mover, creature, ObjectInfoState.None).State);
    }

    [Fact]
    public void Players_PassUnlessImpenetrableOrBothPKOrBothPKLite()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        PhysicsObj mover = Ball(world, 1, 50f);
        PhysicsObj player = Ball(world, 2, 100f, weenie: WeenieTraits.Player);
        PhysicsObj pk = Ball(world, 3, 110f, weenie: new WeenieTraits { IsCreature = true, IsPlayer = true, IsPK = true });
        PhysicsObj pkl = Ball(world, 4, 120f, weenie: new WeenieTraits { IsCreature = true, IsPlayer = true, IsPKLite = true });
        PhysicsObj imp = Ball(world, 5, 130f, weenie: new WeenieTraits { IsCreature = true, IsPlayer = true, IsImpenetrable = true });
        const ObjectInfoState P = ObjectInfoState.IsPlayer;

        Assert.Equal(TransitionState.Ok, Hit(sweep, mover, player, P).State);
        Assert.Equal(TransitionState.Ok, Hit(sweep, mover, pk, P).State);
        Assert.NotEqual(TransitionState.Ok, Hit(sweep, mover, pk, P | ObjectInfoState.IsPK).State);
        Assert.Equal(TransitionState.Ok, Hit(sweep, mover, pkl, P | ObjectInfoState.IsPK).State);
        Assert.NotEqual(TransitionState.Ok, Hit(sweep, mover, pkl, P | ObjectInfoState.IsPKLite).State);
        Assert.NotEqual(TransitionState.Ok, Hit(sweep, mover, imp, P).State);
        Assert.NotEqual(TransitionState.Ok, Hit(sweep, mover, player, P | ObjectInfoState.IsImpenetrable).State);
        // A non-player mover is blocked by players.
        Assert.NotEqual(TransitionState.Ok, Hit(sweep, mover, player, ObjectInfoState.None).State);
    }

    [Fact]
    public void MissileIgnore_TruthTable()
    {
        PhysicsWorld world = ObjectScene.Flat(out RetailSweep sweep);
        PhysicsObj missile = Ball(world, 1, 50f, PhysicsState.Missile);
        PhysicsObj plain = Ball(world, 2, 60f);
        PhysicsObj otherMissile = Ball(world, 3, 70f, PhysicsState.Missile);
        PhysicsObj creature = Ball(world, 4, 80f, weenie: WeenieTraits.Creature);
        PhysicsObj etherealGame = Ball(world, 5, 90f, PhysicsState.Ethereal, WeenieTraits.Creature);
        PhysicsObj target = Ball(world, 6, 100f, weenie: WeenieTraits.Creature);
        // Placed on the ground, the two missiles reported an environment collision, which strips MISSILE (retail
        // report_environment_collision): arm them again.
        missile.SetState(missile.State | PhysicsState.Missile);
        otherMissile.SetState(otherMissile.State | PhysicsState.Missile);
        Transition t = sweep.Pool.Make()!;
        try
        {
            t.InitObject(missile, ObjectInfoState.PathClipped);
            ObjectInfo oi = t.ObjectInfo;
            Assert.True(oi.MissileIgnore(otherMissile));
            Assert.False(oi.MissileIgnore(plain));
            // No target: creatures are hit; an ethereal game object is passed.
            Assert.False(oi.MissileIgnore(creature));
            Assert.True(oi.MissileIgnore(etherealGame));
            // Aimed at the target: other creatures are passed, the target is not.
            oi.TargetId = target.Id;
            Assert.True(oi.MissileIgnore(creature));
            Assert.False(oi.MissileIgnore(target));
            // A non-missile mover ignores only missiles.
            t.InitObject(plain, ObjectInfoState.None);
            Assert.True(t.ObjectInfo.MissileIgnore(otherMissile));
            Assert.False(t.ObjectInfo.MissileIgnore(creature));
        }
        finally
        {
            sweep.Pool.Cleanup();
        }
    }
}
