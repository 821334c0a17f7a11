using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Motion;

/// <summary>One movement request for <see cref="MovementManager"/> (retail <c>MovementStruct</c>, acclient.h:38069): its
/// type, the command (types 1–4), the target object and its top-level parent (6, 8), the position (7), the target's radius
/// and height (6), and the parameters.</summary>
internal struct MovementStruct
{
    public MovementType Type;
    public MotionCommand Motion;
    public uint ObjectId;
    public uint TopLevelId;
    public Position Pos;
    public float Radius;
    public float Height;
    public MovementParameters Params;

    /// <summary>A request of <paramref name="type"/> with retail's empty position (cell 0, identity frame).</summary>
    public static MovementStruct Of(MovementType type, in MovementParameters p) =>
        new() { Type = type, Pos = new Position(0, Frame.Identity), Params = p };
}
