using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Managers;

/// <summary>
/// Owner of an object's position-correcting sub-managers (retail <c>PositionManager</c>, acclient.h:30952,
/// PORTAL/cpmanager/CPositionManager.c): interpolation towards server positions, sticking to a target, and the
/// dead-reckoning constraint. Each sub-manager is created on first use; one that does not exist costs nothing.
/// </summary>
public sealed class PositionManager
{
    // retail: PositionManager::Create (acclient.c:388404)
    internal PositionManager(PhysicsObj physicsObj)
    {
        PhysicsObj = physicsObj;
    }

    /// <summary>The object this manager moves.</summary>
    public PhysicsObj PhysicsObj { get; }

    /// <summary>The interpolation manager, or null until <see cref="InterpolateTo"/> first runs.</summary>
    public InterpolationManager? InterpolationManager { get; private set; }

    /// <summary>The sticky manager, or null until <see cref="StickTo"/> first runs.</summary>
    public StickyManager? StickyManager { get; private set; }

    /// <summary>The constraint manager, or null until <see cref="ConstrainTo"/> first runs.</summary>
    public ConstraintManager? ConstraintManager { get; private set; }

    /// <summary>
    /// Lets each sub-manager replace or adjust the step's local offset frame, in the order interpolation, sticky, constraint.
    /// </summary>
    /// <param name="offset">The substep's offset frame (animation root motion on entry).</param>
    /// <param name="quantum">Substep duration, seconds.</param>
    // retail: PositionManager::adjust_offset (acclient.c:388286)
    internal void AdjustOffset(ref Frame offset, double quantum)
    {
        InterpolationManager?.AdjustOffset(ref offset, quantum);
        StickyManager?.AdjustOffset(ref offset, quantum);
        ConstraintManager?.AdjustOffset(ref offset, quantum);
    }

    /// <summary>End-of-step work, in the order interpolation, constraint, sticky.</summary>
    // retail: PositionManager::UseTime (acclient.c:388266)
    internal void UseTime()
    {
        InterpolationManager?.UseTime();
        ConstraintManager?.UseTime();
        StickyManager?.UseTime();
    }

    /// <summary>Queues an interpolation towards <paramref name="p"/> (see <see cref="InterpolationManager.InterpolateTo"/>).</summary>
    /// <param name="p">The reported position.</param>
    /// <param name="keepHeading">Keep the object's current heading.</param>
    /// <exception cref="System.ArgumentException"><paramref name="p"/> is unusable; nothing changes.</exception>
    // retail: PositionManager::InterpolateTo (acclient.c:388316)
    public void InterpolateTo(in Position p, bool keepHeading)
    {
        // non-retail: validated before the manager is created, so that a refusal leaves no new manager behind
        ThrowIfUnusable(p);
        PhysicsObj.Touch();
        InterpolationManager ??= new InterpolationManager(PhysicsObj);
        InterpolationManager.InterpolateTo(p, keepHeading);
    }

    /// <summary>Drops every queued interpolation node.</summary>
    // retail: PositionManager::StopInterpolating (acclient.c:388331)
    public void StopInterpolating() => InterpolationManager?.StopInterpolating();

    /// <summary>True while interpolation nodes are queued.</summary>
    // retail: PositionManager::IsInterpolating (acclient.c:388475)
    public bool IsInterpolating => InterpolationManager is not null && InterpolationManager.IsInterpolating;

    /// <summary>Sticks the object to another object for one second (see <see cref="StickyManager.StickTo"/>).</summary>
    /// <param name="objectId">Target id.</param>
    /// <param name="radius">Target radius, metres: finite.</param>
    /// <param name="height">Target height (unused, as in retail): finite.</param>
    /// <exception cref="System.ArgumentException">The radius or the height is not finite; no manager is created.</exception>
    // retail: PositionManager::StickTo (acclient.c:388341)
    public void StickTo(uint objectId, float radius, float height)
    {
        // non-retail: validated before the manager is created, so that a refusal leaves no new manager behind
        if (!float.IsFinite(radius) || !float.IsFinite(height))
        {
            throw new System.ArgumentException("Radius and height must be finite.", nameof(radius));
        }

        PhysicsObj.Touch();
        StickyManager ??= new StickyManager(PhysicsObj);
        StickyManager.StickTo(objectId, radius, height);
    }

    /// <summary>Stops sticking: releases the sticky target, if any (retail <c>PositionManager::UnStick</c>).</summary>
    // retail: PositionManager::UnStick (acclient.c:388306)
    public void StopSticking() => StickyManager?.StopSticking();

    /// <summary>Id of the sticky target, or 0.</summary>
    // retail: PositionManager::GetStickyObjectID (acclient.c:388352)
    public uint StickyObjectId => StickyManager?.TargetId ?? 0u;

    /// <summary>Passes a target-tracking report to the sticky manager, if any.</summary>
    /// <param name="info">The report.</param>
    // retail: PositionManager::HandleUpdateTarget (acclient.c:388487)
    public void HandleUpdateTarget(in TargetInfo info) => StickyManager?.HandleUpdateTarget(info);

    /// <summary>Constrains the object's own motion relative to <paramref name="p"/> (see <see cref="ConstraintManager"/>).</summary>
    /// <param name="p">Constraint position.</param>
    /// <param name="startDistance">Counted distance at which scaling starts, metres: finite.</param>
    /// <param name="maxDistance">Counted distance at which offsets are zeroed, metres: finite.</param>
    /// <exception cref="System.ArgumentException">The position is outside the position domain (<see cref="InputLimits"/>) or a
    /// distance is not finite; no manager is created.</exception>
    // retail: PositionManager::ConstrainTo (acclient.c:388366)
    public void ConstrainTo(in Position p, float startDistance, float maxDistance)
    {
        // non-retail: validated before the manager is created, so that a refusal leaves no new manager behind
        ThrowIfUnusable(p);
        if (!float.IsFinite(startDistance) || !float.IsFinite(maxDistance))
        {
            throw new System.ArgumentException("Constraint distances must be finite.", nameof(maxDistance));
        }

        PhysicsObj.Touch();
        ConstraintManager ??= new ConstraintManager(PhysicsObj);
        ConstraintManager.ConstrainTo(p, startDistance, maxDistance);
    }

    /// <summary>Stops constraining: lifts the constraint, if any (retail <c>PositionManager::UnConstrain</c>).</summary>
    // retail: PositionManager::UnConstrain (acclient.c:388380)
    public void StopConstraining() => ConstraintManager?.StopConstraining();

    /// <summary>True while adjust_offset and UseTime would do nothing: no interpolation node and no pending blip, no sticky
    /// target, no constraint (the scene may then skip a resting object).</summary>
    internal bool IsIdle =>
        (InterpolationManager is null || (InterpolationManager.Count == 0 && InterpolationManager.NodeFailCounter <= 0))
        && (StickyManager is null || StickyManager.TargetId == 0)
        && (ConstraintManager is null || !ConstraintManager.IsConstrained);

    private static void ThrowIfUnusable(in Position p)
    {
        if (!InputLimits.IsPositionInDomain(p))
        {
            throw new System.ArgumentException("Position must be in the position domain (InputLimits).", nameof(p));
        }
    }

    /// <summary>True when the constraint holds the object fully.</summary>
    // retail: PositionManager::IsFullyConstrained (acclient.c:388390)
    public bool IsFullyConstrained => ConstraintManager is not null && ConstraintManager.IsFullyConstrained;
}
