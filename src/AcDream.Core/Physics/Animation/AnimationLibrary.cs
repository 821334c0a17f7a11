using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Animation;

/// <summary>A dictionary-backed <see cref="IAnimationSource"/>: the animations added to it, by id.</summary>
public sealed class AnimationLibrary : IAnimationSource
{
    private readonly Dictionary<uint, AnimClip> _animations = new();

    /// <summary>Number of animations held.</summary>
    public int Count => _animations.Count;

    /// <summary>Adds <paramref name="animation"/> under its <see cref="AnimClip.Id"/>, replacing one with the same id.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="animation"/> is null.</exception>
    public void Add(AnimClip animation)
    {
        ArgumentNullException.ThrowIfNull(animation);
        _animations[animation.Id] = animation;
    }

    /// <summary>Unpacks an animation entry's bytes (<see cref="AnimClip.UnPack(ReadOnlySpan{byte})"/>) and adds it.</summary>
    /// <returns>The animation added.</returns>
    /// <exception cref="RetailDataFormatException">The bytes are not an animation entry (nothing is added).</exception>
    public AnimClip Add(ReadOnlySpan<byte> entry)
    {
        AnimClip animation = AnimClip.UnPack(entry);
        _animations[animation.Id] = animation;
        return animation;
    }

    /// <inheritdoc />
    public AnimClip? GetAnimation(uint animationId) => _animations.TryGetValue(animationId, out AnimClip? a) ? a : null;
}
