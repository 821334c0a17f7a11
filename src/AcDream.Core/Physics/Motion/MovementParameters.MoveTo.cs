using System;
using System.Buffers.Binary;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Motion;

// The move-to side of MovementParameters (PORTAL/canim/CMovementDefs.c): the command a move-to plays at a distance, and the
// parameters' wire layouts.
public partial struct MovementParameters
{
    /// <summary>Bytes of the full layout (<c>MovementParameters::Pack</c> / <c>UnPack</c>): ten 4-byte fields.</summary>
    public const int PackedSize = 40;

    /// <summary>Bytes of the MoveToObject / MoveToPosition layout on the wire (<c>UnPackNet</c>, types 6 and 7): bitfield,
    /// distance to object, min distance, fail distance, speed, walk/run threshold, desired heading.</summary>
    public const int MoveToNetSize = 28;

    /// <summary>Bytes of the TurnToObject / TurnToHeading layout on the wire (<c>UnPackNet</c>, types 8 and 9): bitfield,
    /// speed, desired heading.</summary>
    public const int TurnToNetSize = 12;

    /// <summary>Both move-towards and move-away: walks in when farther than <see cref="DistanceToObject"/>, backs off when
    /// nearer than <see cref="MinDistance"/> (by <see cref="PhysicsGlobals.Epsilon"/>), else no command.</summary>
    // retail: MovementParameters::towards_and_away (acclient.c:346152)
    internal readonly void TowardsAndAway(float currDistance, float currHeading, out MotionCommand command, ref bool movingAway)
    {
        if (currDistance <= (double)DistanceToObject)
        {
            if ((double)currDistance - MinDistance >= PhysicsGlobals.Epsilon)    // x87: the difference in double
            {
                command = 0;
            }
            else
            {
                command = MotionCommand.WalkBackwards;
                movingAway = true;
            }
        }
        else
        {
            command = MotionCommand.WalkForward;
            movingAway = false;
        }
    }

    /// <summary>
    /// The command a move-to plays at <paramref name="currDistance"/> (0: none, it has arrived), whether it moves away, and
    /// its hold key: <see cref="HoldKey.Run"/> when it may charge, or may run and either may not walk or is farther than
    /// <see cref="DistanceToObject"/> + <see cref="WalkRunThreshold"/>; else <see cref="HoldKey.None"/> (walk).
    /// </summary>
    /// <remarks>A <paramref name="movingAway"/> is written only with a command (retail leaves the caller's variable).</remarks>
    // retail: MovementParameters::get_command (acclient.c:346174)
    internal readonly void GetCommand(float currDistance, float currHeading, out MotionCommand command, out HoldKey key,
        ref bool movingAway)
    {
        uint bits = (uint)Flags;
        if ((bits & (uint)MovementParameterFlags.MoveTowards) != 0)
        {
            if ((bits & (uint)MovementParameterFlags.MoveAway) != 0)
            {
                TowardsAndAway(currDistance, currHeading, out command, ref movingAway);
            }
            else
            {
                TowardsOnly(currDistance, out command, ref movingAway);
            }
        }
        else if ((bits & (uint)MovementParameterFlags.MoveAway) == 0)
        {
            TowardsOnly(currDistance, out command, ref movingAway);
        }
        else if (currDistance < (double)MinDistance)
        {
            command = MotionCommand.WalkForward;
            movingAway = true;
        }
        else
        {
            command = 0;
        }

        bits = (uint)Flags;
        if ((bits & (uint)MovementParameterFlags.CanCharge) != 0
            || ((bits & (uint)MovementParameterFlags.CanRun) != 0
                && ((bits & (uint)MovementParameterFlags.CanWalk) == 0
                    || (double)currDistance - DistanceToObject > WalkRunThreshold)))  // x87: the difference in double
        {
            key = HoldKey.Run;
        }
        else
        {
            key = HoldKey.None;
        }
    }

    // retail: MovementParameters::get_command (acclient.c:346174), LABEL_8 (towards, or neither flag)
    private readonly void TowardsOnly(float currDistance, out MotionCommand command, ref bool movingAway)
    {
        if (currDistance > (double)DistanceToObject)
        {
            command = MotionCommand.WalkForward;
            movingAway = false;
        }
        else
        {
            command = 0;
        }
    }

    /// <summary>The heading, relative to the direction of the target, that a move-to with <paramref name="command"/> faces:
    /// 180 when walking or running away (or walking backwards towards), else 0.</summary>
    // retail: MovementParameters::get_desired_heading (acclient.c:346223)
    internal static double GetDesiredHeading(MotionCommand command, bool movingAway)
    {
        if (command == MotionCommand.RunForward || command == MotionCommand.WalkForward)
        {
            return movingAway ? 180.0 : 0.0;
        }

        if (command == MotionCommand.WalkBackwards)
        {
            return movingAway ? 0.0 : 180.0;
        }

        return 0.0;
    }

