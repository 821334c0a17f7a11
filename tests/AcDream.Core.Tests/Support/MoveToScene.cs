using System.Numerics;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Support;

/// <summary>
/// Flat ground at z = 20 (landblock 0x8080, retail sweep) and creatures with one 0.5 m sphere, a cylinder radius of 0.5 m
/// (the part array's <c>Radius</c>, what move-tos measure with), the stand-in motion table (walk 3.12 m/s, run 4 m/s × run
/// rate, turn 1.5 rad/s) and the retail movement manager. Ticks of 0.05 s are one step each.
/// </summary>
internal static class MoveToScene
{
    /// <summary>The player's run speed with run skill 200: run rate 2.375 × 4 m/s = 9.5 m/s, 0.475 m per 0.05 s step.</summary>
    public const float RunSpeed = 9.5f;

    /// <summary>Walk speed: 3.12 m/s, 0.156 m per step.</summary>
    public const float WalkSpeed = 3.12f;

    /// <summary>One step of the turn at speed 1: 1.5 rad/s × 0.05 s = 0.075 rad = 4.2971835°.</summary>
    public const double TurnStepDegrees = 0.075 * 180.0 / System.Math.PI;

    public static PhysicsWorld FlatWorld()
    {
        var terrain = SweepScene.Terrain();
        SweepScene.AddBlock(terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 20);
        return SweepScene.Physics(terrain, out _);
    }

    /// <summary>Cell id of the scene's outdoor cell (4, 4) of landblock 0x8080 (positions are landblock-local).</summary>
    public static uint Cell => SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 4, 4);

    public static Position At(float x, float y) => new(Cell, new Vector3(x, y, 20f));

    public static PhysicsObj Creature(PhysicsWorld world, uint id, IMotionWeenie weenie, Vector3 at, float radius = 0.5f)
    {
        PhysicsObj obj = world.CreateObject(id);
        obj.Weenie = weenie;
        var parts = Walkers.OneSphere();
        parts.MotionPlayer = new SpeedOnlyMotionPlayer();
        parts.Radius = radius;
        obj.PartArray = parts;
        Assert.True(obj.EnterWorld(new Position(Cell, at)));
        return obj;
    }

    /// <summary>A world with the player (id 1, run skill 200) at (x, y, 20) facing north.</summary>
    public static (PhysicsWorld World, PhysicsObj Player, MovementManager Mm) WithPlayer(float x = 100f, float y = 40f)
    {
        PhysicsWorld world = FlatWorld();
        PhysicsObj player = Creature(world, 1, new PlayerWeenie { RunSkill = 200 }, new Vector3(x, y, 20f));
        world.Player = player;
        return (world, player, MovementManager.Of(player));
    }
}
