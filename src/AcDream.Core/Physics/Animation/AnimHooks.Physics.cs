using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Animation;

// The hooks the library runs itself (retail: their Execute calls CPhysicsObj's own setters). They are internal: no listener
// receives them (a client walking AnimFrame.Hooks sees them as AnimHook, with their HookType). Each float they hand to a
// setter is read finite (a scale also within InputLimits' scale domain, a duration within ±2^40 s, the setters' own), so
// that the setter, which refuses such values, never throws from inside a tick.

/// <summary>
/// A fade of the whole object from <see cref="Start"/> to <see cref="End"/> over <see cref="Time"/> seconds: what
/// <see cref="TransparentHook"/>, <see cref="LuminousHook"/> and <see cref="DiffuseHook"/> carry (retail's linker folded their
/// <c>Pack</c> and their <c>UnPack</c> into one function each).
/// </summary>
internal abstract class FadeHook : AnimHook
{
    private readonly string _name;

    private protected FadeHook(string name) => _name = name;

    /// <summary>The value at the start of the fade.</summary>
    public float Start { get; private set; }

    /// <summary>The value at the end of the fade.</summary>
    public float End { get; private set; }

    /// <summary>Duration of the fade, seconds.</summary>
    public float Time { get; private set; }

    // Folded by the linker with TransparentHook's, LuminousHook's, DiffuseHook's and TextureVelocityPartHook's UnPack:
    // three 32-bit words.
    // retail: LuminousHook::UnPack (acclient.c:342371)
    private protected override void UnPackBody(ref RetailDataReader reader)
    {
        Start = ReadFinite(ref reader, _name + " start");
        End = ReadFinite(ref reader, _name + " end");
        Time = ReadDuration(ref reader, _name + " time");
    }
}

/// <summary>
/// A fade of one part from <see cref="Start"/> to <see cref="End"/> over <see cref="Time"/> seconds: what
/// <see cref="TransparentPartHook"/>, <see cref="LuminousPartHook"/> and <see cref="DiffusePartHook"/> carry (retail's linker
/// folded their <c>Pack</c> and their <c>UnPack</c> into one function each).
/// </summary>
internal abstract class PartFadeHook : AnimHook
{
    private readonly string _name;

    private protected PartFadeHook(string name) => _name = name;

    /// <summary>The part's index.</summary>
    public uint Part { get; private set; }

    /// <summary>The value at the start of the fade.</summary>
    public float Start { get; private set; }

    /// <summary>The value at the end of the fade.</summary>
    public float End { get; private set; }

    /// <summary>Duration of the fade, seconds.</summary>
    public float Time { get; private set; }

    // Folded by the linker with LuminousPartHook's and DiffusePartHook's UnPack: part, start, end, time.
    // retail: TransparentPartHook::UnPack (acclient.c:342394)
    private protected override void UnPackBody(ref RetailDataReader reader)
    {
        Part = reader.ReadUInt32(_name + " part");
        Start = ReadFinite(ref reader, _name + " start");
        End = ReadFinite(ref reader, _name + " end");
        Time = ReadDuration(ref reader, _name + " time");
    }
}

/// <summary>Fades the object's translucency (retail <c>TransparentHook</c>: <c>CPhysicsObj::SetTranslucency2</c>).</summary>
internal sealed class TransparentHook : FadeHook
{
    internal TransparentHook()
        : base(nameof(TransparentHook))
    {
    }

    /// <inheritdoc />
    // TransparentHook::GetType returns 20.
    // retail: TransparentHook::GetType (acclient.c:665892)
    public override AnimHookType HookType => AnimHookType.Transparent;

    /// <inheritdoc />
    // retail: TransparentHook::Execute (acclient.c:342341)
    public override void Execute(PhysicsObj obj) => obj.SetTranslucency2(Start, End, Time);
}

