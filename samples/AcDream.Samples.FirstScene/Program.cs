using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Cells;
using AcDream.Core.Physics.WorldData;
using System.Globalization;
using System.IO;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Input;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;

namespace AcDream.Samples.FirstScene;

/// <summary>
/// A client's first scene (docs/getting-started.md walks through it): the terrain around Holtburg, a player built from the human
/// Setup walking, turning, running, jumping and walking into a hut, driven by its movement keys through
/// <see cref="PlayerInput"/>, a remote creature fed position reports every 0.2 s, a creature the server moves onto the player (MoveToObject) and the
/// player turning to face it (TurnToObject), and a fade. Each frame it ticks the world and
/// takes the pose to draw (<see cref="PhysicsObj.GetRenderPose"/> at <see cref="PhysicsWorld.RenderTime"/>); each simulated
/// second it prints that drawn pose and what a developer wants to see. Options: see <c>--help</c>. Exits 1 when the scene did
/// not do what it should (CI smoke-runs it).
/// </summary>
public static class Program
{
    private const string Usage = """
        AcDream.Samples.FirstScene: a player walks, runs, jumps and walks into a hut; a remote creature follows its reports.
        Options:
          --seconds N    simulated seconds (default 40: the scene's 24 s script, then the walk south out of the
                         landblock with the world following; longer runs stand still)
          --fps N        frames per second of the render loop (default 60)
          --terrain DIR  the ac-terrain folder (default: ACDREAM_TERRAIN_DIR, else ../shared/data/ac-terrain above the
                         program or the current folder)
          --synthetic    synthetic slopes instead of the real terrain
          --help         this text
        """;

