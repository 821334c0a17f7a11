using System.Numerics;
using AcDream.Core.Physics.Spatial;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Cost of the retail Frame operations that every tick calls. Each benchmark runs 1,000 operations on one frame, each on
/// the result of the one before, so the mean per operation is the latency of the chain (the quaternion product, its
/// square root and division and the float roundings depend on the step before).
/// </summary>
[MemoryDiagnoser]
public class FrameBenchmarks
{
    private const int Ops = 1000;
    private Frame _a;
    private Frame _b;
    private Vector3 _w;
    private Vector3 _yaw;
    private Vector3 _p;

    // The single-operation state of the instruction counts (InstructionCounts): each call continues the chain.
    private Frame _chain;
    private Vector3 _point;
    private int _headingStep;

    /// <summary>Builds two non-trivial frames.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _a = Frame.FromHeading(new Vector3(10f, 20f, 30f), 37f);
        _b = new Frame(new Vector3(0.1f, 0.2f, 0.05f), Quaternion.CreateFromAxisAngle(Vector3.Normalize(new Vector3(1, 2, 3)), 0.01f));
        _w = new Vector3(0.001f, -0.002f, 0.03f);
        _yaw = new Vector3(0f, 0f, 0.5f / 30f);
        _p = new Vector3(1f, 2f, 3f);
        _chain = _a;
        _point = _p;
    }

    /// <summary>Frame::combine.</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public Frame Combine()
    {
        Frame r = _a;
        for (int i = 0; i < Ops; i++)
        {
            r.Combine(r, _b);
        }

        return r;
    }

    /// <summary>Frame::grotate (axis-angle pre-multiply and renormalise).</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public Frame GRotate()
    {
        Frame r = _a;
        for (int i = 0; i < Ops; i++)
        {
            r.GRotate(_w);
        }

        return r;
    }

    /// <summary>Frame::grotate by omega·dt of a pure yaw (0.5 rad/s for 1/30 s).</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public Frame GRotateYaw()
    {
        Frame r = _a;
        for (int i = 0; i < Ops; i++)
        {
            r.GRotate(_yaw);
        }

        return r;
    }

    /// <summary>Frame::rotate (local axes lifted by the cached matrix, then grotate).</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public Frame Rotate()
    {
        Frame r = _a;
        for (int i = 0; i < Ops; i++)
        {
            r.Rotate(_w);
        }

        return r;
    }

    /// <summary>Frame::localtoglobal then globaltolocal.</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public Vector3 LocalToGlobalRoundTrip()
    {
        Vector3 p = _p;
        for (int i = 0; i < Ops; i++)
        {
            p = _a.GlobalToLocal(_a.LocalToGlobal(p));
        }

        return p;
    }

    /// <summary>Frame::set_heading (through set_vector_heading and euler_set_rotate).</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public Frame SetHeading()
    {
        Frame r = _a;
        for (int i = 0; i < Ops; i++)
        {
            r.SetHeading(i * 0.36f);
        }

        return r;
    }

    /// <summary>Frame::get_heading.</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public double Heading()
    {
        double s = 0;
        for (int i = 0; i < Ops; i++)
        {
            s += _a.Heading;
        }

        return s;
    }

    // One operation of each row, continuing one chain (InstructionCounts).
    internal void CombineOnce() => _chain.Combine(_chain, _b);

    internal void GRotateOnce() => _chain.GRotate(_w);

    internal void RotateOnce() => _chain.Rotate(_w);

    internal void LocalToGlobalRoundTripOnce() => _point = _a.GlobalToLocal(_a.LocalToGlobal(_point));

    internal void SetHeadingOnce()
    {
        _chain.SetHeading(_headingStep * 0.36f);
        _headingStep = (_headingStep + 1) % Ops;
    }
}
