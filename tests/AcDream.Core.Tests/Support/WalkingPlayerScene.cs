using System.Numerics;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Tests.Support;

/// <summary>A player from the human Setup on flat landblocks at 0 m (0xA9B4 and its northern neighbour 0xA9B5), with retail's
/// speed table: WalkForward moves it 3.12 m/s north (SpeedOnlyMotionPlayer, get_state_velocity's walk speed).</summary>
internal sealed class WalkingPlayerScene
{
    /// <summary>Retail's walk speed, m/s, as the float the motion table carries.</summary>
    public const float WalkSpeed = 3.12f;

    public WalkingPlayerScene(Vector3 start, float heading = 0f, PlayerWeenie? weenie = null)
    {
        var table = new float[LandHeightTable.Count];
        for (int i = 0; i < table.Length; i++)
        {
            table[i] = 2f * i;
        }

        Terrain = new TerrainWorld(new LandHeightTable(table));
        Terrain.AddLandBlock(0xA9B4FFFF, new byte[81], new ushort[81]);
        Terrain.AddLandBlock(0xA9B5FFFF, new byte[81], new ushort[81]);
        World = new PhysicsWorld(Terrain);
        Player = World.CreateObject(0x50000001);
        Player.PartArray = new SimplePartArray(SetupPhysics.Human) { MotionPlayer = new SpeedOnlyMotionPlayer() };
        Player.Weenie = weenie ?? new PlayerWeenie { RunSkill = 200, JumpSkill = 100, Strength = 100 };
        var p = new Position(LandDefs.OutdoorCellId(0xA9B4FFFF, start.X, start.Y), Frame.FromHeading(start, heading));
        if (!Player.EnterWorld(p))
        {
            throw new System.InvalidOperationException("the player did not enter the world");
        }

        World.Player = Player;
        Movement = MovementManager.Of(Player);
    }

    public TerrainWorld Terrain { get; }

    public PhysicsWorld World { get; }

    public PhysicsObj Player { get; }

    public MovementManager Movement { get; }

    /// <summary>W down.</summary>
    public void Walk() => Movement.DoMotion(MotionCommand.WalkForward, new MovementParameters());

    /// <summary>The y of a position in the frame of landblock 0xA9B4 (row 0xB5 adds 192 m).</summary>
    public static double GlobalY(in Position p) => (((p.ObjCellId >> 16) & 0xFF) - 0xB4) * 192.0 + p.Frame.Origin.Y;
}