    /// <summary>Runs the scene.</summary>
    public static int Main(string[] args)
    {
        ArgumentNullException.ThrowIfNull(args);
        double seconds = KeyScript.WalkOutSeconds;
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
                case "--help" or "-h":
                    Console.WriteLine(Usage);
                    return 0;
                default:
                    Console.Error.WriteLine($"unknown argument '{args[i]}'");
                    Console.Error.WriteLine(Usage);
                    return 2;
            }
        }

        // 1. Terrain: the landblocks the client has loaded (real data when found).
        terrainDir ??= synthetic ? null : FindTerrain();
        SampleData data = terrainDir is not null ? Scene.LoadHoltburg(terrainDir) : Scene.Synthetic();
        Console.WriteLine(terrainDir is not null ? $"terrain: real Holtburg 3x3 from {terrainDir}" : "terrain: synthetic 3x3 slopes (no ac-terrain folder found)");
        Scene.AddContents(data);

        // 2. The world, built from the client's data by the landscape that follows the player (docs/world.md): retail's grid of
        //    landblocks around the player's cell, of which the 3 x 3 around it are built into the world (terrain, then
        //    buildings, static objects and scenery, in retail's order). The world sweeps with the retail collision sweep over
        //    those cells; each WorldObject of a built block is what a renderer draws (model id, cell, frame, scale).
        var world = new PhysicsWorld(new WorldCells(new TerrainWorld(data.HeightTable)));
        var landscape = new Landscape(new WorldLoader(world, data));
        var start = new Position(Scene.CellAt(60f, 40f), Frame.FromHeading(new Vector3(60f, 40f, 0f), 0f));
        LandscapeChange first = landscape.ChangePosition(start, blocking: true);   // a login: build around the player first
        int objects = 0, missing = 0;
        foreach (WorldBlock b in first.Built)
        {
            objects += b.Objects.Count;
            missing += b.MissingIds.Count;
        }

        Console.WriteLine($"world: {first.Built.Count} landblocks at full detail of {first.Entered.Count} in the {landscape.MidWidth}x{landscape.MidWidth} grid, {objects} objects (buildings, statics, scenery), {missing} missing ids");
        TerrainWorld terrain = landscape.Loader.Cells.Terrain;

        // 3. The player: a part array from the human Setup and the character's skills (its weenie), placed on the ground,
        //    made the world's player (which gives it retail's movement manager and motion interpreter). SetupIssues names
        //    anything that would keep it from walking.
        PhysicsObj player = world.CreateObject(0x50000001);
        // The motion table turns motion commands into root motion: without one the player would not walk (SetupIssues says
        // NoMotionTable). Here it is a retail motion table read from its bytes (MotionTable.UnPack): a client hands it the
        // data-file entry (0x09000001 for a human) from its own dat reader; the sample writes a humanoid table's bytes
        // (HumanoidMotionTable, the walk, run, side-step and turn speeds of the human table). AnimatedPartArray plays it
        // through retail's MotionTableManager and CSequence. A client without motion tables uses
        // new SimplePartArray(SetupPhysics.Human) { MotionPlayer = new SpeedOnlyMotionPlayer() }, which moves the same.
        MotionTable humanTable = MotionTable.UnPack(HumanoidMotionTable.Bytes());
        var body = new AnimatedPartArray(SetupPhysics.Human, numParts: 1, humanTable, animations: null);
        player.PartArray = body;
        player.Weenie = KeyScript.Character();
        if (!player.EnterWorld(Scene.OnGround(terrain, 60f, 40f, heading: 0f)))   // after the landscape built its cells
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

        // 4. The player's input: the movement keys become retail's motion commands (a client passes its keyboard's state).
        var input = new PlayerInput(player);
        var remote = new RemoteCreature(world, terrain);
        var chaser = new Chaser(world, terrain, player);
        var check = new SceneCheck();
        bool faded = false;
        Console.WriteLine("   t  drawn cell      x       y       z     contact  speed  heading  doing                           | creature  error  transl.");
        int frames = (int)Math.Round(seconds * fps);
        int sceneResult = 0;
        string command = "";
        for (int i = 1; i <= frames; i++)
        {
            double now = (double)i / fps;

            // 5. Each frame: network input first (remote objects), then the player's keys, then the world tick, then drawing:
            //    every object at its blended pose for the render time (the world moves objects at most 30 times a second, at
            //    a cadence that depends on the frame rate; the blend is evenly spaced at any).
            remote.Deliver(now);
            (MovementKeys keys, command) = now < KeyScript.Seconds ? KeyScript.At(now) : KeyScript.WalkOut(player);
            input.SetHeldKeys(keys);
            chaser.Deliver(now);
            if ((keys & MovementKeys.Jump) == 0 && command == "run east (jump)" && input.LastError != MotionError.None)
            {
                command = $"jump refused ({input.LastError})";
            }
            if (!faded && now >= 20.0 && remote.Obj is not null)
            {
                faded = true;
                remote.Obj.SetTranslucency(1f, 2.0);   // fade the creature out over 2 s
            }

            // The landscape follows the player before the tick (retail: SmartBox::UseTime -> CellManager::ChangePosition):
            // nothing happens until its cell changes; crossing into another landblock shifts the grid.
            LandscapeChange change = landscape.ChangePosition(player.Position);
            if (change.Built.Count + change.Released.Count != 0)
            {
                Console.WriteLine($"{now,6:F2}  the world follows the player into 0x{landscape.LoadedCellId:X8}: {change.Built.Count} landblocks built, {change.Released.Count} released, {change.Entered.Count} entered the grid");
            }

            world.Tick(now);
            check.Observe(terrain, player, now);
            Position drawn = player.GetRenderPose(world.RenderTime);   // a renderer draws this
            if (i % fps == 0)
            {
                Print(player, drawn, remote, now, command);
                Console.WriteLine($"      chaser: {chaser.Status}");
            }

            if (i == (int)Math.Round(KeyScript.Seconds * fps))
            {
                sceneResult = check.Report(remote, chaser, now);   // the scene's script ends here; the walk out follows
            }
        }

        int crossResult = seconds >= KeyScript.WalkOutSeconds ? check.ReportCrossing(player, landscape) : 0;
        return seconds >= KeyScript.Seconds ? sceneResult | crossResult : 0;
    }

    private static void Print(PhysicsObj player, in Position drawn, RemoteCreature remote, double now, string command)
    {
        Vector3 o = drawn.Frame.Origin;
        Vector3 v = player.CachedVelocity;
        float speed = MathF.Sqrt(v.X * v.X + v.Y * v.Y);
        TransientState ts = player.TransientState;
        string contact = (ts & TransientState.OnWalkable) != 0 ? "walkable" : (ts & TransientState.Contact) != 0 ? "contact" : "airborne";
        string creature = remote.Obj is null ? "(none yet)" : string.Create(CultureInfo.InvariantCulture,
            $"{remote.ErrorAt(now),5:F2} m  {remote.Obj.Translucency,4:F2}");
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"{now,4:F0}  0x{drawn.ObjCellId:X8} {o.X,7:F2} {o.Y,7:F2} {o.Z,7:F2}  {contact,-8} {speed,5:F2}  {drawn.Frame.Heading,6:F1}  {command,-31} | {creature}"));
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
