using System;
using System.IO;
using System.Numerics;
using AcDream.Core.Physics.Math;
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

        // Walk: 3 m/s for the simulated time of the first 60 frames. The world steps its objects when at least 1/30 s has
        // passed since its last step (CPhysics::UseTime), so the last step before t = 1 s lies within 1/30 s of it (a summed
        // frame time can fall an ulp short of the gate): 2.9 to 3.0 m, y in 100 + [2.9, 3.0].
        // Jump: the first step after SetLocalVelocity still starts on walkable ground (no gravity): 4 * 1/30 = 0.133 m (0.2 m
        // for a 1/20 s step); then free flight to 4^2 / (2 * 9.8) = 0.816 m above that, sampled at step times (<= 0.003 m
        // short): top in [0.93, 1.02]. It jumps standing (root motion stopped), so y stays; 1 s after the jump (flight 0.82 s)
        // it stands on the ground again.
        Assert.InRange(player.Position.Frame.Origin.Y, 102.899f, 103.001f);
        Assert.InRange(top, 0.93f, 1.02f);
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
        var body = new SimplePartArray(SetupPhysics.Human);     // spheres, sizes and step heights of the human Setup
        player.PartArray = body;
        player.EnterWorld(new Position(0xA9B40025, new Vector3(100f, 100f, 0f)));
        world.Player = player;                                  // the player gets its movement manager
        System.Diagnostics.Debug.Assert(player.SetupIssues == ObjectSetupIssues.None);

        double now = 0;
        body.SequenceVelocity = new Vector3(0f, 3f, 0f);        // walk: root motion, 3 m/s forward (+Y local)
        for (int f = 0; f < 60; f++) world.Tick(now += 1.0 / 60);                 // 1 s at 60 fps: about 3 m north
        body.SequenceVelocity = Vector3.Zero;                   // stop
        player.SetLocalVelocity(new Vector3(0f, 0f, 4f));       // jump: 4 m/s up; gravity brings it back down
        float top = 0f;
        for (int f = 0; f < 60; f++) { world.Tick(now += 1.0 / 60); top = MathF.Max(top, player.Position.Frame.Origin.Z); }
        // top ≈ 1 m: the first step (1/30 or 1/20 s; still on the ground, so no gravity) rises 0.13-0.2 m, then 4² / (2 · 9.8) = 0.82 m
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
