using AcDream.Core.Physics.Animation;

namespace AcDream.Core.Physics.World;

public sealed partial class PhysicsWorld
{
    /// <summary>Optional client callback for the animation hooks the library does not run itself (sounds, particles,
    /// scripts, attacks, lights, part changes, texture velocity, no-draw); null drops them.</summary>
    public IAnimHookListener? AnimHookListener { get; set; }
}
