using System.Numerics;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Animation;

// The hooks the client runs (retail: their Execute calls the sound, particle, script, weenie and drawing systems): each is
// handed to PhysicsWorld.AnimHookListener with the fields retail reads.

/// <summary>Does nothing (retail <c>NOOPHook</c>).</summary>
public sealed class NoOpHook : AnimHook
{
    internal NoOpHook()
    {
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.NoOp;

    /// <inheritdoc />
    // retail: NOOPHook::Execute (0x00508950, 3 bytes: ret 4; no acclient.c body)
    public override void Execute(PhysicsObj obj)
    {
    }

    // Folded with DefaultScriptHook::UnPack: reads nothing.
    // retail: DefaultScriptHook::UnPack (acclient.c:339664)
    private protected override void UnPackBody(ref RetailDataReader reader)
    {
    }
}

/// <summary>Plays sound <see cref="SoundId"/> (retail <c>SoundHook</c>: <c>SoundManager::PlaySound</c>).</summary>
public sealed class SoundHook : AnimHook
{
    // retail: SoundHook::SoundHook (acclient.c:342177)
    internal SoundHook()
    {
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.Sound;

    /// <summary>The sound's data id (retail <c>gid_</c>).</summary>
    public uint SoundId { get; private set; }

    /// <inheritdoc />
    // retail: SoundHook::Execute (acclient.c:342187)
    public override void Execute(PhysicsObj obj) => Notify(obj);

    // Retail also asks the sound manager to load the sound (SoundManager::CreateSound); that is the client's.
    // retail: SoundHook::UnPack (acclient.c:343067)
    private protected override void UnPackBody(ref RetailDataReader reader) => SoundId = reader.ReadUInt32("SoundHook gid");
}

/// <summary>Plays the sound of type <see cref="SoundType"/> from the object's sound table (retail <c>SoundTableHook</c>).</summary>
public sealed class SoundTableHook : AnimHook
{
    internal SoundTableHook()
    {
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.SoundTable;

    /// <summary>The sound type (retail <c>sound_type_</c>).</summary>
    public uint SoundType { get; private set; }

    /// <inheritdoc />
    // retail: SoundTableHook::Execute (acclient.c:342218)
    public override void Execute(PhysicsObj obj) => Notify(obj);

    // retail: SoundTableHook::UnPack (acclient.c:342237)
    private protected override void UnPackBody(ref RetailDataReader reader) => SoundType = reader.ReadUInt32("SoundTableHook sound_type");
}

/// <summary>Plays sound <see cref="SoundId"/> with a priority, probability and volume (retail <c>SoundTweakedHook</c>).</summary>
public sealed class SoundTweakedHook : AnimHook
{
    // retail: SoundTweakedHook::SoundTweakedHook (acclient.c:342193)
    internal SoundTweakedHook()
    {
        Priority = 0.89999998f; // 0x3F666666
        Probability = 1f;
        Volume = 1f;
    }

    /// <inheritdoc />
    // SoundTweakedHook::GetType returns 21, folded with DBFile2IDTable::GetDBOType.
    // retail: DBFile2IDTable::GetDBOType (acclient.c:290357)
    public override AnimHookType HookType => AnimHookType.SoundTweaked;

    /// <summary>The sound's data id (retail <c>gid_</c>).</summary>
    public uint SoundId { get; private set; }

    /// <summary>Priority (retail <c>prio</c>).</summary>
    public float Priority { get; private set; }

    /// <summary>Probability of playing (retail <c>prob</c>).</summary>
    public float Probability { get; private set; }

    /// <summary>Volume (retail <c>vol</c>).</summary>
    public float Volume { get; private set; }

    /// <inheritdoc />
    // retail: SoundTweakedHook::Execute (acclient.c:342206)
    public override void Execute(PhysicsObj obj) => Notify(obj);

