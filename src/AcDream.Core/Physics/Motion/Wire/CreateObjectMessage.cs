namespace AcDream.Core.Physics.Motion.Wire;

/// <summary>
/// One server CreateObject (message 0xF745), its physics part: the object id and its <see cref="PhysicsDesc"/>. The body's
/// visual description (retail <c>ObjDesc</c>) is read past, the weenie description that follows is the client's
/// (<see cref="WeenieDescOffset"/> says where it starts). Decoded by
/// <see cref="PhysicsMessageDecoder.Decode(System.ReadOnlySpan{byte}, CreateObjectMessage)"/>; applied by
/// <see cref="ServerMessageHandler.HandleCreateObject"/>. Reusable.
/// </summary>
public sealed class CreateObjectMessage
{
    /// <summary>The object.</summary>
    public uint ObjectId { get; set; }

    /// <summary>The physics description.</summary>
    public PhysicsDesc Physics { get; } = new();

    /// <summary>Offset in the body of the weenie description (the bytes after the physics description), for the client.</summary>
    public int WeenieDescOffset { get; set; }
}
