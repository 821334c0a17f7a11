using System.Numerics;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Tests.Replay.Harness;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Cost of the position managers per server update and per tick: InterpolateTo (near branch with prune and head eviction),
/// InterpolationManager.AdjustOffset, the whole PositionManager (interpolation, sticky, constraint) per substep, and a world
/// tick of one interpolating creature. Each benchmark runs <see cref="Ops"/> operations; the mean is per operation.
/// Expected allocation: 0 B.
/// </summary>
[MemoryDiagnoser]
public class ManagerBenchmarks
{
    private const int Ops = 1000;
    private ManagerScene _scene = null!;
    private Position[] _updates = null!;
    private double _now;
    private ushort _stamp;

    /// <summary>A creature on flat ground with a full queue, a stick and a constraint.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _scene = new ManagerScene(new Vector3(60f, 40f, 0f));
        _scene.CreatureParts.SequenceVelocity = new Vector3(0f, 4f, 0f);
        _updates = new Position[64];
        for (int i = 0; i < _updates.Length; i++)
        {
            _updates[i] = ManagerScene.At(new Vector3(60f + (i % 2 * 0.5f), 41f + (i * 0.4f), 0f));
        }

        for (int i = 0; i < _updates.Length; i++)
        {
            _scene.Creature.InterpolateTo(_updates[i], false);
        }

        _scene.Managers.ConstrainTo(_scene.Creature.Position, 10f, 50f);
        _scene.Managers.StickTo(1, 0.5f, 1f);
        _scene.Creature.HandleUpdateTarget(new TargetInfo { ObjectId = 1, Status = TargetStatus.Ok, TargetPosition = _scene.Player.Position });
    }

    /// <summary>InterpolateTo: one server update (near branch, prune walk, head eviction at 20).</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public int InterpolateTo()
    {
        InterpolationManager im = _scene.Interpolation!;
        for (int i = 0; i < Ops; i++)
        {
            im.InterpolateTo(_updates[i & 63], false);
        }

        return im.Count;
    }

    /// <summary>InterpolationManager.AdjustOffset: one substep's step towards the head (audit every 5th).</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public Frame InterpolationAdjustOffset()
    {
        InterpolationManager im = _scene.Interpolation!;
        Frame offset = Frame.Identity;
        for (int i = 0; i < Ops; i++)
        {
            if (im.Count == 0)
            {
                im.InterpolateTo(_updates[i & 63], false);
            }

            offset = Frame.Identity;
            im.AdjustOffset(ref offset, 1.0 / 30.0);
        }

        return offset;
    }

    /// <summary>PositionManager.AdjustOffset + UseTime: all three managers, one substep.</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public Frame PositionManagerTick()
    {
        PositionManager pm = _scene.Managers;
        Frame offset = Frame.Identity;
        for (int i = 0; i < Ops; i++)
        {
            offset = Frame.Identity;
            pm.AdjustOffset(ref offset, 1.0 / 30.0);
            pm.UseTime();
        }

        return offset;
    }

    /// <summary>A 30 Hz world tick of the player and one remote creature receiving a report every tick.</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public bool UpdateAndWorldTick()
    {
        bool ticked = false;
        for (int i = 0; i < Ops; i++)
        {
            _now += 1.0 / 30.0;
            Position p = _updates[i & 63];
            p.Frame.Origin.Y += (float)(_now * 0.01 % 1.0);
            _stamp++;
            _scene.Creature.HandleReceivedPosition(p, _stamp, 0, true);
            ticked |= _scene.World.Tick(_now);
        }

        return ticked;
    }
}
