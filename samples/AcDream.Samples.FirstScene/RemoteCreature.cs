using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Samples.FirstScene;

/// <summary>
/// A creature the client does not control: a stand-in server walks it around a circle and sends its position every 0.2 s,
/// each arriving 0.1 s late. The client applies the server's MovementEvent (walk forward, turning left) once, when the
/// creature appears, with <see cref="MovementEvent.ApplyInterpretedMotion"/> — the motion interpreter then walks it between
/// reports — and each report with <see cref="PhysicsObj.HandleReceivedPosition"/>, whose interpolation corrects the drift.
/// </summary>
internal sealed class RemoteCreature
{
    private const double Period = 0.2;
    private const double Latency = 0.1;
    private const float Radius = 8f;
    private const float WalkSpeed = 3.12f;   // retail's walk speed at forward speed 1 (get_state_velocity)
    private static readonly Vector2 Centre = new(40f, 90f);
    private readonly PhysicsWorld _world;
    private readonly TerrainWorld _terrain;
    private double _nextSend;
    private ushort _positionStamp;

    public RemoteCreature(PhysicsWorld world, TerrainWorld terrain)
    {
        _world = world;
        _terrain = terrain;
    }

    /// <summary>The creature, once its first report has arrived.</summary>
    public PhysicsObj? Obj { get; private set; }

    /// <summary>Number of reports delivered.</summary>
    public int Reports { get; private set; }

    /// <summary>Delivers every report due by client time <paramref name="now"/> (call before the world's tick).</summary>
    public void Deliver(double now)
    {
        while (_nextSend + Latency <= now)
        {
            Position report = Truth(_nextSend);
            _world.SetCurrentTime(_nextSend + Latency);
            if (Obj is null)
            {
                // What a network layer sets on a new remote object before its first update: a part array from its Setup with a
                // motion table, its weenie (a creature: its motion arrives interpreted), then the first position through
                // EnterWorld, then the MovementEvent the server sends with it.
                Obj = _world.CreateObject(0x80000010);
                var body = new SimplePartArray(SetupPhysics.Human) { MotionPlayer = new SpeedOnlyMotionPlayer() };
                Obj.PartArray = body;
                Obj.Weenie = RemoteCreatureWeenie.Creature;
                if (!Obj.EnterWorld(report))
                {
                    throw new InvalidOperationException("The remote creature could not enter the world.");
                }

                MovementEvent.ApplyInterpretedMotion(Obj, WalkingTheCircle());
            }

            Obj.HandleReceivedPosition(report, ++_positionStamp, teleportTimestamp: 0, hasContact: true);
            Reports++;
            _nextSend += Period;
        }
    }

    /// <summary>The interpreted motion state the server sends for the walk around the circle (what a client decodes from the
    /// MovementEvent, <see cref="MovementEventDecoder"/>): walk forward at speed 1 (3.12 m/s) and turn left at the speed that
    /// closes the circle, ω = 3.12 / 8 rad/s over the humanoid table's 1.5 rad/s at speed 1 (an interpreted left turn is TurnRight at a
    /// negative speed).</summary>
    private static InterpretedMotionState WalkingTheCircle() => new()
    {
        ForwardCommand = MotionCommand.WalkForward,
        ForwardSpeed = 1f,
        TurnCommand = MotionCommand.TurnRight,
        TurnSpeed = -(float)(WalkSpeed / Radius / SpeedOnlyMotionPlayer.TurnAnimSpeed),
    };

    /// <summary>Distance, metres, from the creature to where the server has it at <paramref name="now"/>.</summary>
    public float ErrorAt(double now)
    {
        if (Obj is null)
        {
            return float.NaN;
        }

        Vector3 d = Truth(now).GetOffset(Obj.Position);
        return MathF.Sqrt(d.X * d.X + d.Y * d.Y);
    }

    /// <summary>The server's position of the creature at time <paramref name="t"/>: counter-clockwise around the circle at
    /// walking speed, on the ground, facing along its path.</summary>
    public Position Truth(double t)
    {
        double a = t * WalkSpeed / Radius;
        float x = Centre.X + Radius * (float)Math.Cos(a);
        float y = Centre.Y + Radius * (float)Math.Sin(a);
        // Moving counter-clockwise, the path's direction is (-sin a, cos a): heading = atan2(dx, dy) clockwise from north.
        float heading = (float)((Math.Atan2(-Math.Sin(a), Math.Cos(a)) * 180.0 / Math.PI + 360.0) % 360.0);
        return Scene.OnGround(_terrain, x, y, heading);
    }
}
