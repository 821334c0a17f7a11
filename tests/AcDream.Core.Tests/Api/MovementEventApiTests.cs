using System;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.World;
using AcDream.Core.Tests.Retail;
using Xunit;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Core.Tests.Api;

// The MovementEvent entry point's contract: bad bytes are a named RetailDataFormatException from the decoder (nothing is
// applied); a bad message is an ArgumentException from HandleMovementEvent before anything changes.
public class MovementEventApiTests
{
    // A type-7 body (MoveToPosition): 12 header bytes + 4 + origin 16 + parameters 28 + run rate 4 = 64 bytes.
    private static byte[] MoveToPositionBody(float x = 10f) =>
        MovementEventBytes.Body(1, 0, false, new RetailDataWriter().Byte(7).Byte(0).UInt16(0x3D)
            .UInt32(0xA9B3000Cu).Single(x).Single(20f).Single(94f)
            .UInt32(0x1EE4Fu).Single(0.6f).Single(0f).Single(float.MaxValue).Single(2f).Single(15f).Single(0f)
            .Single(1.25f).ToArray());

    [Fact]
    public void Decode_EveryTruncation_IsANamedFormatError()
    {
        byte[] body = MoveToPositionBody();
        Assert.Equal(64, body.Length);
        var m = new MovementEventMessage();
        MovementEventDecoder.Decode(body, m);
        Assert.Equal(MovementEventType.MoveToPosition, m.MovementType);
        for (int n = 0; n < body.Length; n++)
        {
            RetailDataFormatException e = Assert.Throws<RetailDataFormatException>(() => MovementEventDecoder.Decode(body.AsSpan(0, n), m));
            Assert.Equal("MovementEvent", e.Structure);
            Assert.InRange(e.Offset, 0, n);
            Assert.Contains("remain", e.Reason, StringComparison.Ordinal);
        }

        byte[] longer = new byte[body.Length + 1];
        body.CopyTo(longer, 0);
        Assert.Contains("after the movement data", Assert.Throws<RetailDataFormatException>(() => MovementEventDecoder.Decode(longer, m)).Reason,
            StringComparison.Ordinal);
    }

    [Fact]
    public void Decode_UnknownTypeCommandOrNonFiniteNumber_IsANamedFormatError()
    {
        var m = new MovementEventMessage();
        byte[] type5 = MovementEventBytes.Body(1, 0, false, new byte[] { 5, 0, 0x3D, 0 });
        Assert.Contains("movement type 5", Assert.Throws<RetailDataFormatException>(() => MovementEventDecoder.Decode(type5, m)).Reason,
            StringComparison.Ordinal);
        // Style index 408 is one past command_ids.
        byte[] badStyle = MovementEventBytes.Body(1, 0, false, MovementEventBytes.Forward(408, 3, 1f));
        RetailDataFormatException e = Assert.Throws<RetailDataFormatException>(() => MovementEventDecoder.Decode(badStyle, m));
        Assert.Equal(14, e.Offset);
        byte[] nanSpeed = MovementEventBytes.Body(1, 0, false, MovementEventBytes.Forward(0x3D, 7, float.NaN));
        Assert.Contains("forward speed", Assert.Throws<RetailDataFormatException>(() => MovementEventDecoder.Decode(nanSpeed, m)).Reason,
            StringComparison.Ordinal);
        byte[] nanRunRate = MoveToPositionBody();
        BitConverter.TryWriteBytes(nanRunRate.AsSpan(60), float.NaN);
        Assert.Contains("run rate", Assert.Throws<RetailDataFormatException>(() => MovementEventDecoder.Decode(nanRunRate, m)).Reason,
            StringComparison.Ordinal);
        Assert.Throws<ArgumentNullException>(() => MovementEventDecoder.Decode(MoveToPositionBody(), null!));
    }

    [Fact]
    public void HandleMovementEvent_BadMessage_ThrowsBeforeAnythingChanges()
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = world.CreateObject(MovementEventBytes.ObjectId);
        var m = new MovementEventMessage();
        Assert.Throws<ArgumentNullException>(() => obj.HandleMovementEvent(null!));

        MovementEventDecoder.Decode(MovementEventBytes.Body(1, 0, false, MovementEventBytes.Forward(0x3D, 7, 2f), id: 0x80000099u), m);
        Assert.Contains("0x80000099", Assert.Throws<ArgumentException>(() => obj.HandleMovementEvent(m)).Message, StringComparison.Ordinal);

        // Origin x = 100,000 m: outside the position domain.
        MovementEventDecoder.Decode(MoveToPositionBody(100000f), m);
        Assert.Throws<ArgumentException>(() => obj.HandleMovementEvent(m));

        MovementEventDecoder.Decode(MoveToPositionBody(), m);
        m.Parameters = default;
        Assert.Throws<ArgumentException>(() => obj.HandleMovementEvent(m));
        m.Parameters = new MovementParameters { FailDistance = float.PositiveInfinity };
        Assert.Throws<ArgumentException>(() => obj.HandleMovementEvent(m));
        m.Parameters = new MovementParameters();
        m.MovementType = (MovementEventType)5;
        Assert.Throws<ArgumentException>(() => obj.HandleMovementEvent(m));

        Assert.Equal((ushort)0, obj.GetUpdateTime(PhysicsTimeStamp.Movement));
        Assert.Null(obj.Movement);
        Assert.False(obj.LastMoveWasAutonomous);
    }

    [Fact]
    public void DoMotion_WithoutMovementManager_AnswersNoMovementManager()
    {
        var world = new PhysicsWorld(0.0);
        PhysicsObj obj = world.CreateObject(1);
        // acclient.c:317342: no movement manager -> retail's 7 (NoMotionTable), last_move_was_autonomous already set; the
        // port names what is missing (non-retail, docs/divergences.md).
        Assert.Equal(MotionError.NoMovementManager, obj.DoMotion(MotionCommand.WalkForward, new MovementParameters()));
        Assert.Equal(7u, (uint)MotionError.NoMotionTable);
        Assert.Equal(0x10007u, (uint)MotionError.NoMovementManager);
        Assert.True(obj.LastMoveWasAutonomous);
        Assert.Equal(MotionError.NoMovementManager, obj.StopMotion(MotionCommand.WalkForward, new MovementParameters()));
        Assert.Null(obj.Movement);
        Assert.Throws<ArgumentException>(() => obj.DoMotion(MotionCommand.WalkForward, default));
    }
}
