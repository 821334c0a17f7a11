using System;
using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.Objects.Seams;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Support.Shared;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// One world tick (<c>CPhysics::UseTime</c>) of N walkers on real Dereth terrain through the retail sweep: the Holtburg
/// 3 × 3 landblocks (0xA8B3-0xAAB5) from ACDREAM_TERRAIN_DIR (landblock_heights_sample.csv), or, without the data, a
/// synthetic 3 × 3 with random heights (marked in the log). Walkers start at random spots of the centre landblock and walk
/// 3.12 m/s in circles of 6.24 m (0.5 rad/s), so they stay on the terrain. Mean per world tick (0.05 s).
/// </summary>
[MemoryDiagnoser]
public class WorldSweepBenchmarks
{
    private HoltburgCrowd _crowd = null!;

    /// <summary>Number of walkers.</summary>
    [Params(100, 1000)]
    public int N { get; set; }

    /// <summary>Loads the terrain and places the walkers.</summary>
    [GlobalSetup]
    public void Setup() => _crowd = new HoltburgCrowd(N);

    /// <summary>One world tick of all walkers.</summary>
    [Benchmark(OperationsPerInvoke = HoltburgCrowd.Ticks)]
    public bool Tick() => _crowd.Tick();
}

/// <summary>
/// Crowd density: the walkers of <see cref="WorldSweepBenchmarks"/> (all on the 152 m × 152 m interior of the Holtburg
/// centre landblock, so about 2.5 walkers per 24 m cell at 100 and 25 at 1,000), reported per walker and world tick. With
/// a cost that does not grow with the crowd both rows are equal; each walker's sweep tests the shadows of every object
/// listed in the cells it overlaps, so the object-to-object part grows with the density.
/// </summary>
[MemoryDiagnoser]
public class CrowdDensityBenchmarks
{
    private HoltburgCrowd _sparse = null!, _dense = null!;

    /// <summary>Builds both crowds, each in its own terrain world.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _sparse = new HoltburgCrowd(100);
        _dense = new HoltburgCrowd(1000);
    }

    /// <summary>One world tick of 100 walkers; mean per walker.</summary>
    [Benchmark(OperationsPerInvoke = HoltburgCrowd.Ticks * 100)]
    public bool PerWalker100() => _sparse.Tick();

    /// <summary>One world tick of 1,000 walkers; mean per walker.</summary>
    [Benchmark(OperationsPerInvoke = HoltburgCrowd.Ticks * 1000)]
    public bool PerWalker1000() => _dense.Tick();
}

/// <summary>
/// One 0.2 m sweep (one step) of a walker (one sphere, r = 0.5 m, step heights 0.6 m) up a real slope of Holtburg: the
/// spot of the centre landblock 0xA9B4 (whole metres, 30..160 m) where the terrain rises most steeply in +x while staying
/// walkable (rise below 0.9 m per metre), found by a scan of the terrain data at setup and printed in the log. The sweep
/// does not change the object, so every invoke repeats the same sweep. Needs ACDREAM_TERRAIN_DIR (a synthetic 27/24 slope
/// otherwise, marked in the log).
/// </summary>
[MemoryDiagnoser]
public class HoltburgSlopeSweepBenchmarks
{
    private RetailSweep _sweep = null!;
    private PhysicsObj _walker = null!;
    private Position _to;

    /// <summary>Finds the slope and places the walker.</summary>
    [GlobalSetup]
    public void Setup()
    {
        TerrainWorld terrain = HoltburgCrowd.LoadHoltburg(new Random(7));
        var world = new PhysicsWorld(0.0);
        _sweep = new RetailSweep(terrain);
        world.Sweep = _sweep;
        float bestX = 100f, bestY = 100f, bestRise = -1f;
        for (int y = 30; y <= 160; y++)
        {
            for (int x = 30; x <= 160; x++)
            {
                if (Height(terrain, x, y, out float z0) && Height(terrain, x + 0.2f, y, out float z1))
                {
                    float rise = (z1 - z0) / 0.2f;
                    if (rise < 0.9f && rise > bestRise)
                    {
                        (bestX, bestY, bestRise) = (x, y, rise);
                    }
                }
            }
        }

        Height(terrain, bestX, bestY, out float z);
        Console.WriteLine($"// HoltburgSlopeSweepBenchmarks: walker at ({bestX}, {bestY}, {z}) of 0xA9B4, rise {bestRise} m/m in +x");
        var p = new Position(Holtburg.CentreCell(bestX, bestY), Frame.FromHeading(new Vector3(bestX, bestY, z), 90f));
        _walker = Walkers.Create(world, 1, p, Walkers.OneSphere());
        _to = _walker.Position;
        _to.Frame.Origin = new Vector3(_to.Frame.Origin.X + 0.2f, _to.Frame.Origin.Y, _to.Frame.Origin.Z);
    }