    // The order is id, probability, priority, volume.
    // retail: SoundTweakedHook::UnPack (acclient.c:343122)
    private protected override void UnPackBody(ref RetailDataReader reader)
    {
        SoundId = reader.ReadUInt32("SoundTweakedHook gid");
        Probability = reader.ReadSingle("SoundTweakedHook prob");
        Priority = reader.ReadSingle("SoundTweakedHook prio");
        Volume = reader.ReadSingle("SoundTweakedHook vol");
    }
}

/// <summary>The attack cone of an attack hook (retail <c>AttackCone</c>): a part, two directions in the horizontal plane, a
/// radius and a height.</summary>
public readonly record struct AttackCone(int PartIndex, Vector2 Left, Vector2 Right, float Radius, float Height);

/// <summary>An attack (retail <c>AttackHook</c>: <c>CPhysicsObj::attack</c>, the weenie's).</summary>
public sealed class AttackHook : AnimHook
{
    // retail: AttackHook::AttackHook (acclient.c:342002)
    internal AttackHook()
    {
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.Attack;

    /// <summary>The attack cone (retail <c>attack_cone</c>).</summary>
    public AttackCone Cone { get; private set; }

    /// <inheritdoc />
    // retail: AttackHook::Execute (acclient.c:342281)
    public override void Execute(PhysicsObj obj) => Notify(obj);

    // retail: AttackHook::UnPack (acclient.c:343150)
    private protected override void UnPackBody(ref RetailDataReader reader) => Cone = UnPackCone(ref reader);

    // Vec2D::UnPack (acclient.c:467542) reads x then y.
    // retail: AttackCone::UnPack (acclient.c:342621)
    private static AttackCone UnPackCone(ref RetailDataReader reader)
    {
        int part = reader.ReadInt32("AttackCone part_index");
        float lx = reader.ReadSingle("AttackCone left"), ly = reader.ReadSingle("AttackCone left");
        float rx = reader.ReadSingle("AttackCone right"), ry = reader.ReadSingle("AttackCone right");
        float radius = reader.ReadSingle("AttackCone radius");
        float height = reader.ReadSingle("AttackCone height");
        return new AttackCone(part, new Vector2(lx, ly), new Vector2(rx, ry), radius, height);
    }
}

/// <summary>Names a part and a replacement GfxObj (retail <c>ReplaceObjectHook</c>, an <c>AnimPartChange</c>) and, as in retail,
/// does nothing when it fires: its <c>Execute</c> is the shared <c>ret 4</c> of <c>NOOPHook::Execute</c>, so
/// <see cref="IAnimHookListener"/> never receives it. A client that wants part swaps reads <see cref="PartIndex"/> and
/// <see cref="PartId"/> from <see cref="AnimFrame.Hooks"/> itself (a non-retail use of the data).</summary>
public sealed class ReplaceObjectHook : AnimHook
{
    // retail: ReplaceObjectHook::ReplaceObjectHook (acclient.c:342642)
    internal ReplaceObjectHook()
    {
    }

    /// <inheritdoc />
    // retail: ReplaceObjectHook::GetType (acclient.c:342657)
    public override AnimHookType HookType => AnimHookType.ReplaceObject;

    /// <summary>The part's index (a byte in the data).</summary>
    public uint PartIndex { get; private set; }

    /// <summary>The new part's GfxObj data id (0x01000000 plus the packed value).</summary>
    public uint PartId { get; private set; }

    /// <summary>Does nothing (retail: <c>ReplaceObjectHook::Execute</c> shares address 0x00508950 and its 3-byte body, a lone
    /// <c>ret 4</c>, with <c>NOOPHook::Execute</c> in the PDB).</summary>
    // retail: ReplaceObjectHook::Execute (0x00508950, 3 bytes, shared with NOOPHook::Execute: ret 4; no acclient.c body)
    public override void Execute(PhysicsObj obj)
    {
    }

