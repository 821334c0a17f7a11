using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// A client's first scene: the human setup, the world over terrain, the player's movement manager and the setup check
/// (<see cref="PhysicsObj.SetupIssues"/>).
/// </summary>
public sealed class FirstSceneTests
{
    private const int Bx = 0x80;
    private const int By = 0x80;

    // Flat landblock 0x8080 at index 10 of the one-metre table: the ground is the plane z = 10.
    private static TerrainWorld Flat() => SyntheticTerrain.FlatBlock(Bx, By, 10);

    private static Position Spawn(TerrainWorld terrain) => SyntheticTerrain.OnGround(terrain, SyntheticTerrain.CellId(Bx, By, 4, 4), 100f, 100f);

    [Fact]
    public void HumanSetup_HoldsTheHumanCharacterSetupValues()
    {
        // Setup 0x02000001 (sources in docs/getting-started.md): two spheres of radius 0.48 at heights 0.48 and 1.2, no
        // cylinder spheres, radius 0.48, height 1.835, step-up 0.6, step-down 1.5.
        SetupPhysics h = SetupPhysics.Human;
        Assert.Equal(2, h.Spheres.Length);
        Assert.Equal(new Sphere(new Vector3(0f, 0f, 0.48f), 0.48f), h.Spheres[0]);
        Assert.Equal(new Sphere(new Vector3(0f, 0f, 1.2f), 0.48f), h.Spheres[1]);
        Assert.Equal(0, h.CylSpheres.Length);
        Assert.Equal(0x3EF5C28Fu, BitConverter.SingleToUInt32Bits(h.Radius));         // 0.48 f
        Assert.Equal(0x3FEAE148u, BitConverter.SingleToUInt32Bits(h.Height));         // 1.835 f
        Assert.Equal(0x3F19999Au, BitConverter.SingleToUInt32Bits(h.StepUpHeight));   // 0.6 f
        Assert.Equal(0x3FC00000u, BitConverter.SingleToUInt32Bits(h.StepDownHeight)); // 1.5 f
        Assert.Equal(0x3F99999Au, BitConverter.SingleToUInt32Bits(h.Spheres[1].Center.Z)); // 1.2 f
    }