    /// <summary>One 0.2 m sweep up the slope.</summary>
    [Benchmark]
    public object? SlopeCall() => _sweep.RunTransition(_walker, _walker.Position, _to, false);

    private static bool Height(TerrainWorld terrain, float x, float y, out float z) =>
        terrain.TryGetTerrainHeight(new Position(Holtburg.CentreCell(x, y), new Vector3(x, y, 0f)), out z);
}

/// <summary>
/// N walkers on the Holtburg landblocks (see <see cref="WorldSweepBenchmarks"/>), warmed by five world ticks, with
/// object maintenance off; <see cref="Tick"/> runs <see cref="Ticks"/> world ticks of 0.05 s.
/// </summary>
internal sealed class HoltburgCrowd
{
    /// <summary>World ticks per benchmark invoke.</summary>
    public const int Ticks = 10;

    private const double Dt = 0.05;
    private readonly PhysicsWorld _world;
    private double _now;

    /// <summary>Loads a fresh terrain world and places <paramref name="n"/> walkers (random spots and headings, seed 7).</summary>
    public HoltburgCrowd(int n)
    {
        var rnd = new Random(7);
        TerrainWorld terrain = LoadHoltburg(rnd);
        _world = new PhysicsWorld(0.0);
        _world.Sweep = new RetailSweep(terrain);
        int placed = 0;
        for (int i = 0; placed < n && i < n * 4; i++)
        {
            float x = 20f + (float)rnd.NextDouble() * 152f, y = 20f + (float)rnd.NextDouble() * 152f;
            var p = new Position(Holtburg.CentreCell(x, y), new Vector3(x, y, 0f));
            if (!terrain.TryGetTerrainHeight(p, out float z))
            {
                continue;
            }

            p.Frame.Origin = new Vector3(x, y, z);
            p.Frame.SetHeading((float)(rnd.NextDouble() * 360.0));
            PhysicsObj obj = _world.CreateObject((uint)(placed + 1));
            SimplePartArray parts = Walkers.OneSphere();
            parts.SequenceVelocity = new Vector3(0f, 3.12f, 0f);
            parts.SequenceOmega = new Vector3(0f, 0f, 0.5f);
            obj.PartArray = parts;
            obj.Movement = new BasicMovementManager();
            if (obj.EnterWorld(p))
            {
                placed++;
            }
        }

        _world.ObjectMaintenanceActive = false;
        _now = 0.0;
        for (int i = 0; i < 5; i++)
        {
            _now += Dt;
            _world.Tick(_now);
        }
    }

    /// <summary>Runs <see cref="Ticks"/> world ticks; true when the last one ticked.</summary>
    public bool Tick()
    {
        bool ticked = false;
        for (int i = 0; i < Ticks; i++)
        {
            _now += Dt;
            ticked = _world.Tick(_now);
        }

        return ticked;
    }

    /// <summary>Runs one world tick (InstructionCounts).</summary>
    public bool TickOnce()
    {
        _now += Dt;
        return _world.Tick(_now);
    }

    /// <summary>The Holtburg terrain from ACDREAM_TERRAIN_DIR, or a synthetic 3 × 3 of random heights from <paramref name="rnd"/>.</summary>
    public static TerrainWorld LoadHoltburg(Random rnd)
    {
        string? dir = Environment.GetEnvironmentVariable("ACDREAM_TERRAIN_DIR");
        TerrainWorld world;
        if (!string.IsNullOrEmpty(dir))
        {
            world = Holtburg.World(Holtburg.Read(dir));
            Console.WriteLine("// HoltburgCrowd: real Holtburg terrain from " + dir);
            return world;
        }

        Console.WriteLine("// HoltburgCrowd: ACDREAM_TERRAIN_DIR unset, synthetic random terrain");
        var table = new float[256];
        for (int i = 0; i < 256; i++)
        {
            table[i] = i < 201 ? 2f * i : 400f + (i - 200);
        }

        world = new TerrainWorld(new LandHeightTable(table));
        var h = new byte[81];
        var t = new ushort[81];
        for (int bx = 0xA8; bx <= 0xAA; bx++)
        {
            for (int by = 0xB3; by <= 0xB5; by++)
            {
                for (int k = 0; k < 81; k++)
                {
                    h[k] = (byte)(40 + rnd.Next(4));
                }

                world.AddLandBlock(LandBlock.MakeId(bx, by), h, t);
            }
        }

        return world;
    }
}