/// <summary>Fades one part's translucency (retail <c>TransparentPartHook</c>: <c>CPhysicsObj::SetPartTranslucency</c>).</summary>
internal sealed class TransparentPartHook : PartFadeHook
{
    internal TransparentPartHook()
        : base(nameof(TransparentPartHook))
    {
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.TransparentPart;

    /// <inheritdoc />
    // retail: TransparentPartHook::Execute (acclient.c:342388)
    public override void Execute(PhysicsObj obj) => obj.SetPartTranslucency(Part, Start, End, Time);
}

/// <summary>Fades the object's luminosity (retail <c>LuminousHook</c>: <c>CPhysicsObj::SetLuminosity</c>).</summary>
internal sealed class LuminousHook : FadeHook
{
    internal LuminousHook()
        : base(nameof(LuminousHook))
    {
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.Luminous;

    /// <inheritdoc />
    // retail: LuminousHook::Execute (acclient.c:342421)
    public override void Execute(PhysicsObj obj) => obj.SetLuminosity(Start, End, Time);
}

/// <summary>Fades one part's luminosity (retail <c>LuminousPartHook</c>: <c>CPhysicsObj::SetPartLuminosity</c>).</summary>
internal sealed class LuminousPartHook : PartFadeHook
{
    internal LuminousPartHook()
        : base(nameof(LuminousPartHook))
    {
    }

    /// <inheritdoc />
    // retail: LuminousPartHook::GetType (acclient.c:342053)
    public override AnimHookType HookType => AnimHookType.LuminousPart;

    /// <inheritdoc />
    // retail: LuminousPartHook::Execute (acclient.c:342415)
    public override void Execute(PhysicsObj obj) => obj.SetPartLuminosity(Part, Start, End, Time);
}

/// <summary>Fades the object's diffusion (retail <c>DiffuseHook</c>: <c>CPhysicsObj::SetDiffusion</c>).</summary>
internal sealed class DiffuseHook : FadeHook
{
    internal DiffuseHook()
        : base(nameof(DiffuseHook))
    {
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.Diffuse;

    /// <inheritdoc />
    // retail: DiffuseHook::Execute (acclient.c:342461)
    public override void Execute(PhysicsObj obj) => obj.SetDiffusion(Start, End, Time);
}

/// <summary>Fades one part's diffusion (retail <c>DiffusePartHook</c>: <c>CPhysicsObj::SetPartDiffusion</c>).</summary>
internal sealed class DiffusePartHook : PartFadeHook
{
    internal DiffusePartHook()
        : base(nameof(DiffusePartHook))
    {
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.DiffusePart;

    /// <inheritdoc />
    // retail: DiffusePartHook::Execute (acclient.c:342427)
    public override void Execute(PhysicsObj obj) => obj.SetPartDiffusion(Part, Start, End, Time);
}

/// <summary>Scales the object to <see cref="End"/> over <see cref="Time"/> seconds (retail <c>ScaleHook</c>:
/// <c>CPhysicsObj::SetScale</c>).</summary>
internal sealed class ScaleHook : AnimHook
{
    internal ScaleHook()
    {
    }

    /// <inheritdoc />
    // ScaleHook::GetType returns 12, folded with UIElement_Text::GetUIElementType.
    // retail: UIElement_Text::GetUIElementType (acclient.c:713841)
    public override AnimHookType HookType => AnimHookType.Scale;

    /// <summary>The scale at the end, in [0.01, 100].</summary>
    public float End { get; private set; }

    /// <summary>Duration, seconds (below EPSILON: at once).</summary>
    public float Time { get; private set; }

    /// <inheritdoc />
    // retail: ScaleHook::Execute (acclient.c:342473)
    public override void Execute(PhysicsObj obj) => obj.SetScale(End, Time);

    // retail: ScaleHook::UnPack (acclient.c:342499)
    private protected override void UnPackBody(ref RetailDataReader reader)
    {
        int at = reader.Offset;
        float end = ReadFinite(ref reader, "ScaleHook end");
        // non-retail: the scale's domain, as PhysicsObj.SetScale refuses a scale outside it
        if (end < InputLimits.MinScale || end > InputLimits.MaxScale)
        {
            throw reader.ErrorAt(at, $"ScaleHook end {end} is outside [{InputLimits.MinScale}, {InputLimits.MaxScale}]");
        }

        End = end;
        Time = ReadDuration(ref reader, "ScaleHook time");
    }
}

/// <summary>Plays physics script <see cref="ScriptId"/> after a random pause up to <see cref="Pause"/> seconds (retail
/// <c>CallPESHook</c>: <c>CPhysicsObj::CallPES</c>).</summary>
internal sealed class CallPesHook : AnimHook
{
    internal CallPesHook()
    {
    }

