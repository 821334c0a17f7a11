using System;
using System.Collections.Generic;
using System.Globalization;
using System.Numerics;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.Collision.Bsp;
using AcDream.Core.Physics.Collision.Primitives;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// Sixteen missiles (0.1 m spheres, MISSILE, no gravity) fired east at 10, 20, 35 and 50 m/s at a 0.1 m thick wall
/// (x 110..110.1, a building BSP on flat ground) from x = 100, through the retail sweep over terrain and buildings, 1.5 s.
/// Reference: the wall itself. Error: the deepest penetration of a sphere into the wall (sphere's east point past the wall's
/// west face, capped at wall + diameter = 0.3 m when it went through), m; the note counts tunnelled missiles (centre ever east of the wall's east face).
/// </summary>
internal sealed class ThinWallScene : WorldSim
{
    public const string Name = "missiles at a 0.1 m wall (BSP)";
    public const string Reference = "wall faces";
    private const float R = 0.1f;
    private const float Face = 110f;
    private const float Thickness = 0.1f;
    private const float Ground = 20f;
    private readonly PhysicsObj[] _missiles = new PhysicsObj[16];
    private readonly bool[] _tunnelled = new bool[16];
    private double _maxPenetration;

    public ThinWallScene(PhysicsProfile profile, Pacing pacing, double seconds)
        : base(new PhysicsWorld(0.0, profile) { Sweep = new RetailSweep(Cells()) }, pacing, seconds)
    {
        PhysicsState missile = ((PhysicsState)PhysicsGlobals.DefaultState | PhysicsState.Missile) & ~PhysicsState.Gravity;
        float[] speeds = [10f, 20f, 35f, 50f];
        for (int i = 0; i < _missiles.Length; i++)
        {
            var at = new Vector3(100f, 92f + i, Ground + 2f);
            PhysicsObj m = TerrainKit.Walker(World, new Position(TerrainKit.CellId((int)(at.X / 24f), (int)(at.Y / 24f)), at), (uint)(i + 1), missile, R);
            m.SetVelocity(new Vector3(speeds[i % 4], 0f, 0f));
            _missiles[i] = m;
        }
    }

    public override double Error => _maxPenetration;

    public override string Note
    {
        get
        {
            int n = 0;
            foreach (bool t in _tunnelled)
            {
                n += t ? 1 : 0;
            }

            return string.Create(CultureInfo.InvariantCulture, $"tunnelled {n}/16");
        }
    }

    public override void Sample(int i)
    {
        for (int k = 0; k < _missiles.Length; k++)
        {
            float cx = _missiles[k].Position.Frame.Origin.X;
            _maxPenetration = Math.Max(_maxPenetration, Math.Min(cx + R - Face, Thickness + 2 * R)); // capped: fully through
            _tunnelled[k] |= cx > Face + Thickness;
        }
    }

    // Flat ground at 20 m (block 0x8080) with a wall building x 110..110.1, y 90..110, z 20..25.
    private static WorldCells Cells()
    {
        TerrainWorld terrain = TerrainKit.Metres();
        TerrainKit.AddBlock(terrain, (_, _) => (int)Ground);
        var cells = new WorldCells(terrain);
        var min = new Vector3(Face, 90f, Ground);
        var max = new Vector3(Face + Thickness, 110f, Ground + 5f);
        float x0 = 0f, y0 = min.Y - 100f, z0 = 0f, x1 = Thickness, y1 = max.Y - 100f, z1 = 5f;
        var polys = new List<Polygon>
        {
            Quad(new(x1, y0, z0), new(x1, y1, z0), new(x1, y1, z1), new(x1, y0, z1), 0),
            Quad(new(x0, y0, z0), new(x0, y0, z1), new(x0, y1, z1), new(x0, y1, z0), 1),
            Quad(new(x0, y1, z0), new(x0, y1, z1), new(x1, y1, z1), new(x1, y1, z0), 2),
            Quad(new(x0, y0, z0), new(x1, y0, z0), new(x1, y0, z1), new(x0, y0, z1), 3),
            Quad(new(x0, y0, z1), new(x1, y0, z1), new(x1, y1, z1), new(x0, y1, z1), 4),
            Quad(new(x0, y0, z0), new(x0, y1, z0), new(x1, y1, z0), new(x1, y0, z0), 5),
        };
        var origin = new Vector3(Face, 100f, Ground);
        BspTree bsp = BspBuilder.Build(polys.ToArray());
        var part = new PhysicsPart(new GfxObjPhysics(bsp), new Position(TerrainKit.CellId(4, 4), new Frame(origin, Quaternion.Identity)), Vector3.One);
        var building = new BuildingObj(part, []);
        for (int cx = 4; cx <= 4; cx++)
        {
            for (int cy = 3; cy <= 4; cy++)
            {
                LandCell? lc = terrain.GetLandCell(TerrainKit.CellId(cx, cy));
                if (lc is not null)
                {
                    lc.Building = building;
                }
            }
        }

        return cells;
    }

    private static Polygon Quad(Vector3 a, Vector3 b, Vector3 c, Vector3 d, short id) =>
        new(id, new[] { a, b, c, d }, new ushort[] { 0, 1, 2, 3 });
}
