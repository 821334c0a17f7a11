using System;
using System.Numerics;
using AcDream.Core.Physics.Math;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;

namespace AcDream.Samples.FirstScene;

/// <summary>
/// A creature the client does not control: a stand-in server walks it around a circle and sends its position every 0.2 s,
/// each arriving 0.1 s late; the client applies each report with <see cref="PhysicsObj.HandleReceivedPosition"/> and keeps
/// the creature's root motion at the motion the server says it has (walking), so that it moves smoothly between reports.
/// </summary>
internal sealed class RemoteCreature
{
    private const double Period = 0.2;
    private const double Latency = 0.1;
    private const float Radius = 8f;
    private static readonly Vector2 Centre = new(40f, 90f);
    private readonly PhysicsWorld _world;
    private readonly TerrainWorld _terrain;
    private SimplePartArray? _body;
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
                // What a network layer sets on a new remote object before its first update: a part array from its Setup, a
                // movement manager (GetMinterp creates it), then the first position through EnterWorld.
                Obj = _world.CreateObject(0x80000010);
                _body = new SimplePartArray(SetupPhysics.Human);
                Obj.PartArray = _body;
                Obj.GetMinterp();
                if (!Obj.EnterWorld(report))
                {
                    throw new InvalidOperationException("The remote creature could not enter the world.");
                }
            }

            // The motion the server reports (walk forward, turning left around the circle), then the position.
            _body!.SequenceVelocity = new Vector3(0f, PlayerControl.WalkSpeed, 0f);
            _body.SequenceOmega = new Vector3(0f, 0f, PlayerControl.WalkSpeed / Radius);
            Obj.HandleReceivedPosition(report, ++_positionStamp, teleportTimestamp: 0, hasContact: true);
            Reports++;
            _nextSend += Period;
        }
    }

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
        double a = t * PlayerControl.WalkSpeed / Radius;
        float x = Centre.X + Radius * (float)Math.Cos(a);
        float y = Centre.Y + Radius * (float)Math.Sin(a);
        // Moving counter-clockwise, the path's direction is (-sin a, cos a): heading = atan2(dx, dy) clockwise from north.
        float heading = (float)((Math.Atan2(-Math.Sin(a), Math.Cos(a)) * 180.0 / Math.PI + 360.0) % 360.0);
        return Scene.OnGround(_terrain, x, y, heading);
    }
}
