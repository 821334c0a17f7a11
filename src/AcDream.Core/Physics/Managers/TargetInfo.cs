using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Managers;

/// <summary>Status of a tracked target (retail <c>TargetStatus</c>, acclient.h:7264).</summary>
public enum TargetStatus : uint
{
    /// <summary>Not yet known.</summary>
    Undefined = 0,

    /// <summary>The target is in the world and its position is current.</summary>
    Ok = 1,

    /// <summary>The target left the world.</summary>
    ExitWorld = 2,

    /// <summary>The target teleported.</summary>
    Teleported = 3,

    /// <summary>The target went into a container.</summary>
    Contained = 4,

    /// <summary>The target was attached to a parent.</summary>
    Parented = 5,

    /// <summary>Tracking timed out.</summary>
    TimedOut = 6,
}

/// <summary>
/// A target-tracking report delivered to <see cref="PhysicsObj.HandleUpdateTarget"/> (retail <c>TargetInfo</c>,
/// acclient.h:31591; only the fields the position managers read).
/// </summary>
public struct TargetInfo
{
    /// <summary>Tracking context; retail forwards only context 0 to the managers.</summary>
    public uint ContextId;

    /// <summary>Id of the tracked object.</summary>
    public uint ObjectId;

    /// <summary>Tracking status.</summary>
    public TargetStatus Status;

    /// <summary>The target's current position.</summary>
    public Position TargetPosition;
}

/// <summary>
/// Client seam for the target tracking the sticky manager asks for (retail <c>CPhysicsObj::set_target</c> /
/// <c>clear_target</c>, which reach the TargetManager). Called on the update path; must not allocate.
/// </summary>
public interface ITargetTracker
{
    /// <summary>Start tracking <paramref name="objectId"/> for <paramref name="obj"/>.</summary>
    // retail caller: CPhysicsObj::set_target (acclient.c:315991)
    void SetTarget(PhysicsObj obj, uint contextId, uint objectId, float radius, double quantum);

    /// <summary>Stop tracking for <paramref name="obj"/>.</summary>
    // retail caller: CPhysicsObj::clear_target (acclient.c:316011)
    void ClearTarget(PhysicsObj obj);
}
