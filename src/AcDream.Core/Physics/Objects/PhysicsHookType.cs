namespace AcDream.Core.Physics.Objects;

/// <summary>
/// What a <see cref="PhysicsObjHook"/> drives (retail <c>PhysicsObjHook::HookType</c>, the cases of
/// <c>CPhysicsObj::process_fp_hook</c>, acclient.c:320571). Values are retail's.
/// </summary>
public enum PhysicsHookType
{
    /// <summary>Object scale (<c>SetScaleStatic</c>).</summary>
    Scale = 0,

    /// <summary>Whole-object translucency (<c>SetTranslucencyInternal</c>).</summary>
    Translucency = 1,

    /// <summary>Translucency of the part named by the hook's user data.</summary>
    PartTranslucency = 2,

    /// <summary>Whole-object luminosity.</summary>
    Luminosity = 3,

    /// <summary>Whole-object diffusion.</summary>
    Diffusion = 4,

    /// <summary>Luminosity of the part named by the hook's user data.</summary>
    PartLuminosity = 5,

    /// <summary>Diffusion of the part named by the hook's user data.</summary>
    PartDiffusion = 6,

    /// <summary>Plays the physics script named by the user data once the value reaches 1 (<c>CallPESInternal</c>).</summary>
    CallPes = 7,
}
