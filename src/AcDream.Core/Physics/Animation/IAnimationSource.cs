namespace AcDream.Core.Physics.Animation;

/// <summary>
/// Resolves an animation data id to its animation, as retail's data cache does (<c>DBObj::Get</c> with a 0x03 id, from
/// <c>AnimSequenceNode::set_animation_id</c>). The client implements it over its dat files, or uses
/// <see cref="AnimationLibrary"/>.
/// </summary>
public interface IAnimationSource
{
    /// <summary>The animation with data id <paramref name="animationId"/>, or null when there is none (the sequence then
    /// drops that animation, as retail drops a node without one). Called when an animation is queued, not per tick.</summary>
    AnimClip? GetAnimation(uint animationId);
}
