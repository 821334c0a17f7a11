
namespace AcDream.Core.Physics.Objects;

/// <summary>
/// A one-shot animation event queued on an object (retail <c>CAnimHook</c> in <c>anim_hooks</c>): executed once in the
/// next <c>process_hooks</c> and then dropped. Called inside the tick: must not allocate.
/// </summary>
public interface IAnimHook
{
    /// <summary>Runs the event on <paramref name="obj"/>.</summary>
    void Execute(PhysicsObj obj);
}
