// PhysicsObj — the hook list: add_anim_hook, process_hooks, process_fp_hook, Hook_AnimDone, SetScale, SetTranslucency, CallPES.
using System;
using AcDream.Core.Physics.Animation;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Objects;

public sealed partial class PhysicsObj
{
    private IAnimHook?[] _animHooks = Array.Empty<IAnimHook?>();
    private int _animHookCount;

    /// <summary>Newest hook in the object's list (retail <c>hooks</c>), or null.</summary>
    public PhysicsObjHook? Hooks { get; private set; }

    /// <summary>Number of anim hooks waiting for the next <c>process_hooks</c>.</summary>
    public int PendingAnimHookCount => _animHookCount;

    /// <summary>Pushes <paramref name="hook"/> at the head of the hook list: it runs first at the next step.</summary>
    /// <exception cref="ArgumentException">The hook already belongs to an object.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    public void AddHook(PhysicsObjHook hook)
    {
        ThrowIfRemoved();
        ArgumentNullException.ThrowIfNull(hook);
        if (hook.Owner is not null)
        {
            throw new ArgumentException("The hook already belongs to an object.", nameof(hook));
        }

        Touch();

        hook.Owner = this;
        hook.Prev = null;
        PhysicsObjHook? head = Hooks;
        if (head is not null)
        {
            head.Prev = hook;
        }

        hook.Next = head;
        Hooks = hook;
    }

    /// <summary>Queues a one-shot animation event for the next <c>process_hooks</c> (the bag grows by doubling, from 8).</summary>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::add_anim_hook (acclient.c:322062)
    public void AddAnimHook(IAnimHook hook)
    {
        ThrowIfRemoved();
        ArgumentNullException.ThrowIfNull(hook);
        Touch();
        if (_animHookCount == _animHooks.Length)
        {
            Array.Resize(ref _animHooks, _animHooks.Length == 0 ? 8 : _animHooks.Length * 2);
        }

        _animHooks[_animHookCount++] = hook;
    }

    /// <summary>
    /// Runs every hook, newest first, removing each one whose Execute reports done; then runs and clears the anim hooks.
    /// </summary>
    // retail: CPhysicsObj::process_hooks (acclient.c:318640)
    internal void ProcessHooks()
    {
        PhysicsObjHook? h = Hooks;
        while (h is not null)
        {
            // Read before Execute: a hook added during Execute goes to the head and waits for the next step.
            PhysicsObjHook? next = h.Next;
            bool done = h.Execute(this);
            // non-retail: Execute removed the object from its world, which emptied the list (pooled hooks are back in the
            // pool): the walk stops rather than run or return those hooks again
            if (h.Owner != this)
            {
                return;
            }

            if (done)
            {
                UnlinkHook(h);
                h.OnRemoved(World);
            }

            h = next;
        }

        int n = _animHookCount;
        if (n > 0)
        {
            int ran = 0;
            try
            {
                // non-retail: retail re-reads the growing count, so an anim hook queued by an anim hook ran in the same pass
                // (and a hook that re-queues itself never returned); the hooks queued during the pass wait for the next step
                while (ran < n)
                {
                    IAnimHook hook = _animHooks[ran]!;
                    // Counted before Execute: a one-shot hook that throws has run and is dropped with the others (the finally),
                    // so the exception reaches the client once and the next step does not run the hook again.
                    ran++;
                    hook.Execute(this);
                    // non-retail: Execute removed the object from its world, which dropped the queue
                    if (RemovedFromWorld)
                    {
                        return;
                    }
                }
            }
            finally
            {
                // non-retail: the hooks that ran leave the queue also when one threw (try/finally costs nothing when none does)
                if (!RemovedFromWorld)
                {
                    DropRunAnimHooks(ran);
                }
            }
        }
    }

    // Retail shrinks the array to its count, then empties it; we keep the capacity so the tick does not allocate, and move the
    // hooks queued during the pass to the front.
    private void DropRunAnimHooks(int ran)
    {
        int queued = _animHookCount - ran;
        Array.Copy(_animHooks, ran, _animHooks, 0, queued);
        Array.Clear(_animHooks, queued, ran);
        _animHookCount = queued;
    }

