using System;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;

namespace AcDream.Samples.FirstScene;

/// <summary>
/// A creature the server moves onto the player: at <see cref="StartAt"/> it receives a MoveToObject (what a 0xF74C
/// MovementEvent of type 6 carries; a network layer hands that message to <see cref="PhysicsObj.HandleMovementEvent"/>,
/// which ends in the same call), and retail's <c>MoveToManager</c> turns it towards the player and runs or walks it there,
/// following the player while it moves. When the player has stopped and the creature has arrived, the player turns to face it (TurnToObject, type 8).
/// </summary>
internal sealed class Chaser
{
    /// <summary>Script time of the MoveToObject.</summary>
    public const double StartAt = 17.0;

    /// <summary>Earliest script time of the player's TurnToObject: after its keys are released at 20 s, once the creature has
    /// arrived.</summary>
    public const double TurnAfter = 20.5;

    private readonly PhysicsObj _player;
    private bool _started;
    private bool _turned;

    public Chaser(PhysicsWorld world, TerrainWorld terrain, PhysicsObj player)
    {
        ArgumentNullException.ThrowIfNull(world);
        _player = player;
        Obj = world.CreateObject(0x80000C01);
        Obj.PartArray = new SimplePartArray(SetupPhysics.Human) { MotionPlayer = new SpeedOnlyMotionPlayer() };
        Obj.Weenie = RemoteCreatureWeenie.Creature;
        if (!Obj.EnterWorld(Scene.OnGround(terrain, 125f, 60f, heading: 270f)))
        {
            throw new InvalidOperationException("the chaser could not enter the world");
        }
    }

    /// <summary>The creature.</summary>
    public PhysicsObj Obj { get; }

    /// <summary>True once the move-to has ended (it reached the player).</summary>
    public bool Arrived => _started && !Obj.IsMovingTo();

    /// <summary>Centre distance to the player, metres.</summary>
    public float Distance => _player.Position.Distance(Obj.Position);

    /// <summary>How far the player's heading is from facing the creature, degrees (0..180).</summary>
    public double PlayerFacingError
    {
        get
        {
            double want = _player.Position.HeadingTo(Obj.Position);
            double d = Math.Abs(want - _player.Position.Frame.Heading) % 360.0;
            return d > 180.0 ? 360.0 - d : d;
        }
    }

    /// <summary>Sends the scripted server commands due at <paramref name="now"/> (call after the player's keys, before the
    /// world tick: a key change is a player command, which cancels the player's own move-to or turn-to).</summary>
    public void Deliver(double now)
    {
        if (!_started && now >= StartAt)
        {
            _started = true;
            // Run when farther than 1 m (walk_run_threshhold), stop 0.6 m from the player's cylinder (the default
            // distance_to_object), give up beyond 100 m (fail distance).
            Obj.MoveToObject(_player.Id, new MovementParameters { WalkRunThreshold = 1f, FailDistance = 100f });
        }

        if (!_turned && now >= TurnAfter && Arrived)
        {
            _turned = true;
            _player.TurnToObject(Obj.Id, new MovementParameters());
        }
    }

    /// <summary>What the creature is doing, for the console.</summary>
    public string Status => !_started ? "waits" : Obj.IsMovingTo() ? $"moving to the player, {Distance,5:F2} m" : $"arrived, {Distance,5:F2} m";
}
