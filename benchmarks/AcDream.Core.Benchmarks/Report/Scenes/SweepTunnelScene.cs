using System;
using System.Globalization;
using System.Numerics;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// Sixteen balls (0.5 m spheres) thrown east at 25-50 m/s from 12-58 m up at a ridge (10 m plains either side of a 60 m
/// crest at x = 96, faces N.z = 0.43) through the retail sweep, 3 s; the highest skim the crest. Reference: the terrain
/// itself. Error: the largest penetration of a sphere below the terrain surface (terrain height under the origin minus the
/// sphere's lowest point), m; the note counts tunnelling balls: found more than a radius below the surface after some
/// frame, or crossing the crest line x = 96 lower than 59.5 m (half a metre under the crest, linear between frames).
/// </summary>
internal sealed class SweepTunnelScene : WorldSim
{
    public const string Name = "balls at a ridge (sweep)";
    public const string Reference = "terrain surface";
    private readonly TerrainWorld _terrain;
    private readonly PhysicsObj[] _balls = new PhysicsObj[16];
    private readonly bool[] _tunnelledBall = new bool[16];
    private readonly Vector3[] _previous = new Vector3[16];
    private double _maxPenetration;

    public SweepTunnelScene(PhysicsProfile profile, Pacing pacing, double seconds)
        : this(Terrain(), profile, pacing, seconds)
    {
    }

    private SweepTunnelScene(TerrainWorld terrain, PhysicsProfile profile, Pacing pacing, double seconds)
        : base(TerrainKit.World(terrain, profile), pacing, seconds)
    {
        _terrain = terrain;
        for (int i = 0; i < _balls.Length; i++)
        {
            float z = 12f + 46f * (i % 4) / 3f;
            float speed = 25f + 25f * (i / 4) / 3f;
            PhysicsObj b = World.CreateObject((uint)(i + 1));
            b.PartArray = new SimplePartArray(1, 1) { Radius = 0.5f };
            var parts = (SimplePartArray)b.PartArray;
            parts.SetSpheres(new[] { new Sphere(new Vector3(0f, 0f, 0.5f), 0.5f) });
            float y = 30f + 5f * i;
            if (!b.EnterWorld(new Position(TerrainKit.CellId(2, (int)(y / 24f)), new Vector3(60f, y, z))))
            {
                throw new InvalidOperationException("ball could not enter the world");
            }

            b.SetVelocity(new Vector3(speed, 0f, 0f));
            _balls[i] = b;
            _previous[i] = b.Position.Frame.Origin;
        }
    }

    public override double Error => _maxPenetration;

    public override string Note
    {
        get
        {
            int n = 0;
            foreach (bool t in _tunnelledBall)
            {
                n += t ? 1 : 0;
            }

            return string.Create(CultureInfo.InvariantCulture, $"tunnelled {n}/16");
        }
    }

    public override void Sample(int i)
    {
        for (int k = 0; k < _balls.Length; k++)
        {
            PhysicsObj b = _balls[k];
            float ground = TerrainKit.Ground(_terrain, b.Position);
            if (float.IsNaN(ground))
            {
                continue;
            }

            double pen = ground - b.Position.Frame.Origin.Z;
            _maxPenetration = Math.Max(_maxPenetration, pen);
            _tunnelledBall[k] |= pen > 0.5;
            Vector3 o = b.Position.Frame.Origin;
            Vector3 prev = _previous[k];
            if (prev.X < 96f && o.X >= 96f)
            {
                double a = (96.0 - prev.X) / (o.X - prev.X);
                _tunnelledBall[k] |= prev.Z + a * (o.Z - prev.Z) < 59.5;
            }

            _previous[k] = o;
        }
    }

    private static TerrainWorld Terrain()
    {
        TerrainWorld t = TerrainKit.Metres();
        TerrainKit.AddBlock(t, (vx, _) => vx == 4 ? 60 : 10);
        return t;
    }
}
