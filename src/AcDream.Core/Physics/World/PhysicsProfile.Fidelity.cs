using System;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.World;

// The fidelity switches of a profile. Each default is retail; every other value is a deliberate, documented divergence
// (docs/divergences.md) whose error and cost are measured in docs/accuracy-vs-cost.md.
public sealed partial class PhysicsProfile
{
    /// <summary>
    /// Arithmetic of the tick's frame math and integration (<c>Frame::combine</c>, <c>Frame::grotate</c>,
    /// <c>UpdatePhysicsInternal</c>, <c>calc_friction</c>). Default <see cref="ArithmeticMode.RetailDouble"/>: double
    /// intermediates where the client kept x87 temporaries. <see cref="ArithmeticMode.Float32"/> is not retail.
    /// </summary>
    public ArithmeticMode Arithmetic { get; private init; } = ArithmeticMode.RetailDouble;

    /// <summary>
    /// How often a rotation change renormalises the quaternion: 1 (default, retail: <c>Frame::set_rotate</c> normalises on
    /// every combine and grotate), N &gt; 1 on every N-th rotation change of an object only, 0 never. Values other than 1 are
    /// not retail: the unnormalised product is stored as is and the cached matrix is rebuilt from it.
    /// </summary>
    public int RenormaliseEvery { get; private init; } = 1;

    /// <summary>
    /// Scale of the sweep's step length relative to the first sphere's radius: the sweep takes
    /// <c>ceil(|offset| / (scale × radius))</c> steps. 1 (default) is retail's <c>CTransition::calc_num_steps</c>
    /// (acclient.c:311763); above 1 is coarser (fewer, longer steps), below 1 finer. Not retail unless 1.
    /// </summary>
    public float SweepStepScale { get; private init; } = 1f;

    /// <summary>
    /// How a remote object follows server position reports. Default <see cref="RemoteSmoothing.Retail"/>
    /// (<c>InterpolationManager</c>); the others are not retail.
    /// </summary>
    public RemoteSmoothing RemoteSmoothing { get; private init; } = RemoteSmoothing.Retail;

    /// <summary>True when every fidelity switch has its retail value (the time slicing may still be ACE's).</summary>
    public bool HasRetailFidelity =>
        Arithmetic == ArithmeticMode.RetailDouble && RenormaliseEvery == 1 && SweepStepScale == 1f
        && RemoteSmoothing == RemoteSmoothing.Retail;

    /// <summary>
    /// A copy of this profile (same time slicing) with the given fidelity switches changed; a null argument keeps this
    /// profile's value.
    /// </summary>
    /// <param name="arithmetic">See <see cref="Arithmetic"/>.</param>
    /// <param name="renormaliseEvery">See <see cref="RenormaliseEvery"/>; must be &gt;= 0.</param>
    /// <param name="sweepStepScale">See <see cref="SweepStepScale"/>; must be finite and in (0, 1000].</param>
    /// <param name="remoteSmoothing">See <see cref="RemoteSmoothing"/>.</param>
    /// <param name="name">Name of the new profile; by default this profile's name followed by the changed switches.</param>
    /// <returns>The new profile.</returns>
    /// <exception cref="ArgumentException">A value is out of range or not a defined enum member.</exception>
    public PhysicsProfile With(ArithmeticMode? arithmetic = null, int? renormaliseEvery = null, float? sweepStepScale = null,
        RemoteSmoothing? remoteSmoothing = null, string? name = null)
    {
        if (arithmetic is { } a && !Enum.IsDefined(a))
        {
            throw new ArgumentException("Unknown arithmetic mode.", nameof(arithmetic));
        }

        if (renormaliseEvery is < 0)
        {
            throw new ArgumentException("RenormaliseEvery must be >= 0 (0 = never, 1 = retail).", nameof(renormaliseEvery));
        }

        if (sweepStepScale is { } s && !(float.IsFinite(s) && s > 0f && s <= 1000f))
        {
            throw new ArgumentException("SweepStepScale must be finite and in (0, 1000].", nameof(sweepStepScale));
        }

        if (remoteSmoothing is { } r && !Enum.IsDefined(r))
        {
            throw new ArgumentException("Unknown remote smoothing.", nameof(remoteSmoothing));
        }

        ArithmeticMode na = arithmetic ?? Arithmetic;
        int nr = renormaliseEvery ?? RenormaliseEvery;
        float ns = sweepStepScale ?? SweepStepScale;
        RemoteSmoothing nm = remoteSmoothing ?? RemoteSmoothing;
        string n = name ?? string.Create(System.Globalization.CultureInfo.InvariantCulture,
            $"{Name}{(na != ArithmeticMode.RetailDouble ? "+" + na : "")}{(nr != 1 ? "+Renormalise" + nr : "")}{(ns != 1f ? "+Sweep" + ns : "")}{(nm != RemoteSmoothing.Retail ? "+" + nm : "")}");
        return new PhysicsProfile(this, n)
        {
            Arithmetic = na,
            RenormaliseEvery = nr,
            SweepStepScale = ns,
            RemoteSmoothing = nm,
        };
    }
}