    [Fact]
    public void SimplePartArray_FromASetup_TakesItsShapeSizesAndStepHeights()
    {
        var cyl = new CylSphere(new Vector3(0f, 0f, 0f), 0.3f, 1.1f);
        var setup = new SetupPhysics(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) }, new[] { cyl }, 0.7f, 1.9f, 0.4f, 1.25f);
        var parts = new SimplePartArray(setup, numParts: 3);

        Assert.Equal(3, parts.NumParts);
        Assert.Equal(setup.Spheres.ToArray(), parts.Spheres.ToArray());
        Assert.Equal(new[] { cyl }, parts.CylSpheres.ToArray());
        Assert.Equal((0.7f, 1.9f, 0.4f, 1.25f), (parts.Radius, parts.Height, parts.StepUpHeight, parts.StepDownHeight));
        Assert.Throws<ArgumentNullException>(() => new SimplePartArray(null!));
    }

    [Fact]
    public void SetupPhysics_RejectsBadValues()
    {
        var s = new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) };
        Assert.Throws<ArgumentException>(() => new SetupPhysics(s, ReadOnlySpan<CylSphere>.Empty, float.NaN, 1f, 0.5f, 0.5f));
        Assert.Throws<ArgumentException>(() => new SetupPhysics(s, ReadOnlySpan<CylSphere>.Empty, 1f, 1f, -0.1f, 0.5f));
        Assert.Throws<ArgumentException>(() => new SetupPhysics(new[] { new Sphere(Vector3.Zero, 0f) }, ReadOnlySpan<CylSphere>.Empty, 1f, 1f, 0.5f, 0.5f));
    }

    [Fact]
    public void WorldOverTerrain_UsesTheRetailSweep_WithoutTerrainTheFreeSpaceSweep()
    {
        var overTerrain = new PhysicsWorld(Flat());
        Assert.IsType<RetailSweep>(overTerrain.Sweep);
        Assert.False(overTerrain.IsFreeSpace);

        var free = new PhysicsWorld();
        Assert.Same(FreeSpaceSweep.Instance, free.Sweep);
        Assert.True(free.IsFreeSpace);
        Assert.Throws<ArgumentNullException>(() => new PhysicsWorld((TerrainWorld)null!));

        // A terrain world serves one physics world: a second world over it is refused, the first keeps it.
        TerrainWorld shared = Flat();
        var first = new PhysicsWorld(shared);
        Assert.Throws<ArgumentException>(() => new PhysicsWorld(shared));
        Assert.IsType<RetailSweep>(first.Sweep);
        Assert.IsType<RetailSweep>(new PhysicsWorld(new AcDream.Core.Physics.Cells.WorldCells(Flat())).Sweep);
        Assert.Throws<ArgumentNullException>(() => new PhysicsWorld((AcDream.Core.Physics.Cells.WorldCells)null!));
    }

    [Fact]
    public void PlayerOnTerrain_StandsOnIt_ForASecond()
    {
        // The issue's defect: a free-space world let a player on loaded terrain fall through (z -4.6 after 1 s). Over the
        // terrain the player rests on the plane z = 10 (contact: no gravity).
        TerrainWorld terrain = Flat();
        var world = new PhysicsWorld(terrain);
        PhysicsObj player = world.CreateObject(1);
        player.PartArray = new SimplePartArray(SetupPhysics.Human) { MotionPlayer = new SpeedOnlyMotionPlayer() };
        Assert.True(player.EnterWorld(Spawn(terrain)));
        world.Player = player;
        for (int k = 1; k <= 20; k++)
        {
            world.Tick(k * 0.05);
        }

        Assert.Equal(10f, player.Position.Frame.Origin.Z);
        Assert.Equal(ObjectSetupIssues.NoWeenie, player.SetupIssues);       // no PlayerWeenie: run rate 1
        player.Weenie = new PlayerWeenie();
        Assert.Equal(ObjectSetupIssues.None, player.SetupIssues);
    }

    [Fact]
    public void Player_WalkingThreeMetresPerSecond_MovesThreeMetresInOneSecond()
    {
        // Setting the world's player gives it retail's movement manager. Without one it deactivates itself on every step that
        // starts at rest on walkable ground (the small-velocity stop in UpdatePhysicsInternal leaves it inactive), so only every
        // other 0.05 s step moves it: 1.5 m. With one, all 20 steps of 0.05 s move it 3 * 0.05 = 0.15 m: 3 m north.
        TerrainWorld terrain = Flat();
        var world = new PhysicsWorld(terrain);
        PhysicsObj player = world.CreateObject(1);
        var body = new SimplePartArray(SetupPhysics.Human);
        player.PartArray = body;
        Assert.True(player.EnterWorld(Spawn(terrain)));
        world.Player = player;
        Assert.IsType<MovementManager>(player.Movement);   // the retail movement manager (Physics/Motion)
        body.SequenceVelocity = new Vector3(0f, 3f, 0f);
        for (int k = 1; k <= 20; k++)
        {
            world.Tick(k * 0.05);
        }

        Assert.Equal(103f, player.Position.Frame.Origin.Y, 4);
        Assert.Equal(100f, player.Position.Frame.Origin.X);
        Assert.Equal(10f, player.Position.Frame.Origin.Z);
    }

    [Fact]
    public void Creature_WithoutAMovementManager_WalksHalfSpeed_AndSaysSo()
    {
        // Retail behaviour, kept: a non-player object without a movement manager loses ACTIVE on each step that begins at rest
        // on walkable ground; within 96 m of the player update_object sets it active again on the next frame, and that frame's
        // step clears it again, so it moves on every other step (10 of 20): 1.5 m. (With no player nothing reactivates it: it
        // stops after its first step.) SetupIssues names the cause.
        TerrainWorld terrain = Flat();
        var world = new PhysicsWorld(terrain);
        PhysicsObj player = world.CreateObject(1);
        player.PartArray = new SimplePartArray(SetupPhysics.Human);
        Position p = Spawn(terrain);
        p.Frame.Origin += new Vector3(10f, 0f, 0f);
        Assert.True(player.EnterWorld(p));
        world.Player = player;
        PhysicsObj creature = world.CreateObject(2);
        var body = new SimplePartArray(SetupPhysics.Human);
        creature.PartArray = body;
        Assert.True(creature.EnterWorld(Spawn(terrain)));
        Assert.Equal(ObjectSetupIssues.NoMovementManager | ObjectSetupIssues.NoMotionTable | ObjectSetupIssues.NoWeenie,
            creature.SetupIssues);
        body.SequenceVelocity = new Vector3(0f, 3f, 0f);
        for (int k = 1; k <= 20; k++)
        {
            world.Tick(k * 0.05);
        }

        Assert.Equal(101.5f, creature.Position.Frame.Origin.Y, 4);
    }

    [Fact]
    public void Player_GetsTheWorldFactorysMovementManager()
    {
        var world = new PhysicsWorld(Flat());
        var made = new BasicMovementManager();
        world.MovementManagerFactory = new Factory(made);
        PhysicsObj player = world.CreateObject(1);
        world.Player = player;
        Assert.Same(made, player.Movement);

        // A player that already has one keeps it.
        var own = new BasicMovementManager();
        PhysicsObj other = world.CreateObject(2);
        other.Movement = own;
        world.Player = other;
        Assert.Same(own, other.Movement);
    }

    [Fact]
    public void SetupIssues_NameEachMistake()
    {
        var free = new PhysicsWorld();
        PhysicsObj bare = free.CreateObject(1);
        Assert.Equal(ObjectSetupIssues.NoPartArray | ObjectSetupIssues.NoMovementManager | ObjectSetupIssues.FreeSpaceSweep
            | ObjectSetupIssues.NotInCell | ObjectSetupIssues.NoWeenie, bare.SetupIssues);

        // README's old recipe: a part array of retail's no-setup step heights (0.01 m).
        TerrainWorld terrain = Flat();
        var world = new PhysicsWorld(terrain);
        PhysicsObj noSetup = world.CreateObject(2);
        var parts = new SimplePartArray(1, 0);
        parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) });
        noSetup.PartArray = parts;
        noSetup.Movement = new BasicMovementManager();
        Assert.True(noSetup.EnterWorld(Spawn(terrain)));
        Assert.Equal(ObjectSetupIssues.NoSetupStepHeights, noSetup.SetupIssues);

        PhysicsObj noSpheres = world.CreateObject(3);
        noSpheres.PartArray = new SimplePartArray(1, 0) { StepUpHeight = 0.6f, StepDownHeight = 0.6f };
        noSpheres.Movement = new BasicMovementManager();
        Assert.True(noSpheres.EnterWorld(Spawn(terrain)));
        Assert.Equal(ObjectSetupIssues.NoCollisionSpheres, noSpheres.SetupIssues);
    }

    [Fact]
    public void ObjectWithoutAPartArray_AskedToMove_StaysOutOfEveryCell_AndIsReported()
    {
        // Retail enter_cell needs a part array: the object is never in a cell, update_object skips it, and a velocity set on
        // it moves nothing. SetupIssues reports NoPartArray and NotInCell.
        TerrainWorld terrain = Flat();
        var world = new PhysicsWorld(terrain);
        PhysicsObj obj = world.CreateObject(1);
        obj.Movement = new BasicMovementManager();
        obj.EnterWorld(Spawn(terrain));
        obj.SetVelocity(new Vector3(0f, 3f, 0f));
        Vector3 before = obj.Position.Frame.Origin;
        for (int k = 1; k <= 20; k++)
        {
            world.Tick(k * 0.05);
        }

        Assert.Equal(before, obj.Position.Frame.Origin);
        Assert.Equal(0u, obj.CellId);
        Assert.Equal(ObjectSetupIssues.NoPartArray | ObjectSetupIssues.NotInCell, obj.SetupIssues);
    }

    private sealed class Factory(IMovementManager made) : IMovementManagerFactory
    {
        public IMovementManager Create(PhysicsObj obj) => made;
    }
}
