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
}