    /// <summary>
    /// Reads the parameters of a MovementEvent of movement type <paramref name="type"/> (6–9) from the wire: types 6 and 7
    /// (MoveToObject, MoveToPosition) carry <see cref="MoveToNetSize"/> bytes — <c>u32</c> bitfield, <c>f32</c>
    /// <see cref="DistanceToObject"/>, <see cref="MinDistance"/>, <see cref="FailDistance"/>, <see cref="Speed"/>,
    /// <see cref="WalkRunThreshold"/>, <see cref="DesiredHeading"/>; types 8 and 9 (TurnToObject, TurnToHeading)
    /// <see cref="TurnToNetSize"/> bytes — bitfield, speed, desired heading. Every other field keeps retail's default
    /// (<c>new MovementParameters()</c>). Retail <c>MovementParameters::UnPackNet</c>.
    /// </summary>
    /// <param name="data">The bytes, starting at the parameters (little-endian).</param>
    /// <param name="type">The movement type: 6, 7, 8 or 9.</param>
    /// <param name="bytesRead">Bytes consumed (28 or 12).</param>
    /// <returns>The parameters.</returns>
    /// <exception cref="ArgumentException"><paramref name="type"/> is not 6–9.</exception>
    /// <exception cref="RetailDataFormatException">The data are shorter than the layout, a float is NaN or infinite, or the
    /// speed is beyond ±<see cref="MaxMoveToSpeed"/>.</exception>
    public static MovementParameters UnPackNet(ReadOnlySpan<byte> data, MovementType type, out int bytesRead)
    {
        if (type < MovementType.MoveToObject || type > MovementType.TurnToHeading)
        {
            throw new ArgumentException("MovementParameters are on the wire only for movement types 6 to 9.", nameof(type));
        }

        var r = new RetailDataReader(data, "MovementParameters");
        var p = new MovementParameters();
        p.UnPackNet(ref r, type);
        bytesRead = r.Offset;
        return p;
    }

    /// <summary>Reads the wire layout of <paramref name="type"/> from <paramref name="r"/> (see <see cref="UnPackNet(ReadOnlySpan{byte}, MovementType, out int)"/>).</summary>
    /// <returns>False (nothing read) for a type other than 6–9, as retail.</returns>
    /// <exception cref="RetailDataFormatException">Short data, a float that is not finite, or a speed beyond
    /// ±<see cref="MaxMoveToSpeed"/> (non-retail: the move-to API's domain).</exception>
    // retail: MovementParameters::UnPackNet (acclient.c:346343)
    internal bool UnPackNet(ref RetailDataReader r, MovementType type)
    {
        int size;
        switch (type)
        {
            case MovementType.MoveToObject:
            case MovementType.MoveToPosition:
                size = MoveToNetSize;
                break;
            case MovementType.TurnToObject:
            case MovementType.TurnToHeading:
                size = TurnToNetSize;
                break;
            default:
                return false;
        }

        if (r.Remaining < size)
        {
            throw r.Error($"MovementParameters of movement type {(uint)type} need {size} bytes, {r.Remaining} remain");
        }

        int speedAt;
        if (size == MoveToNetSize)
        {
            Flags = (MovementParameterFlags)r.ReadUInt32("bitfield");
            DistanceToObject = r.ReadFiniteSingle("distance_to_object");
            MinDistance = r.ReadFiniteSingle("min_distance");
            FailDistance = r.ReadFiniteSingle("fail_distance");
            speedAt = r.Offset;
            Speed = r.ReadFiniteSingle("speed");
            WalkRunThreshold = r.ReadFiniteSingle("walk_run_threshhold");
        }
        else
        {
            Flags = (MovementParameterFlags)r.ReadUInt32("bitfield");
            speedAt = r.Offset;
            Speed = r.ReadFiniteSingle("speed");
        }

        DesiredHeading = r.ReadFiniteSingle("desired_heading");
        // non-retail: the move-to API's speed bound, so that decoded parameters can go straight to the move-to manager
        if (Math.Abs(Speed) > MaxMoveToSpeed)
        {
            throw r.ErrorAt(speedAt, $"speed {Speed} is beyond ±{MaxMoveToSpeed}");
        }

        return true;
    }

    /// <summary>Writes the wire layout of <paramref name="type"/> (the server's side of <see cref="UnPackNet(ReadOnlySpan{byte}, MovementType, out int)"/>;
    /// retail's client has no writer for it).</summary>
    /// <returns>Bytes written (28 or 12).</returns>
    /// <exception cref="ArgumentException"><paramref name="type"/> is not 6–9, or <paramref name="destination"/> is too short.</exception>
    public readonly int PackNet(Span<byte> destination, MovementType type)
    {
        bool moveTo = type is MovementType.MoveToObject or MovementType.MoveToPosition;
        if (!moveTo && type is not (MovementType.TurnToObject or MovementType.TurnToHeading))
        {
            throw new ArgumentException("MovementParameters are on the wire only for movement types 6 to 9.", nameof(type));
        }

        int size = moveTo ? MoveToNetSize : TurnToNetSize;
        if (destination.Length < size)
        {
            throw new ArgumentException($"The destination needs {size} bytes.", nameof(destination));
        }

        BinaryPrimitives.WriteUInt32LittleEndian(destination, (uint)Flags);
        int o = 4;
        if (moveTo)
        {
            WriteSingle(destination, ref o, DistanceToObject);
            WriteSingle(destination, ref o, MinDistance);
            WriteSingle(destination, ref o, FailDistance);
            WriteSingle(destination, ref o, Speed);
            WriteSingle(destination, ref o, WalkRunThreshold);
        }
        else
        {
            WriteSingle(destination, ref o, Speed);
        }

        WriteSingle(destination, ref o, DesiredHeading);
        return o;
    }