    // ReplaceObjectHook::UnPack is AnimPartChange::UnPack (acclient.c:471698): the part index byte, then the id packed as
    // Unpack_AsDataIDOfKnownType (acclient.c:667731) with the GfxObj base 0x01000000.
    // retail: ReplaceObjectHook::UnPack (acclient.c:342266)
    private protected override void UnPackBody(ref RetailDataReader reader)
    {
        PartIndex = reader.ReadByte("AnimPartChange part_index");
        ushort first = reader.ReadUInt16("AnimPartChange part_id");
        if ((first & 0x8000) == 0)
        {
            PartId = 0x01000000u + first;
        }
        else
        {
            ushort second = reader.ReadUInt16("AnimPartChange part_id");
            PartId = 0x01000000u + (second | ((uint)(first & 0x3FFF) << 16));
        }
    }
}

/// <summary>Creates a particle emitter on a part (retail <c>CreateParticleHook</c>).</summary>
public class CreateParticleHook : AnimHook
{
    // retail: CreateParticleHook::CreateParticleHook (acclient.c:342678)
    internal CreateParticleHook()
    {
        Offset = Frame.Identity;
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.CreateParticle;

    /// <summary>The emitter's data id (retail <c>emitter_info_id</c>).</summary>
    public uint EmitterInfoId { get; private set; }

    /// <summary>The part it is attached to (retail <c>part_index</c>).</summary>
    public uint PartIndex { get; private set; }

    /// <summary>The emitter's frame relative to the part (retail <c>offset</c>).</summary>
    public Frame Offset { get; private set; }

    /// <summary>The emitter's id, to destroy or stop it later (retail <c>emitter_id</c>).</summary>
    public uint EmitterId { get; private set; }

    /// <inheritdoc />
    // retail: CreateParticleHook::Execute (acclient.c:342512)
    public override void Execute(PhysicsObj obj) => Notify(obj);

    // The offset is Frame::UnPack (acclient.c:357132): origin, then w, x, y, z.
    // retail: CreateParticleHook::UnPack (acclient.c:343212)
    private protected override void UnPackBody(ref RetailDataReader reader)
    {
        EmitterInfoId = reader.ReadUInt32("CreateParticleHook emitter_info_id");
        PartIndex = reader.ReadUInt32("CreateParticleHook part_index");
        Offset = reader.ReadFrame("CreateParticleHook offset");
        EmitterId = reader.ReadUInt32("CreateParticleHook emitter_id");
    }
}

/// <summary>Creates a blocking particle emitter (retail <c>CreateBlockingParticleHook</c>, a create-particle hook).</summary>
public sealed class CreateBlockingParticleHook : CreateParticleHook
{
    // retail: CreateBlockingParticleHook::CreateBlockingParticleHook (acclient.c:342706)
    internal CreateBlockingParticleHook()
    {
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.CreateBlockingParticle;

    /// <inheritdoc />
    // retail: CreateBlockingParticleHook::Execute (acclient.c:342524)
    public override void Execute(PhysicsObj obj) => Notify(obj);
}

/// <summary>Destroys particle emitter <see cref="EmitterId"/> (retail <c>DestroyParticleHook</c>).</summary>
public sealed class DestroyParticleHook : AnimHook
{
    internal DestroyParticleHook()
    {
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.DestroyParticle;

    /// <summary>The emitter's id.</summary>
    public uint EmitterId { get; private set; }

    /// <inheritdoc />
    // retail: DestroyParticleHook::Execute (acclient.c:342535)
    public override void Execute(PhysicsObj obj) => Notify(obj);

    // retail: DestroyParticleHook::UnPack (acclient.c:342303)
    private protected override void UnPackBody(ref RetailDataReader reader) => EmitterId = reader.ReadUInt32("DestroyParticleHook emitter_id");
}

/// <summary>Stops particle emitter <see cref="EmitterId"/> (retail <c>StopParticleHook</c>).</summary>
public sealed class StopParticleHook : AnimHook
{
    internal StopParticleHook()
    {
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.StopParticle;

    /// <summary>The emitter's id.</summary>
    public uint EmitterId { get; private set; }

    /// <inheritdoc />
    // retail: StopParticleHook::Execute (acclient.c:342541)
    public override void Execute(PhysicsObj obj) => Notify(obj);

    // retail: DestroyParticleHook::UnPack (acclient.c:342303)
    private protected override void UnPackBody(ref RetailDataReader reader) => EmitterId = reader.ReadUInt32("StopParticleHook emitter_id");
}

/// <summary>Hides or shows the object (retail <c>NoDrawHook</c>: <c>CPhysicsObj::set_nodraw</c>).</summary>
public sealed class NoDrawHook : AnimHook
{
    internal NoDrawHook()
    {
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.NoDraw;

    /// <summary>True to hide the object (retail <c>_no_draw</c>, non-zero).</summary>
    public bool NoDraw { get; private set; }

    /// <inheritdoc />
    // retail: NoDrawHook::Execute (acclient.c:342317)
    public override void Execute(PhysicsObj obj) => Notify(obj);

    // retail: DestroyParticleHook::UnPack (acclient.c:342303)
    private protected override void UnPackBody(ref RetailDataReader reader) => NoDraw = reader.ReadInt32("NoDrawHook no_draw") != 0;
}

/// <summary>Plays the object's default script (retail <c>DefaultScriptHook</c>).</summary>
public sealed class DefaultScriptHook : AnimHook
{
    internal DefaultScriptHook()
    {
    }

    /// <inheritdoc />
    // DefaultScriptHook::GetType returns 17, folded with UIElement_GroupBox::GetUIElementType.
    // retail: UIElement_GroupBox::GetUIElementType (acclient.c:297797)
    public override AnimHookType HookType => AnimHookType.DefaultScript;

