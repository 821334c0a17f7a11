using System;
using System.Globalization;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// A remote creature replayed from a known path: it walks 4 m/s along a polyline (north, east, a 1 s stop, south-west,
/// north) on flat terrain through the retail sweep, 20 m from the player. The server reports its position and motion every
/// 0.25 s and each report arrives 0.1 s later. Reference: the true path at the client time of each frame (so the
/// network's 0.1 s delay is part of every choice's error). Error: mean distance after the first second, m; the note gives
/// the largest.
/// </summary>
internal sealed class RemoteCreatureScene : WorldSim
{
    public const string Name = "remote creature, replayed path";
    public const string Reference = "true path at client time";
    private const double Period = 0.25;
    private const double Latency = 0.1;
    private const float Speed = 4f;
    private const float Ground = 20f;
    private static readonly Vector2[] Waypoints = [new(60f, 60f), new(60f, 72f), new(72f, 72f), new(72f, 72f), new(63.5f, 63.5f), new(63.5f, 75.5f)];
    private static readonly double[] Durations = [3.0, 3.0, 1.0, 3.0, 3.0];
    private readonly PhysicsObj _creature;
    private double _nextSend = Period;
    private ushort _stamp;
    private double _sum;
    private int _n;
    private double _max;

    public RemoteCreatureScene(PhysicsProfile profile, Pacing pacing, double seconds)
        : base(TerrainKit.World(Terrain(), profile), pacing, seconds)
    {
        PhysicsObj player = World.CreateObject(1);
        player.PartArray = new SimplePartArray(1, 1) { Radius = 0.5f };
        player.EnterWorld(new Position(TerrainKit.CellId(3, 3), new Vector3(80f, 80f, Ground)));
        World.Player = player;
        Truth(0.0, out Vector2 p0, out float h0, out _);
        _creature = TerrainKit.Walker(World, new Position(TerrainKit.CellId(2, 2), Frame.FromHeading(new Vector3(p0.X, p0.Y, Ground), h0)), 2);
        TerrainKit.Walk(_creature, new Vector3(0f, Speed, 0f));
    }

    public override double Error => _n == 0 ? 0.0 : _sum / _n;

    public override string Note => string.Create(CultureInfo.InvariantCulture, $"max {_max:F3} m");

    public PhysicsObj Creature => _creature;

    public override void Advance(int i)
    {
        double now = TimeOf(i);
        while (_nextSend + Latency <= now)
        {
            Truth(_nextSend, out Vector2 p, out float heading, out bool moving);
            TerrainKit.Walk(_creature, new Vector3(0f, moving ? Speed : 0f, 0f));
            World.SetCurrentTime(_nextSend + Latency);
            var report = new Position(TerrainKit.CellId((int)(p.X / 24f), (int)(p.Y / 24f)), Frame.FromHeading(new Vector3(p.X, p.Y, Ground), heading));
            _creature.HandleReceivedPosition(report, ++_stamp, 0, true);
            _nextSend += Period;
        }

        World.Tick(now);
    }

    public override void Sample(int i)
    {
        double now = TimeOf(i);
        if (now < 1.0)
        {
            return;
        }

        Truth(now, out Vector2 p, out _, out _);
        Vector3 o = new Position(TerrainKit.CellId(0, 0), Vector3.Zero).GetOffset(_creature.Position);
        double d = Math.Sqrt(((double)o.X - p.X) * ((double)o.X - p.X) + ((double)o.Y - p.Y) * ((double)o.Y - p.Y));
        _sum += d;
        _n++;
        _max = Math.Max(_max, d);
    }

    /// <summary>The true position, heading (degrees clockwise from north) and motion at time <paramref name="t"/>.</summary>
    public static void Truth(double t, out Vector2 p, out float heading, out bool moving)
    {
        double s = t;
        for (int k = 0; k < Durations.Length; k++)
        {
            Vector2 a = Waypoints[k], b = Waypoints[k + 1];
            Vector2 d = b - a;
            moving = d.LengthSquared() > 0f;
            heading = moving ? (float)(Math.Atan2(d.X, d.Y) * 180.0 / Math.PI + 360.0) % 360f : Heading(k);
            if (s <= Durations[k] || k == Durations.Length - 1)
            {
                double f = Math.Min(1.0, s / Durations[k]);
                p = a + d * (float)f;
                moving &= f < 1.0;
                return;
            }

            s -= Durations[k];
        }

        throw new InvalidOperationException("unreachable");
    }

    private static float Heading(int k)
    {
        while (k > 0 && Waypoints[k] == Waypoints[k + 1])
        {
            k--;
        }

        Vector2 d = Waypoints[k + 1] - Waypoints[k];
        return (float)(Math.Atan2(d.X, d.Y) * 180.0 / Math.PI + 360.0) % 360f;
    }

    private static TerrainWorld Terrain()
    {
        TerrainWorld t = TerrainKit.Metres();
        TerrainKit.AddBlock(t, (_, _) => (int)Ground);
        return t;
    }
}