    /// <summary>Writes all ten fields (retail's full layout, <see cref="PackedSize"/> bytes): bitfield, distance to object,
    /// min distance, fail distance, desired heading, speed, walk/run threshold, context id, hold key, action stamp.</summary>
    /// <returns>Bytes written (40).</returns>
    /// <exception cref="ArgumentException"><paramref name="destination"/> is shorter than 40 bytes.</exception>
    // retail: MovementParameters::Pack (acclient.c:346241)
    public readonly int Pack(Span<byte> destination)
    {
        if (destination.Length < PackedSize)
        {
            throw new ArgumentException("The destination needs 40 bytes.", nameof(destination));
        }

        BinaryPrimitives.WriteUInt32LittleEndian(destination, (uint)Flags);
        int o = 4;
        WriteSingle(destination, ref o, DistanceToObject);
        WriteSingle(destination, ref o, MinDistance);
        WriteSingle(destination, ref o, FailDistance);
        WriteSingle(destination, ref o, DesiredHeading);
        WriteSingle(destination, ref o, Speed);
        WriteSingle(destination, ref o, WalkRunThreshold);
        BinaryPrimitives.WriteUInt32LittleEndian(destination[o..], ContextId);
        BinaryPrimitives.WriteUInt32LittleEndian(destination[(o + 4)..], (uint)HoldKeyToApply);
        BinaryPrimitives.WriteUInt32LittleEndian(destination[(o + 8)..], ActionStamp);
        return PackedSize;
    }

    /// <summary>Reads all ten fields (the layout of <see cref="Pack"/>).</summary>
    /// <exception cref="RetailDataFormatException">Fewer than 40 bytes, or a float that is not finite.</exception>
    // retail: MovementParameters::UnPack (acclient.c:346289)
    public static MovementParameters UnPack(ReadOnlySpan<byte> data)
    {
        var r = new RetailDataReader(data, "MovementParameters");
        if (r.Remaining < PackedSize)
        {
            throw r.Error($"MovementParameters need {PackedSize} bytes, {r.Remaining} remain");
        }

        var p = new MovementParameters
        {
            Flags = (MovementParameterFlags)r.ReadUInt32("bitfield"),
            DistanceToObject = r.ReadFiniteSingle("distance_to_object"),
            MinDistance = r.ReadFiniteSingle("min_distance"),
            FailDistance = r.ReadFiniteSingle("fail_distance"),
            DesiredHeading = r.ReadFiniteSingle("desired_heading"),
            Speed = r.ReadFiniteSingle("speed"),
            WalkRunThreshold = r.ReadFiniteSingle("walk_run_threshhold"),
            ContextId = r.ReadUInt32("context_id"),
            HoldKeyToApply = (HoldKey)r.ReadUInt32("hold_key_to_apply"),
            ActionStamp = r.ReadUInt32("action_stamp"),
        };
        return p;
    }

    private static void WriteSingle(Span<byte> d, ref int o, float v)
    {
        BinaryPrimitives.WriteSingleLittleEndian(d[o..], v);
        o += 4;
    }

    /// <summary>Largest speed multiplier a move-to takes, in magnitude: 100 (non-retail bound; the server sends 1, or 1.5 for a
    /// melee charge). The move-to plays its walk, run and turns at this multiple of their speeds; a speed like 1e30 would
    /// carry the body out of the position domain in one step.</summary>
    public const float MaxMoveToSpeed = 100f;

    /// <summary>Throws unless every float is finite and the speed is within ±<see cref="MaxMoveToSpeed"/> (the move-to API's
    /// check; with <see cref="MotionChecks.Check"/>).</summary>
    internal readonly void CheckFiniteForMoveTo(string paramName)
    {
        MotionChecks.Check(this);
        // non-retail: the speed's bound (see MaxMoveToSpeed)
        if (Math.Abs(Speed) > MaxMoveToSpeed)
        {
            throw new ArgumentException("A move-to's speed must be within ±100.", paramName);
        }

        if (!float.IsFinite(DistanceToObject) || !float.IsFinite(MinDistance) || !float.IsFinite(DesiredHeading)
            || !float.IsFinite(FailDistance) || !float.IsFinite(WalkRunThreshold))
        {
            throw new ArgumentException("Move-to parameters must be finite (distances, heading, threshold).", paramName);
        }
    }
}
