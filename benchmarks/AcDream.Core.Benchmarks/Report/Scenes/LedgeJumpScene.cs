using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// A jump over a ledge: a walker (EDGE_SLIDE off) 2 m before the edge of a 60 m plateau jumps at (0, 4, 5) m/s local while
/// running 4 m/s, clears the edge, falls down the 50 m cliff (not walkable) to the 10 m plain and runs on; 6 s. Reference:
/// the same scene stepped every 1/600 s.
/// </summary>
internal sealed class LedgeJumpScene : StepSceneSim
{
    public const string Name = "jump over a ledge";

    public LedgeJumpScene(PhysicsProfile profile, Pacing? pacing, double seconds)
        : base(TerrainKit.World(Terrain(), profile), pacing, seconds)
    {
        Basis = new Position(TerrainKit.CellId(0, 0), Vector3.Zero);
        PhysicsState state = (PhysicsState)PhysicsGlobals.DefaultState & ~PhysicsState.EdgeSlide;
        var p = new Position(TerrainKit.CellId(3, 4), Frame.FromHeading(new Vector3(94f, 108f, 60f), 90f));
        PhysicsObj w = TerrainKit.Walker(World, p, 1, state);
        TerrainKit.Walk(w, new Vector3(0f, 4f, 0f));
        w.SetVelocity(new Vector3(4f, 0f, 5f));
        Track(w);
    }

    // Plateau at 60 m for vx <= 4 (x <= 96), a cliff to 10 m in one 24 m cell (N.z = 0.43), plain at 10 m from x = 120.
    private static TerrainWorld Terrain()
    {
        TerrainWorld t = TerrainKit.Metres();
        TerrainKit.AddBlock(t, (vx, _) => vx <= 4 ? 60 : 10);
        return t;
    }
}
