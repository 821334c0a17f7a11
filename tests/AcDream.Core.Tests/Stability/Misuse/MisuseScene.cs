using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Motion.Wire;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support;

namespace AcDream.Core.Tests.Stability.Misuse;

/// <summary>
/// The misuse suite's small scene: flat terrain (landblock 0x8080 at height index 10, the one-metre table: z = 10 m), the retail
/// sweep, a walker at (100, 100) (one 0.5 m sphere, a movement manager, walking 1 m/s, the player) with every position manager in
/// use, a resting second object 3 m east, a dormant third object (no movement manager) 6 m west, a fade in progress, and a
/// remote creature 6 m north (an animated part array playing a motion table from bytes) with retail's movement manager and motion interpreter (run rate 1.5 from a MovementEvent's
/// state), running a move-to towards the second object. Built fresh for every case.
/// </summary>
internal sealed class MisuseScene
{
    /// <summary>Tick length, seconds (one step per tick).</summary>
    public const double Dt = 0.05;

    public MisuseScene()
    {
        Terrain = SweepScene.Terrain();
        SweepScene.AddBlock(Terrain, SweepScene.BlockX, SweepScene.BlockY, (_, _) => 10);
        World = SweepScene.Physics(Terrain, out RetailSweep sweep);
        Sweep = sweep;
        Walker = SweepScene.Walker(World, At(100f, 100f), id: 1);
        WalkerParts = (SimplePartArray)Walker.PartArray!;
        Other = SweepScene.Walker(World, At(103f, 100f), id: 2);
        Resting = World.CreateObject(3);
        Resting.PartArray = Support.Shared.Walkers.OneSphere();
        Resting.EnterWorld(At(94f, 100f));
        World.Player = Walker;
        WalkerParts.SequenceVelocity = new Vector3(0f, 1f, 0f);
        Walker.SetTranslucency(0.5f, 1.0);
        Walker.InterpolateTo(At(100f, 102f), false);
        Walker.ConstrainTo(Walker.Position, 10f, 50f);
        Walker.PositionManager!.StickTo(2u, 0.5f, 1.8f);
        Creature = World.CreateObject(4);
        Creature.Weenie = RemoteCreatureWeenie.Creature;
        Creature.PartArray = AnimatedParts();
        Creature.EnterWorld(At(100f, 106f));
        MovementEvent.ApplyInterpretedMotion(Creature,
            new InterpretedMotionState { ForwardCommand = MotionCommand.RunForward, ForwardSpeed = 1.5f });
        Creature.MoveToObject(2u, new MovementParameters());
        Tick(4);
    }

    public TerrainWorld Terrain { get; }

    public PhysicsWorld World { get; }

    public RetailSweep Sweep { get; }

    public PhysicsObj Walker { get; }

    public SimplePartArray WalkerParts { get; }

    public PhysicsObj Other { get; }

    /// <summary>A resting object with no movement manager, 6 m west of the walker: dormant once the scene has seen it idle.</summary>
    public PhysicsObj Resting { get; }

    /// <summary>A remote creature with retail's movement manager (and interpreter), running a move-to towards
    /// <see cref="Other"/>: the motion members of the object, and the static MovementEvent entry, are called on it.</summary>
    public PhysicsObj Creature { get; }

    // The creature's body: two parts playing a small motion table from bytes (Ready, walk, run, side-step, turn cycles and a
    // link; each animation 4 frames of 1 mm root motion at 30 fps).
    private static AnimatedPartArray AnimatedParts()
    {
        const uint NonCombat = 0x8000003Du, Ready = 0x41000003u, Walk = 0x45000005u, Run = 0x44000007u, Side = 0x6500000Fu,
            Turn = 0x6500000Du;
        MotionTable table = MotionTable.UnPack(new MotionTableBytes { DefaultStyle = NonCombat }
            .StyleDefault(NonCombat, Ready)
            .Cycle(NonCombat, Ready, MotionDataSpec.One(0x03000001, 0, -1, 30f))
            .Cycle(NonCombat, Walk, MotionDataSpec.One(0x03000002, 0, -1, 30f, velocity: new Vector3(0f, 3.12f, 0f)))
            .Cycle(NonCombat, Run, MotionDataSpec.One(0x03000002, 0, -1, 30f, velocity: new Vector3(0f, 4f, 0f)))
            .Modifier(0, Side, new MotionDataSpec(System.Array.Empty<(uint, int, int, float)>(), Velocity: new Vector3(1.25f, 0f, 0f)))
            .Modifier(0, Turn, new MotionDataSpec(System.Array.Empty<(uint, int, int, float)>(), Omega: new Vector3(0f, 0f, -1.5f)))
            .Link(NonCombat, Ready, Walk, MotionDataSpec.One(0x03000003, 0, -1, 30f))
            .ToArray());
        var lib = new AnimationLibrary();
        foreach (uint id in new uint[] { 0x03000001, 0x03000002, 0x03000003 })
        {
            var b = new AnimationBytes(id, 2);
            for (int i = 0; i < 4; i++)
            {
                b.Frame(new Vector3(0f, 0.001f, 0f), Quaternion.Identity);
            }

            lib.Add(AnimClip.UnPack(b.ToArray()));
        }

        var setup = new SetupPhysics(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) }, System.ReadOnlySpan<CylSphere>.Empty,
            0.5f, 1.8f, 0.6f, 0.6f);
        return new AnimatedPartArray(setup, 2, table, lib);
    }

    /// <summary>A position on the ground (z = 10 m) of landblock 0x8080 at (x, y), in the outdoor cell that contains it.</summary>
    public static Position At(float x, float y)
    {
        var p = new Position(SweepScene.CellId(SweepScene.BlockX, SweepScene.BlockY, 0, 0), new Vector3(x, y, 10f));
        p.AdjustToOutside();
        return p;
    }

    /// <summary>Ticks <paramref name="n"/> times by <see cref="Dt"/>.</summary>
    public void Tick(int n)
    {
        for (int i = 0; i < n; i++)
        {
            World.Tick(World.CurrentTime + Dt);
        }
    }
}
