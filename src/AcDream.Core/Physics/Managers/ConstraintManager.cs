namespace AcDream.Core.Physics;

/// <summary>
/// Holds an object within a distance of a position (retail <c>ConstraintManager</c>, PORTAL/cpmanager/CConstraintManager.c).
/// Placeholder seam: the retail behaviour is ported in issue 4.
/// </summary>
public sealed class ConstraintManager
{
    internal ConstraintManager(PhysicsObj physicsObj)
    {
        PhysicsObj = physicsObj;
    }

    /// <summary>The constrained object.</summary>
    public PhysicsObj PhysicsObj { get; }

    /// <summary>Adjusts the step's offset frame to respect the constraint.</summary>
    public void AdjustOffset(ref Frame offset, double quantum)
    {
    }

    /// <summary>End-of-step bookkeeping.</summary>
    public void UseTime()
    {
    }

    /// <summary>Constrains to <paramref name="p"/>.</summary>
    public void ConstrainTo(in Position p, float startDistance, float maxDistance)
    {
    }

    /// <summary>Removes the constraint.</summary>
    public void UnConstrain()
    {
    }

    /// <summary>True when fully constrained.</summary>
    public bool IsFullyConstrained() => false;
}
