using System;
using System.Globalization;
using System.IO;
using System.Numerics;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;

namespace AcDream.Samples.FirstScene;

/// <summary>
/// A client's first scene (docs/getting-started.md walks through it): the terrain around Holtburg, a player built from the human
/// Setup walking, turning, running, jumping and walking into a hut, a remote creature fed position reports every 0.2 s, and a
/// fade; each simulated second it prints what a developer wants to see. Options: <c>--seconds N</c> (default 60; the script
/// takes 24), <c>--fps N</c> (default 60), <c>--terrain DIR</c> (the ac-terrain folder; else ACDREAM_TERRAIN_DIR, else
/// ../shared/data/ac-terrain above the program or the current folder), <c>--synthetic</c> (skip the real terrain).
/// Exits 1 when the scene did not do what it should (CI smoke-runs it).
/// </summary>
public static class Program
{
    private const double ScriptSeconds = 24.0;

    /// <summary>Runs the scene.</summary>
    public static int Main(string[] args)
    {
        ArgumentNullException.ThrowIfNull(args);
        double seconds = 60.0;
        int fps = 60;
        string? terrainDir = null;
        bool synthetic = false;
        for (int i = 0; i < args.Length; i++)
        {
            switch (args[i])
            {
                case "--seconds" when i + 1 < args.Length:
                    seconds = double.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
                case "--fps" when i + 1 < args.Length:
                    fps = int.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
                case "--terrain" when i + 1 < args.Length:
                    terrainDir = args[++i];
                    break;
                case "--synthetic":
                    synthetic = true;
                    break;
                default:
                    Console.Error.WriteLine($"unknown argument '{args[i]}'; options: --seconds N, --fps N, --terrain DIR, --synthetic");
                    return 2;
            }
        }

        // 1. Terrain: the landblocks the client has loaded (real data when found).
        terrainDir ??= synthetic ? null : FindTerrain();
        TerrainWorld terrain = terrainDir is not null ? Scene.LoadHoltburg(terrainDir) : Scene.Synthetic();
        Console.WriteLine(terrainDir is not null ? $"terrain: real Holtburg 3x3 from {terrainDir}" : "terrain: synthetic 3x3 slopes (no ac-terrain folder found)");
        Scene.AddHut(terrain);

        // 2. The world over that terrain: the retail collision sweep.
        var world = new PhysicsWorld(terrain);

        // 3. The player: a part array from the human Setup and the character's skills (its weenie), placed on the ground,
        //    made the world's player (which gives it retail's movement manager and motion interpreter). SetupIssues names
        //    anything that would keep it from walking.
        PhysicsObj player = world.CreateObject(0x50000001);
        // The motion table turns motion commands into root motion: without one the player would not walk (SetupIssues says
        // NoMotionTable). A client with real motion tables plugs its own in here.
        var body = new SimplePartArray(SetupPhysics.Human) { MotionTable = new RetailSpeedMotionTable() };
        player.PartArray = body;
        player.Weenie = PlayerControl.Character();
        if (!player.EnterWorld(Scene.OnGround(terrain, 60f, 40f, heading: 0f)))
        {
            Console.Error.WriteLine("the player could not enter the world");
            return 1;
        }

        world.Player = player;
        if (player.SetupIssues != ObjectSetupIssues.None)
        {
            Console.Error.WriteLine($"player setup issues: {player.SetupIssues}");
            return 1;
        }

        var controls = new PlayerControl(player, body);
        var remote = new RemoteCreature(world, terrain);
        var check = new SceneCheck();
        bool faded = false;
        Console.WriteLine("   t  player cell     x       y       z     contact  speed  heading  command                         | creature  error  transl.");
        int frames = (int)Math.Round(seconds * fps);
        string command = "";
        for (int i = 1; i <= frames; i++)
        {
            double now = (double)i / fps;

            // 4. Each frame: network input first (remote objects), then the player's controls, then the world tick.
            remote.Deliver(now);
            command = controls.Drive(now);
            if (!faded && now >= 20.0 && remote.Obj is not null)
            {
                faded = true;
                remote.Obj.SetTranslucency(1f, 2.0);   // fade the creature out over 2 s
            }

            world.Tick(now);
            check.Observe(terrain, player, now);
            if (i % fps == 0)
            {
                Print(player, remote, now, command);
            }
        }

        return seconds >= ScriptSeconds ? check.Report(remote, seconds) : 0;
    }

    private static void Print(PhysicsObj player, RemoteCreature remote, double now, string command)
    {
        Vector3 o = player.Position.Frame.Origin;
        Vector3 v = player.CachedVelocity;
        float speed = MathF.Sqrt(v.X * v.X + v.Y * v.Y);
        TransientState ts = player.TransientState;
        string contact = (ts & TransientState.OnWalkable) != 0 ? "walkable" : (ts & TransientState.Contact) != 0 ? "contact" : "airborne";
        string creature = remote.Obj is null ? "(none yet)" : string.Create(CultureInfo.InvariantCulture,
            $"{remote.ErrorAt(now),5:F2} m  {remote.Obj.Translucency,4:F2}");
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"{now,4:F0}  0x{player.Position.ObjCellId:X8} {o.X,7:F2} {o.Y,7:F2} {o.Z,7:F2}  {contact,-8} {speed,5:F2}  {player.Position.Frame.Heading,6:F1}  {command,-31} | {creature}"));
    }

    // The ac-terrain folder: ACDREAM_TERRAIN_DIR, else ../shared/data/ac-terrain beside a folder above the program or the
    // current directory; null when none is found.
    private static string? FindTerrain()
    {
        string? env = Environment.GetEnvironmentVariable("ACDREAM_TERRAIN_DIR");
        if (!string.IsNullOrEmpty(env))
        {
            return File.Exists(Path.Combine(env, "landblock_heights_sample.csv")) ? Path.GetFullPath(env) : null;
        }

        foreach (string start in new[] { AppContext.BaseDirectory, Directory.GetCurrentDirectory() })
        {
            for (string? d = Path.GetFullPath(start); d is not null; d = Path.GetDirectoryName(d.TrimEnd(Path.DirectorySeparatorChar)))
            {
                string candidate = Path.GetFullPath(Path.Combine(d, "..", "shared", "data", "ac-terrain"));
                if (File.Exists(Path.Combine(candidate, "landblock_heights_sample.csv")))
                {
                    return candidate;
                }
            }
        }

        return null;
    }
}
