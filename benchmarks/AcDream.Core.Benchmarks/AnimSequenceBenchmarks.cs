using System;
using System.Numerics;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Spatial;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// One tick of an animation sequence playing (retail <c>CSequence::update</c>): a 30-frame cyclic animation with root motion
/// and 20 parts at 30 frames per second, plus the sequence's velocity and omega, advanced by 1/30 s (one frame crossed and
/// its root motion combined; a loop every 30 ticks). No hook object, so no hooks are queued. Expected: 0 B per tick.
/// </summary>
[MemoryDiagnoser]
public class AnimSequenceBenchmarks
{
    private const int Ticks = 300;
    private AnimSequence _sequence = null!;
    private Frame _offset;

    /// <summary>Builds the animation and queues it.</summary>
    [GlobalSetup]
    public void Setup()
    {
        const int frames = 30, parts = 20;
        var pos = new AFrame[frames];
        var partFrames = new AnimFrame[frames];
        for (int i = 0; i < frames; i++)
        {
            pos[i] = new AFrame(new Vector3(0f, 0.1f, 0f), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.01f));
            var pf = new AFrame[parts];
            Array.Fill(pf, AFrame.Identity);
            partFrames[i] = new AnimFrame(pf, null, 0);
        }

        var library = new AnimationLibrary();
        library.Add(new AnimClip(0x03000001, parts, pos, partFrames, hasHooks: false));
        _sequence = new AnimSequence(library);
        _sequence.SetVelocity(new Vector3(0f, 1f, 0f));
        _sequence.SetOmega(new Vector3(0f, 0f, 0.5f));
        _sequence.AppendAnimation(new AnimData(0x03000001, 0, -1, 30f));
    }

    /// <summary>One sequence update of 1/30 s into a fresh offset frame.</summary>
    [Benchmark(OperationsPerInvoke = Ticks)]
    public Frame OneTick()
    {
        Frame last = default;
        for (int i = 0; i < Ticks; i++)
        {
            _offset = Frame.Identity;
            _sequence.Update(1.0 / 30.0, ref _offset);
            last = _offset;
        }

        return last;
    }

    // One update of the row (InstructionCounts).
    internal void OneTickOnce()
    {
        _offset = Frame.Identity;
        _sequence.Update(1.0 / 30.0, ref _offset);
    }
}