    /// <summary>Applies one interpolated hook value to the object or its parts.</summary>
    /// <exception cref="ArgumentException">The value is NaN or infinite, or a scale outside [0.01, 100] (state unchanged).</exception>
    // retail: CPhysicsObj::process_fp_hook (acclient.c:320571)
    internal void ProcessFPHook(PhysicsHookType type, float value, uint userData)
    {
        ThrowIfNotFinite(value, 0.0);
        if (type == PhysicsHookType.Scale)
        {
            InputLimits.ThrowIfScaleOutside(value, nameof(value));
        }

        Touch();
        switch (type)
        {
            case PhysicsHookType.Scale:
                SetScaleStatic(value);
                break;
            case PhysicsHookType.Translucency:
                SetTranslucencyInternal(value);
                break;
            case PhysicsHookType.PartTranslucency:
                PartArray?.SetPartTranslucency(userData, value);
                break;
            case PhysicsHookType.Luminosity:
                PartArray?.SetLuminosity(value);
                break;
            case PhysicsHookType.PartLuminosity:
                PartArray?.SetPartLuminosity(userData, value);
                break;
            case PhysicsHookType.Diffusion:
                PartArray?.SetDiffusion(value);
                break;
            case PhysicsHookType.PartDiffusion:
                PartArray?.SetPartDiffusion(userData, value);
                break;
            case PhysicsHookType.CallPes:
                CallPesInternal(userData, value);
                break;
            default:
                break;
        }
    }

    /// <summary>Scales the object to <paramref name="scale"/> now, or over <paramref name="delta"/> seconds of physics clock
    /// when delta &gt;= EPSILON.</summary>
    /// <param name="scale">The target scale: in [<see cref="InputLimits.MinScale"/>, <see cref="InputLimits.MaxScale"/>] =
    /// [0.01, 100] (a fade passes only through values between the current scale and this one).</param>
    /// <param name="delta">Fade duration, seconds: finite (below EPSILON: at once).</param>
    /// <exception cref="ArgumentException">The scale is outside [0.01, 100] (also NaN, ±∞, 0, negative) or the duration is
    /// not finite (state unchanged; retail accepts any).</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::SetScale (acclient.c:320621)
    public void SetScale(float scale, double delta)
    {
        ThrowIfRemoved();
        ThrowIfNotFinite(scale, delta);
        // non-retail: the scale's domain (a non-positive scale made every later sweep throw)
        InputLimits.ThrowIfScaleOutside(scale, nameof(scale));
        Touch();
        if (delta >= PhysicsGlobals.Epsilon)
        {
            AddFPHook(PhysicsHookType.Scale, delta, Scale, scale, 0);
        }
        else
        {
            SetScaleStatic(scale);
        }
    }

    /// <summary>Sets the scale at once (retail <c>SetScaleStatic</c>).</summary>
    /// <param name="scale">The scale: in [<see cref="InputLimits.MinScale"/>, <see cref="InputLimits.MaxScale"/>] = [0.01, 100].</param>
    /// <exception cref="ArgumentException">The scale is outside [0.01, 100] (also NaN, ±∞, 0, negative); state unchanged.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::SetScaleStatic (acclient.c:319007)
    public void SetScaleStatic(float scale)
    {
        ThrowIfRemoved();
        // non-retail: the scale's domain (a non-positive scale made every later sweep throw)
        InputLimits.ThrowIfScaleOutside(scale, nameof(scale));
        Touch();
        PartArray?.SetScale(scale);
        Scale = scale;
        SyncObstacleSummary();
    }

    /// <summary>Fades the translucency from 0 to <paramref name="translucency"/> over <paramref name="delta"/> seconds (retail
    /// starts every such fade at 0), or sets it at once when delta &lt; EPSILON.</summary>
    /// <exception cref="ArgumentException">An argument is NaN or infinite.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::SetTranslucency (acclient.c:318693)
    public void SetTranslucency(float translucency, double delta)
    {
        ThrowIfRemoved();
        ThrowIfNotFinite(translucency, delta);
        Touch();
        if (delta >= PhysicsGlobals.Epsilon)
        {
            AddFPHook(PhysicsHookType.Translucency, delta, 0.0f, translucency, 0);
        }
        else
        {
            SetTranslucencyInternal(translucency);
        }
    }