    /// <inheritdoc />
    // retail: CallPESHook::GetType (acclient.c:342730)
    public override AnimHookType HookType => AnimHookType.CallPes;

    /// <summary>The physics script's data id (retail <c>pes</c>).</summary>
    public uint ScriptId { get; private set; }

    /// <summary>The longest random pause before it plays, seconds (retail <c>pause</c>).</summary>
    public float Pause { get; private set; }

    /// <inheritdoc />
    // retail: CallPESHook::Execute (acclient.c:342467)
    public override void Execute(PhysicsObj obj) => obj.CallPes(ScriptId, Pause);

    // retail: CallPESHook::UnPack (acclient.c:343176)
    private protected override void UnPackBody(ref RetailDataReader reader)
    {
        ScriptId = reader.ReadUInt32("CallPESHook pes");
        Pause = ReadDuration(ref reader, "CallPESHook pause");
    }
}

/// <summary>Makes the object ethereal or tries to make it solid (retail <c>EtherealHook</c>: <c>CPhysicsObj::set_ethereal</c>).</summary>
internal sealed class EtherealHook : AnimHook
{
    internal EtherealHook()
    {
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.Ethereal;

    /// <summary>True to make the object ethereal (retail <c>ethereal</c>, non-zero).</summary>
    public bool Ethereal { get; private set; }

    /// <inheritdoc />
    // retail: EtherealHook::Execute (acclient.c:342311)
    public override void Execute(PhysicsObj obj) => obj.SetEthereal(Ethereal);

    // Folded with the other one-word hooks' UnPack.
    // retail: DestroyParticleHook::UnPack (acclient.c:342303)
    private protected override void UnPackBody(ref RetailDataReader reader) =>
        Ethereal = reader.ReadInt32("EtherealHook ethereal") != 0;
}

/// <summary>Sets the object's angular velocity, rad/s in world axes (retail <c>SetOmegaHook</c>:
/// <c>CPhysicsObj::set_omega</c>).</summary>
internal sealed class SetOmegaHook : AnimHook
{
    internal SetOmegaHook()
    {
    }

    /// <inheritdoc />
    // SetOmegaHook::GetType returns 22, folded with MenuDialog::GetUIElementType.
    // retail: MenuDialog::GetUIElementType (acclient.c:662530)
    public override AnimHookType HookType => AnimHookType.SetOmega;

    /// <summary>The angular velocity set (retail <c>axis</c>).</summary>
    public Vector3 Axis { get; private set; }

    /// <inheritdoc />
    // retail: SetOmegaHook::Execute (acclient.c:342547)
    public override void Execute(PhysicsObj obj) => obj.SetOmega(Axis);

    // Retail reads the axis only when its size argument is at least 12; the library always reads it (a short entry is a
    // format error).
    // retail: SetOmegaHook::UnPack (acclient.c:343254)
    private protected override void UnPackBody(ref RetailDataReader reader)
    {
        float x = ReadFinite(ref reader, "SetOmegaHook axis");
        float y = ReadFinite(ref reader, "SetOmegaHook axis");
        float z = ReadFinite(ref reader, "SetOmegaHook axis");
        Axis = new Vector3(x, y, z);
    }
}

/// <summary>An animation of the sequence ended while link animations were queued (retail <c>AnimDoneHook</c>, fired by
/// <c>CSequence::update_internal</c>): the object's part array is told (<c>CPhysicsObj::Hook_AnimDone</c>). Never read from
/// data.</summary>
internal sealed class AnimDoneHook : AnimHook
{
    internal AnimDoneHook()
    {
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.AnimDone;

    /// <inheritdoc />
    // retail: AnimDoneHook::Execute (acclient.c:342335)
    public override void Execute(PhysicsObj obj) => obj.HookAnimDone();

    private protected override void UnPackBody(ref RetailDataReader reader)
    {
    }
}
