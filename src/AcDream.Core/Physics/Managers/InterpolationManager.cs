namespace AcDream.Core.Physics;

/// <summary>
/// Moves an object smoothly towards queued server positions (retail <c>InterpolationManager</c>,
/// PORTAL/cpmanager/CInterpolationManager.c). Placeholder seam: the retail behaviour is ported in issue 4.
/// </summary>
public sealed class InterpolationManager
{
    internal InterpolationManager(PhysicsObj physicsObj)
    {
        PhysicsObj = physicsObj;
    }

    /// <summary>The object being interpolated.</summary>
    public PhysicsObj PhysicsObj { get; }

    /// <summary>Adjusts the step's offset frame towards the head node.</summary>
    // retail: InterpolationManager::adjust_offset (acclient.c:389177)
    public void AdjustOffset(ref Frame offset, double quantum)
    {
    }

    /// <summary>End-of-step bookkeeping (blip on repeated failure).</summary>
    // retail: InterpolationManager::UseTime (acclient.c:389277)
    public void UseTime()
    {
    }

    /// <summary>Queues <paramref name="p"/>.</summary>
    // retail: InterpolationManager::InterpolateTo (acclient.c:389016)
    public void InterpolateTo(in Position p, bool keepHeading)
    {
    }

    /// <summary>Drops every node.</summary>
    // retail: InterpolationManager::StopInterpolating (acclient.c:388852)
    public void StopInterpolating()
    {
    }

    /// <summary>True while nodes are queued.</summary>
    public bool IsInterpolating() => false;
}
