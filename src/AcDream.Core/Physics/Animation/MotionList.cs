namespace AcDream.Core.Physics.Animation;

/// <summary>
/// One entry of a <see cref="MotionState"/>'s modifier or action list: a motion and its speed (retail <c>MotionList</c>,
/// 12 bytes: motion, speed_mod, next).
/// </summary>
/// <remarks>Retail news and deletes each node; the port recycles them through the owning state's free list so that a
/// command in the tick allocates nothing once the lists have grown (the nodes are the same, only their memory is reused).
/// </remarks>
internal sealed class MotionList
{
    /// <summary>The motion id (retail <c>motion</c>).</summary>
    public uint Motion;

    /// <summary>Its speed (retail <c>speed_mod</c>).</summary>
    public float SpeedMod = 1f;

    /// <summary>The next entry, or null (retail <c>next</c>).</summary>
    public MotionList? Next;
}
