using System;
using System.Buffers.Binary;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Animation;

/// <summary>
/// An event carried by one frame of an animation (retail <c>CAnimHook</c>, CAnimHook.c): when a playing
/// <see cref="AnimSequence"/> crosses the frame in a matching <see cref="Direction"/>, the hook is queued on the object
/// (<see cref="PhysicsObj.AddAnimHook"/>) and runs in the object's next <c>process_hooks</c>. The physics hooks (scale,
/// translucency, luminosity, diffusion, ethereal, omega, physics scripts, animation done) run in the library and are
/// internal types; the others are public and handed to <see cref="World.PhysicsWorld.AnimHookListener"/>. The library reads
/// hooks (as part of an animation) and writes none.
/// </summary>
/// <remarks>A hook belongs to its animation and is shared by every object that plays it: it holds no per-object state.</remarks>
public abstract class AnimHook : IAnimHook
{
    private protected AnimHook()
    {
    }

    /// <summary>The hook's kind (retail <c>GetType</c>).</summary>
    public abstract AnimHookType HookType { get; }

    /// <summary>When the hook fires (retail <c>direction_</c>, read from the data; <see cref="AnimHookDirection.Unknown"/>
    /// before that). Any value the data holds is kept: one other than both (0), forward (1) or backward (-1) never fires.</summary>
    public AnimHookDirection Direction { get; internal set; } = AnimHookDirection.Unknown;

    /// <summary>The next hook of the same animation frame (retail <c>next_hook</c>), or null.</summary>
    public AnimHook? Next { get; private set; }

    /// <summary>Runs the hook on <paramref name="obj"/> (retail <c>Execute</c>). Called from the object's hook processing.</summary>
    public abstract void Execute(PhysicsObj obj);

    // The hook's own fields (retail: the type's UnPack).
    private protected abstract void UnPackBody(ref RetailDataReader reader);

    /// <summary>Hands the hook to the world's <see cref="IAnimHookListener"/>, if any (the client-side hooks' Execute).</summary>
    private protected void Notify(PhysicsObj obj) => obj.World.AnimHookListener?.OnAnimHook(obj, this);

    /// <summary>Appends this hook at the end of the list that starts at <paramref name="start"/>.</summary>
    // retail: CAnimHook::add_to_list (acclient.c:342124)
    internal void AddToList(ref AnimHook? start)
    {
        AnimHook? h = start;
        if (h is not null)
        {
            while (h.Next is not null)
            {
                h = h.Next;
            }

            h.Next = this;
        }
        else
        {
            start = this;
        }
    }

    /// <summary>
    /// Reads one hook: its type word, its direction word, the type's fields, then the padding to a multiple of four from the
    /// start of the entry (retail <c>CAnimHook::UnPackHook</c> and <c>PackObj::ALIGN_PTR</c>).
    /// </summary>
    /// <exception cref="RetailDataFormatException">Truncated; a type retail does not read (it returned no hook and left the
    /// fields unread, so every later byte was misread); a physics hook's value outside its domain.</exception>
    // retail: CAnimHook::UnPackHook (acclient.c:342736)
    internal static AnimHook UnPackHook(ref RetailDataReader reader)
    {
        int at = reader.Offset;
        uint type = reader.ReadUInt32("CAnimHook type");
        int direction = reader.ReadInt32("CAnimHook direction");
        AnimHook hook = type switch
        {
            0 => new NoOpHook(),
            16 => new NoDrawHook(),
            17 => new DefaultScriptHook(),
            18 => new DefaultScriptPartHook(),
            1 => new SoundHook(),
            2 => new SoundTableHook(),
            5 => new ReplaceObjectHook(),
            20 => new TransparentHook(),
            7 => new TransparentPartHook(),
            9 => new LuminousPartHook(),
            8 => new LuminousHook(),
            11 => new DiffusePartHook(),
            10 => new DiffuseHook(),
            12 => new ScaleHook(),
            13 => new CreateParticleHook(),
            26 => new CreateBlockingParticleHook(),
            14 => new DestroyParticleHook(),
            15 => new StopParticleHook(),
            19 => new CallPesHook(),
            21 => new SoundTweakedHook(),
            22 => new SetOmegaHook(),
            23 => new TextureVelocityHook(),
            24 => new TextureVelocityPartHook(),
            25 => new SetLightHook(),
            3 => new AttackHook(),
            6 => new EtherealHook(),
            // non-retail: retail returns no hook for any other type (4, AnimDone, included) without reading its fields, so
            // the rest of the entry is read out of step; the library refuses the bytes
            _ => throw reader.ErrorAt(at, $"unknown animation hook type {type}"),
        };

        hook.UnPackBody(ref reader);
        hook.Direction = (AnimHookDirection)direction;
        reader.Align4();
        return hook;
    }

    // Reads a float that a physics hook hands to a PhysicsObj setter, which refuses NaN and infinity: a format error here.
    private protected static float ReadFinite(ref RetailDataReader reader, string what) => reader.ReadFiniteSingle(what);

    // Reads a duration a physics hook hands to a PhysicsObj setter (a fade's or a scale's time, CallPES's pause): finite and
    // within the setters' own domain, |t| < 2^40 s (InputLimits.IsClockTimeInDomain, the predicate the setters test), so
    // that the setter never refuses it inside process_hooks: a format error here.
    private protected static float ReadDuration(ref RetailDataReader reader, string what)
    {
        int at = reader.Offset;
        float t = reader.ReadFiniteSingle(what);
        // non-retail: retail takes any float; a duration of 2^40 s or more made every tick crossing the hook's frame throw
        if (!Spatial.InputLimits.IsClockTimeInDomain(t))
        {
            throw reader.ErrorAt(at, $"{what} {t} s is outside ±2^40 s");
        }

        return t;
    }
}
