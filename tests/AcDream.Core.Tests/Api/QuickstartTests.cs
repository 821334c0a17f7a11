using System;
using System.IO;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Input;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using Xunit;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// The quickstart of README.md and of the package README (src/AcDream.Core/PACKAGE.md): the same code, compiled and run here,
/// and a check that both READMEs still show exactly this code.
/// </summary>
public sealed class QuickstartTests
{
    [Fact]
    public void Quickstart_WalksThreeMetresNorth_ThenJumps()
    {
        var (player, top) = Quickstart();

        // Walk: WalkForward plays at retail's 3.12 m/s (SpeedOnlyMotionPlayer; get_state_velocity's walk speed) for the
        // simulated time of the first 60 frames. The world steps its objects when at least 1/30 s has passed since its last
        // step (CPhysics::UseTime), so the last step before t = 1 s lies within 1/30 s of it (a summed frame time can fall an
        // ulp short of the gate): 29/30 to 1 s of walking, y in 100 + 3.12 * [0.9667, 1] = [103.016, 103.12].
        // Jump: jump skill 100 at extent 0.5 gives h = (100 / 1400 * 22.2 + 0.05) * 0.5 = 0.8179 m (GetJumpHeight) and
        // v_z = sqrt(19.6 h) = 4.0037 m/s (InqJumpVelocity); the extent is the power bar's level when the key comes up, the
        // seconds held on the world's clock (30 frames of 1/60 s = 0.5 s; ClientCombatSystem::GetPowerBarLevel). Jump clears ON_WALKABLE at once (CMotionInterp::jump), so the
        // next step already flies from z = 0 with that launch speed: the apex is v_z^2 / (2 * 9.8) = 0.8179 m, sampled at
        // 1/30 s step times, so at most 9.8 * (1/60)^2 / 2 = 0.0014 m short: top in [0.8165, 0.8180]. It jumps standing
        // (the walk stopped), so y stays; 1 s after the jump (flight 0.82 s) it stands on the ground again.
        Assert.InRange(player.Position.Frame.Origin.Y, 103.015f, 103.121f);
        Assert.InRange(top, 0.8165f, 0.8180f);
        Assert.Equal(0f, player.Position.Frame.Origin.Z, 5);   // the landing's contact-plane placement leaves float rounding
        Assert.Equal(ObjectSetupIssues.None, player.SetupIssues);
    }

    [Fact]
    public void ReadmeAndPackageReadme_ShowThisCode()
    {
        string root = TerrainDataDir.RepoRoot() ?? throw new InvalidOperationException("repository root not found");
        string[] mine = Region(File.ReadAllLines(Path.Combine(root, "tests", "AcDream.Core.Tests", "Api", "QuickstartTests.cs")));
        Assert.Equal(mine, Block(File.ReadAllLines(Path.Combine(root, "README.md"))));
        Assert.Equal(mine, Block(File.ReadAllLines(Path.Combine(root, "src", "AcDream.Core", "PACKAGE.md"))));
    }

    private static (PhysicsObj Player, float Top) Quickstart()
    {
        // quickstart-begin
        // Terrain: the client's height table (Region) and landblocks (here one flat landblock at 0 m).
        var table = new float[LandHeightTable.Count];
        for (int i = 0; i < table.Length; i++) table[i] = 2f * i;
        var terrain = new TerrainWorld(new LandHeightTable(table));
        terrain.AddLandBlock(0xA9B4FFFF, new byte[81], new ushort[81]);

        var world = new PhysicsWorld(terrain);                  // over terrain: the retail collision sweep
        PhysicsObj player = world.CreateObject(0x50000001);
        var body = new SimplePartArray(SetupPhysics.Human) { MotionPlayer = new SpeedOnlyMotionPlayer() };
        player.PartArray = body;                                // the human Setup's shape; retail's walk/run/turn speeds
        player.Weenie = new PlayerWeenie { RunSkill = 200, JumpSkill = 100, Strength = 100 };
        var spawn = new Vector3(100f, 100f, 0f);                // landblock-local metres; its outdoor cell is 0xA9B40025
        player.EnterWorld(new Position(LandDefs.OutdoorCellId(0xA9B4FFFF, spawn.X, spawn.Y), spawn));
        world.Player = player;                                  // the player gets retail's movement manager
        System.Diagnostics.Debug.Assert(player.SetupIssues == ObjectSetupIssues.None);
        var keys = new PlayerInput(player);                     // the player's keys, as retail's command interpreter sends them

        double now = 0;
        keys.KeyDown(MovementKeys.Forward);                                 // W down: walk, 3.12 m/s forward
        for (int f = 0; f < 60; f++) world.Tick(now += 1.0 / 60);           // 1 s at 60 fps: about 3.1 m north
        keys.KeyUp(MovementKeys.Forward);                                   // W up: stop
        keys.KeyDown(MovementKeys.Jump);                                    // jump key down: the power bar fills ...
        for (int f = 0; f < 30; f++) world.Tick(now += 1.0 / 60);           // ... for 0.5 s ...
        keys.KeyUp(MovementKeys.Jump);                                      // ... and up: a 0.82 m jump (4.0 m/s up)
        float top = 0f;
        for (int f = 0; f < 60; f++) { world.Tick(now += 1.0 / 60); top = MathF.Max(top, player.Position.Frame.Origin.Z); }
        // quickstart-end
        return (player, top);
    }

    // The lines between the quickstart markers, trimmed.
    private static string[] Region(string[] lines)
    {
        int a = Array.FindIndex(lines, l => l.Trim() == "// quickstart-begin");
        int b = Array.FindIndex(lines, l => l.Trim() == "// quickstart-end");
        return Trim(lines[(a + 1)..b]);
    }

    // A README's first C# block, without its using lines, trimmed.
    private static string[] Block(string[] lines)
    {
        int a = Array.FindIndex(lines, l => l.Trim() == "```csharp");
        int b = Array.FindIndex(lines, a + 1, l => l.Trim() == "```");
        return Trim(Array.FindAll(lines[(a + 1)..b], l => !l.StartsWith("using ", StringComparison.Ordinal)));
    }

    private static string[] Trim(string[] lines) => Array.FindAll(Array.ConvertAll(lines, l => l.Trim()), l => l.Length > 0);
}