    /// <summary>Fades the translucency from <paramref name="start"/> to <paramref name="end"/> over <paramref name="delta"/> seconds.</summary>
    /// <exception cref="ArgumentException">An argument is NaN or infinite.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::SetTranslucency2 (acclient.c:316920)
    public void SetTranslucency2(float start, float end, double delta)
    {
        ThrowIfRemoved();
        ThrowIfNotFinite(start, delta);
        ThrowIfNotFinite(end, delta);
        Touch();
        if (delta >= PhysicsGlobals.Epsilon)
        {
            AddFPHook(PhysicsHookType.Translucency, delta, start, end, 0);
        }
        else
        {
            SetTranslucencyInternal(end);
        }
    }

    /// <summary>Sets the translucency at once, never below <see cref="TranslucencyOriginal"/>.</summary>
    /// <exception cref="ArgumentException">The value is NaN or infinite (state unchanged).</exception>
    // retail: CPhysicsObj::SetTranslucencyInternal (acclient.c:316802)
    internal void SetTranslucencyInternal(float translucency)
    {
        ThrowIfNotFinite(translucency, 0.0);
        Touch();
        float t = translucency < (double)_translucencyOriginal ? _translucencyOriginal : translucency;
        Translucency = t;
        PartArray?.SetTranslucency(t);
    }

    /// <summary>Fades one part's translucency (or sets it at once when delta &lt; EPSILON).</summary>
    /// <exception cref="ArgumentException">An argument is NaN or infinite.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::SetPartTranslucency (acclient.c:318758)
    public void SetPartTranslucency(uint part, float start, float end, double delta)
    {
        ThrowIfRemoved();
        FadeOrSet(PhysicsHookType.PartTranslucency, part, start, end, delta);
    }

    /// <summary>Fades the luminosity (or sets it at once when delta &lt; EPSILON).</summary>
    /// <exception cref="ArgumentException">An argument is NaN or infinite.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::SetLuminosity (acclient.c:318826)
    public void SetLuminosity(float start, float end, double delta)
    {
        ThrowIfRemoved();
        FadeOrSet(PhysicsHookType.Luminosity, 0, start, end, delta);
    }

    /// <summary>Fades one part's luminosity (or sets it at once when delta &lt; EPSILON).</summary>
    /// <exception cref="ArgumentException">An argument is NaN or infinite.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::SetPartLuminosity (acclient.c:318792)
    public void SetPartLuminosity(uint part, float start, float end, double delta)
    {
        ThrowIfRemoved();
        FadeOrSet(PhysicsHookType.PartLuminosity, part, start, end, delta);
    }

    /// <summary>Fades the diffusion (or sets it at once when delta &lt; EPSILON).</summary>
    /// <exception cref="ArgumentException">An argument is NaN or infinite.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::SetDiffusion (acclient.c:318894)
    public void SetDiffusion(float start, float end, double delta)
    {
        ThrowIfRemoved();
        FadeOrSet(PhysicsHookType.Diffusion, 0, start, end, delta);
    }

    /// <summary>Fades one part's diffusion (or sets it at once when delta &lt; EPSILON).</summary>
    /// <exception cref="ArgumentException">An argument is NaN or infinite.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::SetPartDiffusion (acclient.c:318860)
    public void SetPartDiffusion(uint part, float start, float end, double delta)
    {
        ThrowIfRemoved();
        FadeOrSet(PhysicsHookType.PartDiffusion, part, start, end, delta);
    }

