using System.Numerics;
using AcDream.Core.Physics.Collision.Sweep;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Objects.Parts;
using AcDream.Core.Physics.World;
using Xunit;

namespace AcDream.Core.Tests.Support;

/// <summary>Shared scene builders for the object-tick tests.</summary>
internal static class TickTestContext
{
    /// <summary>An outdoor cell of landblock 0xA9B4 (cell 1 covers x, y in [0, 24)).</summary>
    public const uint OutdoorCell = 0xA9B40001u;

    /// <summary>Creates a world and one object with a <see cref="SimplePartArray"/> placed at <paramref name="origin"/>.</summary>
    public static PhysicsObj CreateObject(PhysicsWorld world, Vector3 origin, int spheres = 1, uint id = 0)
    {
        PhysicsObj obj = world.CreateObject(id);
        obj.PartArray = new SimplePartArray(numParts: 2, numSpheres: spheres);
        Assert.True(obj.EnterWorld(new Position(OutdoorCell, origin)));
        return obj;
    }

    /// <summary>A world whose clocks start at <paramref name="start"/>.</summary>
    public static PhysicsWorld World(double start = 0.0, PhysicsProfile? profile = null) => new(start, profile);
}

/// <summary>Records step sizes into a preallocated array (no allocation per step).</summary>
internal sealed class StepRecorder : IStepObserver
{
    private readonly float[] _quanta = new float[4096];
    private readonly double[] _times = new double[4096];

    public int Count { get; private set; }

    public float Quantum(int i) => _quanta[i];

    public double Time(int i) => _times[i];

    public void Clear() => Count = 0;

    public void OnStep(PhysicsObj obj, float quantum, double physicsTime)
    {
        _quanta[Count] = quantum;
        _times[Count] = physicsTime;
        Count++;
    }
}

/// <summary>A sweep that always succeeds at the requested position on a horizontal walkable floor (normal +Z).</summary>
internal sealed class FlatGroundSweep : CollisionSweep
{
    public override bool SweepObject(PhysicsObj obj, in Position oldPos, in Position newPos, bool adminMove, ref TransitionResult result)
    {
        result = Ground(newPos, obj.CellId);
        return true;
    }

    public override SetPositionError SetPosition(PhysicsObj obj, in Position pos, SetPositionFlags flags)
    {
        obj.CommitTransition(Ground(pos, pos.ObjCellId));
        return SetPositionError.Ok;
    }

    private static TransitionResult Ground(in Position p, uint cell)
    {
        TransitionResult r = TransitionResult.FreeSpace(p);
        r.CurrentCellId = cell;
        r.ContactPlaneValid = true;
        r.ContactPlaneNormal = new Vector3(0f, 0f, 1f);
        r.ContactPlaneD = -p.Frame.Origin.Z;
        r.ContactPlaneCellId = cell;
        return r;
    }
}

/// <summary>A sweep that always fails (blocked everywhere).</summary>
internal sealed class BlockedTransition : CollisionSweep
{
    public override bool SweepObject(PhysicsObj obj, in Position oldPos, in Position newPos, bool adminMove, ref TransitionResult result) => false;

    public override SetPositionError SetPosition(PhysicsObj obj, in Position pos, SetPositionFlags flags)
    {
        obj.CommitTransition(TransitionResult.FreeSpace(pos));
        return SetPositionError.Ok;
    }
}
