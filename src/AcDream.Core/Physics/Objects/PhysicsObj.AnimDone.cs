using System;
using AcDream.Core.Physics.Animation;

namespace AcDream.Core.Physics.Objects;

public sealed partial class PhysicsObj
{
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