    /// <summary>
    /// Plays physics script <paramref name="scriptId"/> after a random delay in [0, <paramref name="delta"/>] seconds, or at once
    /// when delta &lt; EPSILON (only while the object is in a cell).
    /// </summary>
    /// <exception cref="ArgumentException"><paramref name="delta"/> is NaN or infinite.</exception>
    /// <exception cref="InvalidOperationException">The object was removed from its world.</exception>
    // retail: CPhysicsObj::CallPES (acclient.c:318972)
    public void CallPes(uint scriptId, double delta)
    {
        ThrowIfRemoved();
        ThrowIfNotFinite(0f, delta);
        Touch();
        if (delta >= PhysicsGlobals.Epsilon)
        {
            float upper = (float)delta;
            float randomDelay = World.RollDice(0.0f, upper);
            AddFPHook(PhysicsHookType.CallPes, randomDelay, 0.0f, 1.0f, scriptId);
        }
        else if (CellId != 0)
        {
            World.ScriptPlayer?.PlayScript(this, scriptId);
        }
    }

    // retail: CPhysicsObj::CallPESInternal (acclient.c:318962)
    private void CallPesInternal(uint scriptId, float value)
    {
        if (value >= 1.0f && CellId != 0)
        {
            World.ScriptPlayer?.PlayScript(this, scriptId);
        }
    }

    private void FadeOrSet(PhysicsHookType type, uint part, float start, float end, double delta)
    {
        ThrowIfNotFinite(start, delta);
        ThrowIfNotFinite(end, delta);
        if (delta >= PhysicsGlobals.Epsilon)
        {
            AddFPHook(type, delta, start, end, part);
        }
        else
        {
            ProcessFPHook(type, end, part);
        }
    }

    private void AddFPHook(PhysicsHookType type, double delta, float start, float end, uint userData)
    {
        // non-retail: the scene's declared effects (retail always adds the hook)
        if ((World.Effects & SceneEffects.Hooks) == 0)
        {
            // A scene without hooks never walks a hook list: the fade takes its end value at once (no hook is created, so
            // none can pile up unprocessed).
            ProcessFPHook(type, end, userData);
            return;
        }

        // non-retail: an object removed from its world is never ticked again, so a fade on it would hold a pooled hook for
        // ever; it takes its end value at once instead.
        if (RemovedFromWorld)
        {
            ProcessFPHook(type, end, userData);
            return;
        }

        FPHook hook = World.RentFPHook(type, World.PhysicsTime, delta, start, end, userData);
        AddHook(hook);
    }

    private void UnlinkHook(PhysicsObjHook h)
    {
        PhysicsObjHook? next = h.Next;
        PhysicsObjHook? prev = h.Prev;
        if (next is not null)
        {
            next.Prev = prev;
        }

        if (prev is not null)
        {
            prev.Next = next;
        }
        else
        {
            Hooks = next;
        }

        h.Prev = null;
        h.Next = null;
        h.Owner = null;
    }

    internal void ClearHooksOnRemove()
    {
        PhysicsObjHook? h = Hooks;
        while (h is not null)
        {
            PhysicsObjHook? next = h.Next;
            UnlinkHook(h);
            h.OnRemoved(World);
            h = next;
        }

        Array.Clear(_animHooks, 0, _animHookCount);
        _animHookCount = 0;
    }

    // non-retail: a fade's duration is a span of the physics clock, so it has the clock's domain (|delta| < 2^40 s); a
    // longer one overflowed the float duration of CallPES's random delay to infinity
    private static void ThrowIfNotFinite(float value, double delta)
    {
        if (!float.IsFinite(value) || !InputLimits.IsClockTimeInDomain(delta))
        {
            throw new ArgumentException("Hook values must be finite and durations within ±2^40 s.");
        }
    }

    /// <summary>The sequence's AnimDone hook ran: the part array is told one animation finished.</summary>
    // retail: CPhysicsObj::Hook_AnimDone (acclient.c:317086)
    internal void HookAnimDone()
    {
        if (PartArray is IAnimationDoneTarget target)
        {
            target.AnimationDone(true);
        }
    }

    /// <summary>The anim hooks waiting for the next <c>process_hooks</c>, in queue order (for tests and diagnostics).</summary>
    internal ReadOnlySpan<IAnimHook?> PendingAnimHooks => _animHooks.AsSpan(0, _animHookCount);
}
