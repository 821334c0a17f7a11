namespace AcDream.Core.Physics.Animation;

/// <summary>
/// A part array that is told when an animation of its sequence ends while links are queued (retail
/// <c>CPartArray::AnimationDone</c>, reached from <c>CPhysicsObj::Hook_AnimDone</c> when the sequence's AnimDone hook runs).
/// Implemented by the animated part array, which hands it to its motion table manager.
/// </summary>
internal interface IAnimationDoneTarget
{
    /// <summary>One animation finished (<paramref name="success"/> is true from the hook).</summary>
    void AnimationDone(bool success);
}
