using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.World;

/// <summary>
/// How a world slices time for <c>update_object</c>, and the fidelity switches the accuracy-versus-cost report measures.
/// Two named profiles exist: <see cref="Retail"/> (the default, the retail client) and <see cref="AceCompatible"/> (the ACE
/// server emulator's deliberate changes). Immutable; <see cref="With"/> derives a profile with other fidelity switches
/// (their defaults are retail's; see <c>PhysicsProfile.Fidelity.cs</c>).
/// </summary>
public sealed partial class PhysicsProfile
{
    /// <summary>
    /// The retail client: <c>update_object</c> ignores a dt at or below EPSILON, runs one step when dt &lt;= MaxQuantum
    /// (0.2 s), slices longer frames into 0.2 s steps and runs the remainder only above MinQuantum (1/30 s)
    /// (acclient.c:323080). The world ticks once at least MinQuantum has passed (<c>CPhysics::UseTime</c>, acclient.c:311334).
    /// </summary>
    public static readonly PhysicsProfile Retail = new(
        "Retail", accumulateBelowMinQuantum: false, PhysicsGlobals.MaxQuantum, PhysicsGlobals.MinQuantum, PhysicsGlobals.HugeQuantum);

    /// <summary>
    /// ACE's server port: <c>update_object</c> returns early while dt &lt; 1/30 s WITHOUT consuming time (so time accumulates
    /// until a 30 Hz step is due), and slices at 0.1 s instead of 0.2 s. Everything else is retail.
    /// </summary>
    /// <remarks>ACE stores 0.1 and 1/30 as floats; we keep the double values (the difference is below 1.5e-9 s).</remarks>
    public static readonly PhysicsProfile AceCompatible = new(
        "AceCompatible", accumulateBelowMinQuantum: true, PhysicsGlobals.AceMaxQuantum, PhysicsGlobals.MinQuantum, PhysicsGlobals.HugeQuantum);

    private PhysicsProfile(string name, bool accumulateBelowMinQuantum, double maxQuantum, double minQuantum, double hugeQuantum)
    {
        Name = name;
        AccumulateBelowMinQuantum = accumulateBelowMinQuantum;
        MaxQuantum = maxQuantum;
        MinQuantum = minQuantum;
        HugeQuantum = hugeQuantum;
    }

    /// <summary>The profile's name.</summary>
    public string Name { get; }

    /// <summary>
    /// False (retail): a dt at or below EPSILON is consumed without a step. True (ACE): a dt below <see cref="MinQuantum"/>
    /// returns early and is kept, so it adds up with the next frame.
    /// </summary>
    public bool AccumulateBelowMinQuantum { get; }

    /// <summary>Longest single step, seconds (retail 0.2, ACE 0.1).</summary>
    public double MaxQuantum { get; }

    /// <summary>Shortest remainder that is simulated after slicing, and the world's tick period, seconds (1/30).</summary>
    public double MinQuantum { get; }

    /// <summary>Longest frame that is simulated at all, seconds (2.0).</summary>
    public double HugeQuantum { get; }

    /// <inheritdoc />
    public override string ToString() => Name;

    private PhysicsProfile(PhysicsProfile basis, string name)
        : this(name, basis.AccumulateBelowMinQuantum, basis.MaxQuantum, basis.MinQuantum, basis.HugeQuantum)
    {
        Arithmetic = basis.Arithmetic;
        RenormaliseEvery = basis.RenormaliseEvery;
        SweepStepScale = basis.SweepStepScale;
        RemoteSmoothing = basis.RemoteSmoothing;
    }
}
