namespace AcDream.Core.Physics.Managers;

/// <summary>One detection cylinder of a <see cref="DetectionManager"/> (retail <c>DetectionCylsphere</c>): a radius around the
/// detecting object, the watched object (0: every object, retail's global detection), and whether it was inside at the last
/// check. Pooled by the manager.</summary>
internal sealed class DetectionCylsphere
{
    /// <summary>The client's id of the cylinder (retail <c>context_id</c>), the key of the detection table.</summary>
    public uint ContextId;

    /// <summary>Detection radius, metres, added to the watched object's radius (retail <c>radius</c>).</summary>
    public float Radius;

    /// <summary>The watched object and its last status (retail <c>info</c>); object id 0 is global detection.</summary>
    public uint ObjectId;

    /// <summary>The last status (retail <c>info.object_status</c>).</summary>
    public DetectionStatus ObjectStatus;

    /// <summary>The watched object was inside at the last check (retail <c>object_detected</c>).</summary>
    public bool ObjectDetected;
}
