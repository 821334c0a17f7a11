namespace AcDream.Core.Physics;

/// <summary>
/// Keeps an object next to a target object (retail <c>StickyManager</c>, PORTAL/cpmanager/CStickyManager.c).
/// Placeholder seam: the retail behaviour is ported in issue 4.
/// </summary>
public sealed class StickyManager
{
    internal StickyManager(PhysicsObj physicsObj)
    {
        PhysicsObj = physicsObj;
    }

    /// <summary>The object that sticks.</summary>
    public PhysicsObj PhysicsObj { get; }

    /// <summary>Id of the target object, or 0.</summary>
    public uint TargetId { get; private set; }

    /// <summary>Adjusts the step's offset frame towards the target.</summary>
    public void AdjustOffset(ref Frame offset, double quantum)
    {
    }

    /// <summary>End-of-step bookkeeping (timeout).</summary>
    public void UseTime()
    {
    }

    /// <summary>Starts sticking to <paramref name="objectId"/>.</summary>
    public void StickTo(uint objectId, float radius, float height) => TargetId = objectId;

    /// <summary>Stops sticking.</summary>
    public void HandleExitWorld() => TargetId = 0;
}
