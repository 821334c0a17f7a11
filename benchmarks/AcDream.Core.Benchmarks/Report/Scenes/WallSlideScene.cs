using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// A slide along a wall: a walker on a 10 m plain runs 4 m/s heading 60° into a cliff that rises 50 m over one 24 m cell
/// (N.z = 0.43, not walkable) and slides north along its foot; 8 s. Reference: the same scene stepped every 1/600 s.
/// </summary>
internal sealed class WallSlideScene : StepSceneSim
{
    public const string Name = "slide along a wall";

    public WallSlideScene(PhysicsProfile profile, Pacing? pacing, double seconds)
        : base(TerrainKit.World(Terrain(), profile), pacing, seconds)
    {
        Basis = new Position(TerrainKit.CellId(0, 0), Vector3.Zero);
        var p = new Position(TerrainKit.CellId(3, 2), Frame.FromHeading(new Vector3(88f, 60f, 10f), 60f));
        PhysicsObj w = TerrainKit.Walker(World, p, 1);
        TerrainKit.Walk(w, new Vector3(0f, 4f, 0f));
        Track(w);
    }

    // Plain at 10 m for vx <= 4 (x <= 96), rising to 60 m at vx = 5 (x = 120) and beyond.
    private static TerrainWorld Terrain()
    {
        TerrainWorld t = TerrainKit.Metres();
        TerrainKit.AddBlock(t, (vx, _) => vx <= 4 ? 10 : 60);
        return t;
    }
}