    /// <inheritdoc />
    // retail: DefaultScriptHook::Execute (acclient.c:342329)
    public override void Execute(PhysicsObj obj) => Notify(obj);

    // retail: DefaultScriptHook::UnPack (acclient.c:339664)
    private protected override void UnPackBody(ref RetailDataReader reader)
    {
    }
}

/// <summary>Plays the default script on part <see cref="PartIndex"/> (retail <c>DefaultScriptPartHook</c>).</summary>
public sealed class DefaultScriptPartHook : AnimHook
{
    internal DefaultScriptPartHook()
    {
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.DefaultScriptPart;

    /// <summary>The part's index.</summary>
    public uint PartIndex { get; private set; }

    /// <inheritdoc />
    // retail: DefaultScriptPartHook::Execute (acclient.c:342323)
    public override void Execute(PhysicsObj obj) => Notify(obj);

    // retail: DestroyParticleHook::UnPack (acclient.c:342303)
    private protected override void UnPackBody(ref RetailDataReader reader) => PartIndex = reader.ReadUInt32("DefaultScriptPartHook part_index");
}

/// <summary>Sets the texture velocity of every part (retail <c>TextureVelocityHook</c>).</summary>
public sealed class TextureVelocityHook : AnimHook
{
    // retail: TextureVelocityHook::TextureVelocityHook (acclient.c:342101)
    internal TextureVelocityHook()
    {
    }

    /// <inheritdoc />
    // TextureVelocityHook::GetType returns 23, folded with MessageDialog::GetUIElementType.
    // retail: MessageDialog::GetUIElementType (acclient.c:342112)
    public override AnimHookType HookType => AnimHookType.TextureVelocity;

    /// <summary>U speed.</summary>
    public float USpeed { get; private set; }

    /// <summary>V speed.</summary>
    public float VSpeed { get; private set; }

    /// <inheritdoc />
    // retail: TextureVelocityHook::Execute (acclient.c:342583)
    public override void Execute(PhysicsObj obj) => Notify(obj);

    // Folded with ScaleHook::UnPack: two words.
    // retail: ScaleHook::UnPack (acclient.c:342499)
    private protected override void UnPackBody(ref RetailDataReader reader)
    {
        USpeed = reader.ReadSingle("TextureVelocityHook u_speed");
        VSpeed = reader.ReadSingle("TextureVelocityHook v_speed");
    }
}

/// <summary>Sets one part's texture velocity (retail <c>TextureVelocityPartHook</c>).</summary>
public sealed class TextureVelocityPartHook : AnimHook
{
    // retail: TextureVelocityPartHook::TextureVelocityPartHook (acclient.c:342083)
    internal TextureVelocityPartHook()
    {
        PartIndex = uint.MaxValue;
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.TextureVelocityPart;

    /// <summary>The part's index.</summary>
    public uint PartIndex { get; private set; }

    /// <summary>U speed.</summary>
    public float USpeed { get; private set; }

    /// <summary>V speed.</summary>
    public float VSpeed { get; private set; }

    /// <inheritdoc />
    // retail: TextureVelocityPartHook::Execute (acclient.c:342553)
    public override void Execute(PhysicsObj obj) => Notify(obj);

    // retail: LuminousHook::UnPack (acclient.c:342371)
    private protected override void UnPackBody(ref RetailDataReader reader)
    {
        PartIndex = reader.ReadUInt32("TextureVelocityPartHook part_index");
        USpeed = reader.ReadSingle("TextureVelocityPartHook u_speed");
        VSpeed = reader.ReadSingle("TextureVelocityPartHook v_speed");
    }
}

/// <summary>Turns the object's lights on or off (retail <c>SetLightHook</c>).</summary>
public sealed class SetLightHook : AnimHook
{
    internal SetLightHook()
    {
    }

    /// <inheritdoc />
    public override AnimHookType HookType => AnimHookType.SetLight;

    /// <summary>True to turn the lights on (retail <c>_lights_on</c>, non-zero).</summary>
    public bool LightsOn { get; private set; }

    /// <inheritdoc />
    // retail: SetLightHook::Execute (acclient.c:342589)
    public override void Execute(PhysicsObj obj) => Notify(obj);

    // retail: DestroyParticleHook::UnPack (acclient.c:342303)
    private protected override void UnPackBody(ref RetailDataReader reader) => LightsOn = reader.ReadInt32("SetLightHook lights_on") != 0;
}
