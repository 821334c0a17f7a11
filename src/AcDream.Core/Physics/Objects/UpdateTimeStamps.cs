namespace AcDream.Core.Physics.Objects;

/// <summary>
/// The nine 16-bit network timestamps of an object (retail <c>update_times[9]</c>), indexed by <see cref="PhysicsTimeStamp"/>,
/// held inside the object (18 bytes) rather than in an array of its own.
/// </summary>
[System.Runtime.CompilerServices.InlineArray(9)]
internal struct UpdateTimeStamps
{
    /// <summary>Number of stamps (retail <c>update_times[9]</c>).</summary>
    public const int Count = 9;

    private ushort _element0;
}
