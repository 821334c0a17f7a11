namespace AcDream.Core.Physics.Animation;

/// <summary>The kind of an <see cref="AnimHook"/>; values are retail's (the anonymous <c>*_HOOK</c> enum, acclient.h:7277,
/// each hook's <c>GetType</c>, and the type word of <c>CAnimHook::UnPackHook</c>).</summary>
public enum AnimHookType
{
    /// <summary>Does nothing (<c>NOOPHook</c>).</summary>
    NoOp = 0x0,

    /// <summary>Plays a sound by id (<c>SoundHook</c>).</summary>
    Sound = 0x1,

    /// <summary>Plays a sound of the object's sound table by type (<c>SoundTableHook</c>).</summary>
    SoundTable = 0x2,

    /// <summary>An attack cone (<c>AttackHook</c>).</summary>
    Attack = 0x3,

    /// <summary>An animation of the sequence finished (<c>AnimDoneHook</c>; fired by the sequence, never read from data).</summary>
    AnimDone = 0x4,

    /// <summary>Replaces a part's object (<c>ReplaceObjectHook</c>).</summary>
    ReplaceObject = 0x5,

    /// <summary>Makes the object ethereal or solid (<c>EtherealHook</c>).</summary>
    Ethereal = 0x6,

    /// <summary>Fades one part's translucency (<c>TransparentPartHook</c>).</summary>
    TransparentPart = 0x7,

    /// <summary>Fades the luminosity (<c>LuminousHook</c>).</summary>
    Luminous = 0x8,

    /// <summary>Fades one part's luminosity (<c>LuminousPartHook</c>).</summary>
    LuminousPart = 0x9,

    /// <summary>Fades the diffusion (<c>DiffuseHook</c>).</summary>
    Diffuse = 0xA,

    /// <summary>Fades one part's diffusion (<c>DiffusePartHook</c>).</summary>
    DiffusePart = 0xB,

    /// <summary>Scales the object (<c>ScaleHook</c>).</summary>
    Scale = 0xC,

    /// <summary>Creates a particle emitter (<c>CreateParticleHook</c>).</summary>
    CreateParticle = 0xD,

    /// <summary>Destroys a particle emitter (<c>DestroyParticleHook</c>).</summary>
    DestroyParticle = 0xE,

    /// <summary>Stops a particle emitter (<c>StopParticleHook</c>).</summary>
    StopParticle = 0xF,

    /// <summary>Hides or shows the object (<c>NoDrawHook</c>).</summary>
    NoDraw = 0x10,

    /// <summary>Plays the object's default script (<c>DefaultScriptHook</c>).</summary>
    DefaultScript = 0x11,

    /// <summary>Plays the default script on one part (<c>DefaultScriptPartHook</c>).</summary>
    DefaultScriptPart = 0x12,

    /// <summary>Plays a physics script (<c>CallPESHook</c>).</summary>
    CallPes = 0x13,

    /// <summary>Fades the translucency (<c>TransparentHook</c>).</summary>
    Transparent = 0x14,

    /// <summary>Plays a sound with priority, probability and volume (<c>SoundTweakedHook</c>).</summary>
    SoundTweaked = 0x15,

    /// <summary>Sets the object's angular velocity (<c>SetOmegaHook</c>).</summary>
    SetOmega = 0x16,

    /// <summary>Sets the texture velocity (<c>TextureVelocityHook</c>).</summary>
    TextureVelocity = 0x17,

    /// <summary>Sets one part's texture velocity (<c>TextureVelocityPartHook</c>).</summary>
    TextureVelocityPart = 0x18,

    /// <summary>Turns the object's lights on or off (<c>SetLightHook</c>).</summary>
    SetLight = 0x19,

    /// <summary>Creates a blocking particle emitter (<c>CreateBlockingParticleHook</c>).</summary>
    CreateBlockingParticle = 0x1A,
}

/// <summary>When an <see cref="AnimHook"/> fires as its frame is crossed (retail <c>CAnimHook::AnimHookDir</c>); values are
/// retail's.</summary>
public enum AnimHookDirection
{
    /// <summary>The default direction a hook is constructed with before its data is read (<c>UNKNOWN_ANIMHOOK</c>, -2):
    /// fires in neither direction.</summary>
    Unknown = -2,

    /// <summary>Only when the frame is crossed playing backwards (<c>BACKWARD_ANIMHOOK</c>).</summary>
    Backward = -1,

    /// <summary>In both directions (<c>BOTH_ANIMHOOK</c>).</summary>
    Both = 0,

    /// <summary>Only when the frame is crossed playing forwards (<c>FORWARD_ANIMHOOK</c>).</summary>
    Forward = 1,
}
