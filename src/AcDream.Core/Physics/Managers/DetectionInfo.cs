namespace AcDream.Core.Physics.Managers;

/// <summary>What a detection check found out about an object (retail <c>DetectionType</c>: the values the detection manager
/// stores in <c>DetectionInfo::object_status</c>).</summary>
public enum DetectionStatus : uint
{
    /// <summary>No change since the last check (retail 0; not reported).</summary>
    NoChange = 0,

    /// <summary>The object came inside the detection cylinder (retail <c>EnteredDetection</c>, 1).</summary>
    Entered = 1,

    /// <summary>The object went outside the detection cylinder, or is no longer in the world (retail <c>LeftDetection</c>, 2).</summary>
    Left = 2,
}

/// <summary>One detection report: the object and what happened to it (retail <c>DetectionInfo</c>: <c>object_id</c>,
/// <c>object_status</c>).</summary>
public readonly struct DetectionInfo
{
    /// <summary>Creates a report.</summary>
    public DetectionInfo(uint objectId, DetectionStatus status)
    {
        ObjectId = objectId;
        Status = status;
    }

    /// <summary>The detected object's id (retail <c>object_id</c>).</summary>
    public uint ObjectId { get; }

    /// <summary>Entered or left (retail <c>object_status</c>).</summary>
    public DetectionStatus Status { get; }
}

/// <summary>
/// The client's detection callback (retail: the detecting object's weenie, reached from <c>DetectionManager::CheckDetection</c>
/// and <c>DetectionManager::ReportGlobalDetection</c>). Called inside the tick, during the detecting object's step: it must not
/// allocate. It may remove objects from the world (the detector included: its remaining reports of this check are dropped), and
/// may create or destroy detection cylinders (a destroyed one stops at the detector's next check, as retail defers deletions).
/// </summary>
public interface IDetectionListener
{
    /// <summary><paramref name="info"/>'s object entered or left the detection cylinder <paramref name="contextId"/> of
    /// <paramref name="detector"/>.</summary>
    void OnDetection(Objects.PhysicsObj detector, uint contextId, DetectionInfo info);
}
