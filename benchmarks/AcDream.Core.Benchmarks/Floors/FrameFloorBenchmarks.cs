using System;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks.Floors;

/// <summary>
/// The rows of <see cref="FrameBenchmarks"/> on their bit-identical floor (<see cref="FloorFrame"/>): the same inputs, the
/// same chains of 1,000 operations, each on the result of the one before. Run them in one run beside the library's rows
/// (<c>--filter '*FrameBenchmarks*' '*FrameFloorBenchmarks*'</c>). The setup plays each chain on both and throws when a
/// single bit differs, so a floor that is faster by leaving out arithmetic cannot pass.
/// </summary>
[MemoryDiagnoser]
public class FrameFloorBenchmarks
{
    private const int Ops = 1000;
    private FloorFrame _a;
    private FloorFrame _b;
    private Vector3 _w;
    private Vector3 _yaw;
    private Vector3 _p;

    // The single-operation state of the instruction counts (InstructionCounts): each call continues the chain.
    private FloorFrame _chain;
    private Vector3 _point;
    private int _headingStep;

    /// <summary>The frames of <see cref="FrameBenchmarks"/>, and the bit check of every chain against the library.</summary>
    [GlobalSetup]
    public void Setup()
    {
        Frame a = Frame.FromHeading(new Vector3(10f, 20f, 30f), 37f);
        Frame b = new(new Vector3(0.1f, 0.2f, 0.05f), Quaternion.CreateFromAxisAngle(Vector3.Normalize(new Vector3(1, 2, 3)), 0.01f));
        _a = From(a);
        _b = From(b);
        _w = new Vector3(0.001f, -0.002f, 0.03f);
        _yaw = new Vector3(0f, 0f, 0.5f / 30f);
        _p = new Vector3(1f, 2f, 3f);
        _chain = _a;
        _point = _p;
        Check(a, b);
    }

    /// <summary>combine on its floor.</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public FloorFrame Combine()
    {
        FloorFrame r = _a;
        for (int i = 0; i < Ops; i++)
        {
            r.CombineWith(_b);
        }

        return r;
    }

    /// <summary>grotate on its floor.</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public FloorFrame GRotate()
    {
        FloorFrame r = _a;
        for (int i = 0; i < Ops; i++)
        {
            r.GRotate(_w);
        }

        return r;
    }

    /// <summary>grotate by a pure yaw on its floor.</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public FloorFrame GRotateYaw()
    {
        FloorFrame r = _a;
        for (int i = 0; i < Ops; i++)
        {
            r.GRotate(_yaw);
        }

        return r;
    }

    /// <summary>rotate on its floor.</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public FloorFrame Rotate()
    {
        FloorFrame r = _a;
        for (int i = 0; i < Ops; i++)
        {
            r.Rotate(_w);
        }

        return r;
    }

    /// <summary>localtoglobal then globaltolocal on their floor.</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public Vector3 LocalToGlobalRoundTrip()
    {
        Vector3 p = _p;
        FloorFrame a = _a;
        for (int i = 0; i < Ops; i++)
        {
            p = a.RoundTrip(p);
        }

        return p;
    }

    /// <summary>set_heading on its floor.</summary>
    [Benchmark(OperationsPerInvoke = Ops)]
    public FloorFrame SetHeading()
    {
        FloorFrame r = _a;
        for (int i = 0; i < Ops; i++)
        {
            r.SetHeading(i * 0.36f);
        }

        return r;
    }

    // One operation of each row, continuing one chain (InstructionCounts).
    internal void CombineOnce() => _chain.CombineWith(_b);

    internal void GRotateOnce() => _chain.GRotate(_w);

    internal void RotateOnce() => _chain.Rotate(_w);

    internal void LocalToGlobalRoundTripOnce() => _point = _chain.RoundTrip(_point);

    internal void SetHeadingOnce()
    {
        _chain.SetHeading(_headingStep * 0.36f);
        _headingStep = (_headingStep + 1) % Ops;
    }

    private static FloorFrame From(in Frame f)
    {
        FloorFrame r = default;
        r.Ox = f.Origin.X;
        r.Oy = f.Origin.Y;
        r.Oz = f.Origin.Z;
        r.Qw = f.Qw;
        r.Qx = f.Qx;
        r.Qy = f.Qy;
        r.Qz = f.Qz;
        r.M11 = f.M11;
        r.M12 = f.M12;
        r.M13 = f.M13;
        r.M21 = f.M21;
        r.M22 = f.M22;
        r.M23 = f.M23;
        r.M31 = f.M31;
        r.M32 = f.M32;
        r.M33 = f.M33;
        return r;
    }

    // Every chain of the benchmarks, played on the library and on the floor: the same bits at every step, or an exception.
    private void Check(Frame a, Frame b)
    {
        Frame lc = a, lg = a, ly = a, lr = a, lh = a;
        FloorFrame fc = _a, fg = _a, fy = _a, fr = _a, fh = _a;
        Vector3 lp = _p, fp = _p;
        for (int i = 0; i < Ops; i++)
        {
            lc.Combine(lc, b);
            fc.CombineWith(_b);
            lg.GRotate(_w);
            fg.GRotate(_w);
            ly.GRotate(_yaw);
            fy.GRotate(_yaw);
            lr.Rotate(_w);
            fr.Rotate(_w);
            lh.SetHeading(i * 0.36f);
            fh.SetHeading(i * 0.36f);
            lp = a.GlobalToLocal(a.LocalToGlobal(lp));
            fp = _a.RoundTrip(fp);
            Same(lc, fc, "combine", i);
            Same(lg, fg, "grotate", i);
            Same(ly, fy, "grotate (yaw)", i);
            Same(lr, fr, "rotate", i);
            Same(lh, fh, "set_heading", i);
            if (Bits(lp.X) != Bits(fp.X) || Bits(lp.Y) != Bits(fp.Y) || Bits(lp.Z) != Bits(fp.Z))
            {
                throw new InvalidOperationException($"floor round trip differs from the library at step {i}");
            }
        }
    }

    private static void Same(in Frame l, in FloorFrame f, string row, int step)
    {
        FloorFrame lf = From(l);
        ReadOnlySpan<float> x = [lf.Qw, lf.Qx, lf.Qy, lf.Qz, lf.M11, lf.M12, lf.M13, lf.M21, lf.M22, lf.M23, lf.M31, lf.M32, lf.M33, lf.Ox, lf.Oy, lf.Oz];
        ReadOnlySpan<float> y = [f.Qw, f.Qx, f.Qy, f.Qz, f.M11, f.M12, f.M13, f.M21, f.M22, f.M23, f.M31, f.M32, f.M33, f.Ox, f.Oy, f.Oz];
        for (int k = 0; k < x.Length; k++)
        {
            if (Bits(x[k]) != Bits(y[k]))
            {
                throw new InvalidOperationException($"floor {row} differs from the library at step {step}, field {k}");
            }
        }
    }

    private static int Bits(float v) => BitConverter.SingleToInt32Bits(v);
}
