using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// The non-retail Frame variants behind the fidelity switches (<see cref="PhysicsProfile.Arithmetic"/> = Float32,
/// <see cref="PhysicsProfile.RenormaliseEvery"/> = 0), beside which <see cref="FrameBenchmarks"/> measures the retail ones.
/// Each benchmark runs 1,000 operations; the mean is per operation.
/// </summary>
[MemoryDiagnoser]
public class FidelityFrameBenchmarks
{
    private const int Ops = 1000;
    private Frame _a;
    private Frame _b;
    private Vector3 _w;

    /// <summary>Builds the same two frames as <see cref="FrameBenchmarks"/>.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _a = Frame.FromHeading(new Vector3(10f, 20f, 30f), 37f);
        _b = new Frame(new Vector3(0.1f, 0.2f, 0.05f), Quaternion.CreateFromAxisAngle(Vector3.Normalize(new Vector3(1, 2, 3)), 0.01f));
        _w = new Vector3(0.001f, -0.002f, 0.03f);
    }

    /// <summary>Frame::combine in plain float32.</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public Frame CombineFloat32()
    {
        Frame r = _a;
        for (int i = 0; i < Ops; i++)
        {
            r.CombineFloat32(r, _b);
        }

        return r;
    }

    /// <summary>Frame::combine without renormalising (not retail).</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public Frame CombineNoRenormalise()
    {
        Frame r = _a;
        for (int i = 0; i < Ops; i++)
        {
            r.CombineNoRenormalise(r, _b);
        }

        return r;
    }

    /// <summary>Frame::grotate in plain float32.</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public Frame GRotateFloat32()
    {
        Frame r = _a;
        for (int i = 0; i < Ops; i++)
        {
            r.GRotateFloat32(_w);
        }

        return r;
    }

    /// <summary>Frame::grotate without renormalising (not retail).</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public Frame GRotateNoRenormalise()
    {
        Frame r = _a;
        for (int i = 0; i < Ops; i++)
        {
            r.GRotateNoRenormalise(_w);
        }

        return r;
    }
}
