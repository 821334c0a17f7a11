using System;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Benchmarks.Report;

/// <summary>A recorded path: consumed physics time and landblock-independent offset from the scene's basis.</summary>
internal sealed class Trajectory
{
    public List<double> T { get; } = [];

    public List<Vector3> P { get; } = [];

    public void Add(double t, Vector3 p)
    {
        T.Add(t);
        P.Add(p);
    }

    /// <summary>Linear interpolation at <paramref name="t"/> (clamped to the recorded span).</summary>
    public Vector3 At(double t)
    {
        int n = T.Count;
        if (t <= T[0])
        {
            return P[0];
        }

        if (t >= T[n - 1])
        {
            return P[n - 1];
        }

        int i = T.BinarySearch(t);
        if (i >= 0)
        {
            return P[i];
        }

        i = ~i;
        double a = (t - T[i - 1]) / (T[i] - T[i - 1]);
        return Vector3.Lerp(P[i - 1], P[i], (float)a);
    }
}

/// <summary>
/// A scene on terrain through the retail sweep, run either as the candidate (the world ticked at the pacing's frame times,
/// <c>CPhysics::UseTime</c>) or as the fine-step reference (every object's <c>update_object</c> called every 1/600 s with
/// the retail profile: double intermediates, one step per call). Error: the largest distance of any tracked object from the
/// reference path at the same consumed physics time, m.
/// </summary>
internal abstract class StepSceneSim : Sim
{
    /// <summary>Step of the fine reference, seconds.</summary>
    public const double FineStep = 1.0 / 600.0;

    private readonly double[] _times;
    private readonly bool _fine;
    private PhysicsObj[] _tracked = [];
    private double _t0;
    private double _max;

    protected StepSceneSim(PhysicsWorld world, Pacing? pacing, double seconds)
    {
        World = world;
        Seconds = seconds;
        _fine = pacing is null;
        if (pacing is null)
        {
            int n = (int)Math.Round(seconds / FineStep);
            _times = new double[n];
            for (int i = 0; i < n; i++)
            {
                _times[i] = (i + 1) * FineStep;
            }
        }
        else
        {
            _times = pacing.Times(seconds);
        }
    }

    public PhysicsWorld World { get; }

    public override int Frames => _times.Length;

    public override double Seconds { get; }

    /// <summary>Where offsets are measured from.</summary>
    public Position Basis { get; protected set; }

    /// <summary>The reference paths (one per tracked object) to measure against; null records only.</summary>
    public Trajectory[]? Reference { get; set; }

    /// <summary>The paths recorded by the sampled pass.</summary>
    public Trajectory[] Recorded { get; private set; } = [];

    public override double Error => _max;

    /// <summary>Declares the tracked objects (after they entered the world).</summary>
    protected void Track(params PhysicsObj[] objs)
    {
        _tracked = objs;
        _t0 = objs[0].UpdateTime;
        Recorded = new Trajectory[objs.Length];
        for (int k = 0; k < objs.Length; k++)
        {
            Recorded[k] = new Trajectory();
            Recorded[k].Add(0.0, Basis.GetOffset(objs[k].Position));
        }
    }

    public override void Advance(int i)
    {
        if (_fine)
        {
            World.SetCurrentTime(_times[i]);
            for (int k = 0; k < World.ObjectCount; k++)
            {
                World.GetObject(k).UpdateObject();
            }
        }
        else
        {
            World.Tick(_times[i]);
        }
    }

    public override void Sample(int i)
    {
        for (int k = 0; k < _tracked.Length; k++)
        {
            PhysicsObj o = _tracked[k];
            double t = o.UpdateTime - _t0;
            Vector3 p = Basis.GetOffset(o.Position);
            Trajectory rec = Recorded[k];
            if (t > rec.T[^1])
            {
                rec.Add(t, p);
            }

            if (Reference is not null)
            {
                Vector3 r = Reference[k].At(t);
                _max = Math.Max(_max, ClosedForms.Distance(p, (r.X, r.Y, r.Z)));
            }
        }
    }
}
