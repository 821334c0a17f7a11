using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using AcDream.Core.Physics.Data;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// Eight walkers, far enough apart never to meet, on the real Holtburg landblocks (0xA9B4 and neighbours) walking 3.12 m/s
/// in circles (0.5 rad/s) for 20 s
/// through the retail sweep. Reference: the same scene stepped every 1/600 s.
/// </summary>
internal sealed class HoltburgWalkScene : StepSceneSim
{
    public const string Name = "walkers on Holtburg (real terrain)";

    public HoltburgWalkScene((LandHeightTable Table, System.Collections.Generic.List<LandBlockEntry> Blocks) data, PhysicsProfile profile, Pacing? pacing, double seconds)
        : this(TerrainKit.HoltburgWorld(data), profile, pacing, seconds)
    {
    }

    private HoltburgWalkScene(TerrainWorld terrain, PhysicsProfile profile, Pacing? pacing, double seconds)
        : base(TerrainKit.World(terrain, profile), pacing, seconds)
    {
        Basis = new Position(0xA9B40001u, Vector3.Zero);
        var walkers = new PhysicsObj[8];
        for (int i = 0; i < walkers.Length; i++)
        {
            // 30 m apart (70 m between rows): each walks a circle of radius 6.24 m, so no two ever meet (object collisions would
            // make the comparison with the fine-step run chaotic).
            float x = 20f + 30f * (i % 4), y = 40f + 70f * (i / 4);
            Position p = SyntheticTerrain.OnGround(terrain, Holtburg.CentreCell(x, y), x, y, 45f * i);
            walkers[i] = TerrainKit.Walker(World, p, (uint)(i + 1));
            TerrainKit.Walk(walkers[i], new Vector3(0f, 3.12f, 0f), 0.5f);
        }

        Track(walkers);
    }
}
