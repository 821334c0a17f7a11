using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Animation;

/// <summary>
/// The client's side of the animation hooks the library cannot run itself: sounds, particles, scripts, attacks, lights,
/// texture velocity, no-draw (retail calls the client's sound, particle and weenie systems from these hooks'
/// <c>Execute</c>). Set on <see cref="World.PhysicsWorld.AnimHookListener"/>. <see cref="ReplaceObjectHook"/> and
/// <see cref="NoOpHook"/> never reach it: their retail <c>Execute</c> does nothing.
/// </summary>
public interface IAnimHookListener
{
    /// <summary>
    /// <paramref name="hook"/> fired on <paramref name="obj"/> (in the object's <c>process_hooks</c>, in the order the sequence
    /// crossed the frames). Switch on <see cref="AnimHook.HookType"/> and read the hook's properties. Called inside the tick:
    /// must not allocate. The hook is immutable and belongs to its animation (every object playing it shares it).
    /// </summary>
    void OnAnimHook(PhysicsObj obj, AnimHook hook);
}
