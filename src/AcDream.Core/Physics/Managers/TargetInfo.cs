using System.Numerics;
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
/// A target-tracking report (retail <c>TargetInfo</c>, acclient.h:31591): what an object's <see cref="TargetManager"/> learns
/// of the object it tracks, delivered to <see cref="PhysicsObj.HandleUpdateTarget"/> (then to the move-to and sticky
/// managers). <c>new TargetInfo()</c> gives retail's constructor (identity frames, status
/// <see cref="TargetStatus.Undefined"/>).
/// </summary>
public struct TargetInfo
{
    /// <summary>Creates an empty report: ids 0, radius and quantum 0, both positions cell 0 with the identity frame,
    /// status <see cref="TargetStatus.Undefined"/>.</summary>
    // retail: TargetInfo::TargetInfo (acclient.c:328026)
    public TargetInfo()
    {
        ContextId = 0;
        ObjectId = 0;
        Radius = 0f;
        Quantum = 0.0;
        TargetPosition = new Position(0, Frame.Identity);
        InterpolatedPosition = new Position(0, Frame.Identity);
        InterpolatedHeading = Vector3.Zero;
        Velocity = Vector3.Zero;
        Status = TargetStatus.Undefined;
        LastUpdateTime = 0.0;
    }

    /// <summary>Tracking context; retail forwards only context 0 to the managers.</summary>
    public uint ContextId;

    /// <summary>Id of the tracked object.</summary>
    public uint ObjectId;

    /// <summary>Distance the target must move (from the last position sent) before the next report, metres.</summary>
    public float Radius;

    /// <summary>Look-ahead of the reported interpolated position, seconds (retail <c>quantum</c>).</summary>
    public double Quantum;

    /// <summary>Tracking status.</summary>
    public TargetStatus Status;

    /// <summary>The target's current position.</summary>
    public Position TargetPosition;

    /// <summary>The target's position <see cref="Quantum"/> seconds ahead at its current velocity (retail
    /// <c>interpolated_position</c>).</summary>
    public Position InterpolatedPosition;

    /// <summary>Unit direction from the tracking object to <see cref="InterpolatedPosition"/> ((0, 0, 1) when they
    /// coincide), set by the tracker on receipt (retail <c>interpolated_heading</c>).</summary>
    public Vector3 InterpolatedHeading;

    /// <summary>The target's velocity when the report was sent, m/s.</summary>
    public Vector3 Velocity;

    /// <summary>Client time the tracker last received a report, seconds (retail <c>last_update_time</c>).</summary>
    public double LastUpdateTime;
}
