using System;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Tests.Support;

/// <summary>Records detection reports (with the physics time of each) into preallocated arrays; optionally runs an action on
/// a report (e.g. removing an object).</summary>
internal sealed class DetectionRecorder : IDetectionListener
{
    private readonly double[] _times = new double[64];
    private readonly uint[] _contexts = new uint[64];
    private readonly DetectionInfo[] _infos = new DetectionInfo[64];

    public int Count { get; private set; }

    public int Total { get; private set; }

    public Action<PhysicsObj, DetectionInfo>? OnReport { get; set; }

    public double Time(int i) => _times[i];

    public uint Context(int i) => _contexts[i];

    public DetectionInfo Info(int i) => _infos[i];

    public void OnDetection(PhysicsObj detector, uint contextId, DetectionInfo info)
    {
        Total++;
        if (Count < _infos.Length)
        {
            _times[Count] = detector.World.PhysicsTime;
            _contexts[Count] = contextId;
            _infos[Count] = info;
            Count++;
        }

        OnReport?.Invoke(detector, info);
    }
}
