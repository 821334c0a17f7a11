using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.World;

/// <summary>
/// Test and diagnostics seam: told about every simulation step a world runs. Costs one null test per step when unset.
/// Called inside the tick: implementations must not allocate.
/// </summary>
public interface IStepObserver
{
    /// <summary>A step of <paramref name="quantum"/> seconds starts for <paramref name="obj"/>; <paramref name="physicsTime"/>
    /// is the physics clock at the end of the step.</summary>
    void OnStep(PhysicsObj obj, float quantum, double physicsTime);
}

/// <summary>Told when the world has updated its player (retail <c>SmartBox::PlayerPhysicsUpdatedCallback</c>).</summary>
public interface IPlayerPhysicsListener
{
    /// <summary>The player's update_object has just run.</summary>
    void PlayerPhysicsUpdated(PhysicsObj player);
}
