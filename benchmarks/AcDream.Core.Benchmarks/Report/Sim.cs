using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>
/// One run of one scene under one fidelity choice. <see cref="Advance"/> runs client frame i (the only code that is timed);
/// <see cref="Sample"/> measures after a frame (error pass only); <see cref="Error"/> is read after the error pass.
/// </summary>
internal abstract class Sim
{
    /// <summary>Number of client frames of the run.</summary>
    public abstract int Frames { get; }

    /// <summary>Simulated seconds covered by the run.</summary>
    public abstract double Seconds { get; }

    /// <summary>Runs client frame <paramref name="i"/>.</summary>
    public abstract void Advance(int i);

    /// <summary>Measures after frame <paramref name="i"/> (not timed).</summary>
    public virtual void Sample(int i)
    {
    }

    /// <summary>The run's error, in the row's unit, after the sampled pass.</summary>
    public abstract double Error { get; }

    /// <summary>Optional note for the table (e.g. a second measure).</summary>
    public virtual string Note => "";
}

/// <summary>A sim that ticks one world at the frame times of a <see cref="Pacing"/> (retail's client loop: <c>CPhysics::UseTime</c>).</summary>
internal abstract class WorldSim : Sim
{
    private readonly double[] _times;

    protected WorldSim(PhysicsWorld world, Pacing pacing, double seconds)
    {
        World = world;
        Seconds = seconds;
        _times = pacing.Times(seconds);
    }

    public PhysicsWorld World { get; }

    public override int Frames => _times.Length;

    public override double Seconds { get; }

    public double TimeOf(int i) => _times[i];

    public override void Advance(int i) => World.Tick(_times[i]);
}

/// <summary>Shared builders for the report's scenes.</summary>
internal static class SceneKit
{
    /// <summary>An outdoor cell of landblock 0x8080 (cell 1: x, y in [0, 24)).</summary>
    public const uint Cell = 0x80800001u;

    /// <summary>A plain object (one 0.5 m sphere at its origin, a part array, no movement manager) placed at <paramref name="origin"/>.</summary>
    public static PhysicsObj Ball(PhysicsWorld world, Vector3 origin, uint id = 1)
    {
        PhysicsObj obj = world.CreateObject(id);
        obj.PartArray = new SimplePartArray(1, 1) { Radius = 0.5f };
        if (!obj.EnterWorld(new Position(Cell, origin)))
        {
            throw new InvalidOperationException("object could not enter the world");
        }

        return obj;
    }

    /// <summary>The landblock-independent offset of <paramref name="p"/> from <paramref name="basis"/>, metres.</summary>
    public static Vector3 Offset(in Position basis, in Position p) => basis.GetOffset(p);
}
