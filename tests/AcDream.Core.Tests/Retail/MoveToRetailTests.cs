using System;
using System.Buffers.Binary;
using AcDream.Core.Physics.Managers;
using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Spatial;
using Xunit;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Motion.MoveTo;

namespace AcDream.Core.Tests.Retail;

/// <summary>MovementParameters' move-to side (CMovementDefs.c, acclient.c:346152–346343), heading_greater / heading_diff
/// (acclient.c:344714, 344737) and the constants of MoveToManager and TargetManager.</summary>
public class MoveToRetailTests
{
    private static uint Bits(float f) => BitConverter.SingleToUInt32Bits(f);

    [Fact]
    public void Flags_AreRetailsBitfield_BitByBit()
    {
        // acclient.h:31425 $9DF5898AC3667EE63853CA774377241C, bit 0 first.
        Assert.Equal(0x1u, (uint)MovementParameterFlags.CanWalk);
        Assert.Equal(0x2u, (uint)MovementParameterFlags.CanRun);
        Assert.Equal(0x4u, (uint)MovementParameterFlags.CanSidestep);
        Assert.Equal(0x8u, (uint)MovementParameterFlags.CanWalkBackwards);
        Assert.Equal(0x10u, (uint)MovementParameterFlags.CanCharge);
        Assert.Equal(0x20u, (uint)MovementParameterFlags.FailWalk);
        Assert.Equal(0x40u, (uint)MovementParameterFlags.UseFinalHeading);
        Assert.Equal(0x80u, (uint)MovementParameterFlags.Sticky);
        Assert.Equal(0x100u, (uint)MovementParameterFlags.MoveAway);
        Assert.Equal(0x200u, (uint)MovementParameterFlags.MoveTowards);
        Assert.Equal(0x400u, (uint)MovementParameterFlags.UseSpheres);
        Assert.Equal(0x800u, (uint)MovementParameterFlags.SetHoldKey);
        Assert.Equal(0x1000u, (uint)MovementParameterFlags.Autonomous);
        Assert.Equal(0x2000u, (uint)MovementParameterFlags.ModifyRawState);
        Assert.Equal(0x4000u, (uint)MovementParameterFlags.ModifyInterpretedState);
        Assert.Equal(0x8000u, (uint)MovementParameterFlags.CancelMoveTo);
        Assert.Equal(0x10000u, (uint)MovementParameterFlags.StopCompletely);
        Assert.Equal(0x20000u, (uint)MovementParameterFlags.DisableJumpDuringLink);
        Assert.Equal(0x1EE0Fu, (uint)MovementParameters.DefaultFlags);
    }

    [Fact]
    public void MovementTypes_AreRetailsNumbers()
    {
        // acclient.h:2856 MovementTypes::Type.
        Assert.Equal(0u, (uint)MovementType.Invalid);
        Assert.Equal(5u, (uint)MovementType.StopCompletely);
        Assert.Equal(6u, (uint)MovementType.MoveToObject);
        Assert.Equal(7u, (uint)MovementType.MoveToPosition);
        Assert.Equal(8u, (uint)MovementType.TurnToObject);
        Assert.Equal(9u, (uint)MovementType.TurnToHeading);
    }

    [Fact]
    public void MoveToErrors_AreRetailsWeenieErrors()
    {
        // reference/protocol_enums.tsv, WeenieError.
        Assert.Equal(0xBu, (uint)MotionError.NoMotionInterpreter);
        Assert.Equal(0x36u, (uint)MotionError.ActionCancelled);
        Assert.Equal(0x37u, (uint)MotionError.ObjectGone);
        Assert.Equal(0x38u, (uint)MotionError.NoObject);
        Assert.Equal(0x3Cu, (uint)MotionError.ITeleported);
        Assert.Equal(0x3Du, (uint)MotionError.YouChargedTooFar);
    }

    [Fact]
    public void Constants_ArePinnedByValueAndBits()
    {
        Assert.Equal(0.5f, MoveToManager.TargetTrackRadius);
        Assert.Equal(0x3F000000u, Bits(MoveToManager.TargetTrackRadius));
        Assert.Equal(0.0, MoveToManager.TargetTrackQuantum);
        Assert.Equal(20.0, MoveToManager.AuxTurnThreshold);
        Assert.Equal(1.0, MoveToManager.ProgressCheckInterval);
        Assert.Equal(0.25, MoveToManager.MinProgressRate);
        Assert.Equal(0.1, MoveToManager.QuantumMinSpeed);
        Assert.Equal(0x3FB999999999999AuL, BitConverter.DoubleToUInt64Bits(MoveToManager.QuantumMinSpeed));
        Assert.Equal(1.0, MoveToManager.QuantumChangeThreshold);
        Assert.Equal(0.5, TargetManager.UpdateInterval);
        Assert.Equal(10.0, TargetManager.TargetTimeout);
        Assert.Equal(4, TargetManager.VoyeurBuckets);
        // The EPSILON of heading_diff and towards_and_away: 0.00019999999 (float 0.0002, bits 0x3951B717).
        Assert.Equal(0x3951B717u, Bits(PhysicsGlobals.Epsilon));
        // Defaults (acclient.c:339436): distance 0.6 (0x3F19999A), fail FLT_MAX (0x7F7FFFFF), threshold 15 (0x41700000).
        var p = new MovementParameters();
        Assert.Equal(0x3F19999Au, Bits(p.DistanceToObject));
        Assert.Equal(0x7F7FFFFFu, Bits(p.FailDistance));
        Assert.Equal(0x41700000u, Bits(p.WalkRunThreshold));
        Assert.Equal(0x3F800000u, Bits(p.Speed));
    }

    // get_command (acclient.c:346174). Defaults: distance_to_object 0.6, min 0, threshold 15, flags 0x1EE0F (walk, run,
    // towards). Key: Run when (charge) or (run and (not walk or distance - 0.6 > threshold)), else None.
    [Theory]
    // towards, far: 20 - 0.6 = 19.4 > 15 -> run
    [InlineData(0x1EE0Fu, 20f, 0.6f, 0f, 15f, MotionCommand.WalkForward, HoldKey.Run, false)]
    // towards, 10 m: 9.4 <= 15 -> walk
    [InlineData(0x1EE0Fu, 10f, 0.6f, 0f, 15f, MotionCommand.WalkForward, HoldKey.None, false)]
    // 15.6 m: retail subtracts in double on the x87 (346217): 15.6f - 0.6f = 15.000000357627869 > 15 -> run (a float
    // subtraction rounds it to 15.0 and walks)
    [InlineData(0x1EE0Fu, 15.6f, 0.6f, 0f, 15f, MotionCommand.WalkForward, HoldKey.Run, false)]
    // the melee approach's threshold 1.0 (replay README): 10 - 0.6 = 9.4 > 1 -> run
    [InlineData(0x1EE0Fu, 10f, 0.6f, 0f, 1f, MotionCommand.WalkForward, HoldKey.Run, false)]
    // within distance_to_object: no command (the key still follows the rule: 0.5 - 0.6 < 15 -> walk)
    [InlineData(0x1EE0Fu, 0.5f, 0.6f, 0f, 15f, (MotionCommand)0, HoldKey.None, false)]
    // run only (no walk bit): run at any distance
    [InlineData(0x2u | 0x200u, 2f, 0.6f, 0f, 15f, MotionCommand.WalkForward, HoldKey.Run, false)]
    // walk only: never run
    [InlineData(0x1u | 0x200u, 50f, 0.6f, 0f, 15f, MotionCommand.WalkForward, HoldKey.None, false)]
    // charge: always run
    [InlineData(0x10u | 0x200u, 2f, 0.6f, 0f, 15f, MotionCommand.WalkForward, HoldKey.Run, false)]
    // neither towards nor away: as towards
    [InlineData(0x1u, 5f, 0.6f, 0f, 15f, MotionCommand.WalkForward, HoldKey.None, false)]
    // away only, nearer than min 3: walk forward, moving away
    [InlineData(0x1u | 0x100u, 2f, 0.6f, 3f, 15f, MotionCommand.WalkForward, HoldKey.None, true)]
    // away only, beyond min: none
    [InlineData(0x1u | 0x100u, 4f, 0.6f, 3f, 15f, (MotionCommand)0, HoldKey.None, false)]
    // towards and away, inside the band [min, dto] = [1, 5] at 3: 3 - 1 >= EPSILON -> none
    [InlineData(0x1u | 0x300u, 3f, 5f, 1f, 15f, (MotionCommand)0, HoldKey.None, false)]
    // towards and away, nearer than min: walk backwards, moving away
    [InlineData(0x1u | 0x300u, 0.5f, 5f, 1f, 15f, MotionCommand.WalkBackwards, HoldKey.None, true)]
    // towards and away at 0.00022999999f (0x39712C27) from min 0.00003f: in double (346157) 0.00019999999131 < EPSILON
    // 0.00019999999495 -> walk backwards, moving away (a float subtraction rounds the difference up to EPSILON and stops)
    [InlineData(0x1u | 0x300u, 0.00022999999f, 5f, 0.00003f, 15f, MotionCommand.WalkBackwards, HoldKey.None, true)]
    // towards and away, beyond dto: walk forward
    [InlineData(0x1u | 0x300u, 6f, 5f, 1f, 15f, MotionCommand.WalkForward, HoldKey.None, false)]
    public void GetCommand_IsRetailsTable(uint flags, float distance, float dto, float min, float threshold,
        MotionCommand command, HoldKey key, bool away)
    {
        var p = new MovementParameters
        {
            Flags = (MovementParameterFlags)flags, DistanceToObject = dto, MinDistance = min, WalkRunThreshold = threshold,
        };
        bool movingAway = false;
        p.GetCommand(distance, 0f, out MotionCommand c, out HoldKey k, ref movingAway);
        Assert.Equal(command, c);
        Assert.Equal(key, k);
        Assert.Equal(away, movingAway);
    }

    [Theory]
    [InlineData(MotionCommand.WalkForward, false, 0.0)]
    [InlineData(MotionCommand.WalkForward, true, 180.0)]
    [InlineData(MotionCommand.RunForward, true, 180.0)]
    [InlineData(MotionCommand.WalkBackwards, false, 180.0)]
    [InlineData(MotionCommand.WalkBackwards, true, 0.0)]
    [InlineData(MotionCommand.TurnRight, true, 0.0)]
    public void GetDesiredHeading_FacesAwayWhenMovingAway(MotionCommand c, bool away, double expected) =>
        Assert.Equal(expected, MovementParameters.GetDesiredHeading(c, away));

    [Theory]
    // |x - y| <= 180: turn right is done when x > y; turn left when x <= y.
    [InlineData(91f, 90f, MotionCommand.TurnRight, true)]
    [InlineData(90f, 90f, MotionCommand.TurnRight, false)]
    [InlineData(89f, 90f, MotionCommand.TurnLeft, true)]
    [InlineData(90f, 90f, MotionCommand.TurnLeft, true)]
    // Across the wrap (|x - y| > 180) the comparison flips: turning right to 350 from 10 is done at 355? No: 355 vs 350 is
    // within 180 (done); 5 vs 350 is across the wrap: y < x (350 < 5) is false -> greater = true for turn right.
    [InlineData(5f, 350f, MotionCommand.TurnRight, true)]
    [InlineData(345f, 10f, MotionCommand.TurnLeft, true)]
    [InlineData(15f, 10f, MotionCommand.TurnLeft, false)]
    public void HeadingGreater_IsRetails(float x, float y, MotionCommand m, bool expected) =>
        Assert.Equal(expected, MoveToManager.HeadingGreater(x, y, m));

    [Theory]
    // x - y, wrapped into [0, 360), then for a left turn 360 minus it.
    [InlineData(90f, 0f, MotionCommand.TurnRight, 90.0)]
    [InlineData(270f, 0f, MotionCommand.TurnRight, 270.0)]
    [InlineData(0f, 90f, MotionCommand.TurnRight, 270.0)]
    [InlineData(270f, 0f, MotionCommand.TurnLeft, 90.0)]
    [InlineData(10f, 10.0001f, MotionCommand.TurnLeft, 0.0)]   // |diff| < EPSILON -> 0
    public void HeadingDiff_IsRetails(float x, float y, MotionCommand m, double expected) =>
        Assert.Equal(expected, MoveToManager.HeadingDiff(x, y, m), 4);

    [Fact]
    public void UnPackNet_MoveTo_ReadsRetailsFieldOrder()
    {
        // The melee approach's parameters (replay README): bitfield 0x1EE0F, dto 0.6, min 0, fail 15, speed 1.5, threshold 1.0,
        // heading 0 — 28 bytes in UnPackNet's order (acclient.c:346343).
        Span<byte> b = stackalloc byte[32];
        BinaryPrimitives.WriteUInt32LittleEndian(b, 0x1EE0Fu);
        BinaryPrimitives.WriteUInt32LittleEndian(b[4..], 0x3F19999Au);   // 0.6
        BinaryPrimitives.WriteUInt32LittleEndian(b[8..], 0u);            // 0
        BinaryPrimitives.WriteUInt32LittleEndian(b[12..], 0x41700000u);  // 15
        BinaryPrimitives.WriteUInt32LittleEndian(b[16..], 0x3FC00000u);  // 1.5
        BinaryPrimitives.WriteUInt32LittleEndian(b[20..], 0x3F800000u);  // 1.0
        BinaryPrimitives.WriteUInt32LittleEndian(b[24..], 0x42B40000u);  // 90
        BinaryPrimitives.WriteUInt32LittleEndian(b[28..], 0xDEADBEEFu);  // not read
        MovementParameters p = MovementParameters.UnPackNet(b, MovementType.MoveToObject, out int read);
        Assert.Equal(28, read);
        Assert.Equal(0x1EE0Fu, (uint)p.Flags);
        Assert.Equal(0.6f, p.DistanceToObject);
        Assert.Equal(0f, p.MinDistance);
        Assert.Equal(15f, p.FailDistance);
        Assert.Equal(1.5f, p.Speed);
        Assert.Equal(1f, p.WalkRunThreshold);
        Assert.Equal(90f, p.DesiredHeading);
        // Not on the wire: retail's defaults stay.
        Assert.Equal(HoldKey.Invalid, p.HoldKeyToApply);
        Assert.Equal(0u, p.ContextId);

        Span<byte> back = stackalloc byte[28];
        Assert.Equal(28, p.PackNet(back, MovementType.MoveToPosition));
        Assert.True(back.SequenceEqual(b[..28]));
    }

    [Fact]
    public void UnPackNet_TurnTo_ReadsBitfieldSpeedHeading()
    {
        Span<byte> b = stackalloc byte[12];
        BinaryPrimitives.WriteUInt32LittleEndian(b, 0x10000u);           // stop completely
        BinaryPrimitives.WriteUInt32LittleEndian(b[4..], 0x3FC00000u);   // 1.5
        BinaryPrimitives.WriteUInt32LittleEndian(b[8..], 0x43870000u);   // 270
        MovementParameters p = MovementParameters.UnPackNet(b, MovementType.TurnToHeading, out int read);
        Assert.Equal(12, read);
        Assert.Equal(MovementParameterFlags.StopCompletely, p.Flags);
        Assert.Equal(1.5f, p.Speed);
        Assert.Equal(270f, p.DesiredHeading);
        Assert.Equal(0.6f, p.DistanceToObject);   // default kept
        Assert.Equal(MovementParameters.TurnToNetSize, read);
    }

    [Fact]
    public void PackAndUnPack_RoundTripAllTenFields()
    {
        var p = new MovementParameters
        {
            Flags = (MovementParameterFlags)0x2C5u, DistanceToObject = 1.5f, MinDistance = 0.25f, FailDistance = 30f,
            DesiredHeading = 45f, Speed = 2f, WalkRunThreshold = 3f, ContextId = 7, HoldKeyToApply = HoldKey.Run, ActionStamp = 9,
        };
        Span<byte> b = stackalloc byte[40];
        Assert.Equal(40, p.Pack(b));
        // Retail's Pack order: fail distance (offset 12) before desired heading (16), then speed (20).
        Assert.Equal(0x41F00000u, BinaryPrimitives.ReadUInt32LittleEndian(b[12..]));   // 30
        Assert.Equal(0x42340000u, BinaryPrimitives.ReadUInt32LittleEndian(b[16..]));   // 45
        Assert.Equal(2u, BinaryPrimitives.ReadUInt32LittleEndian(b[32..]));            // Run
        Assert.Equal(p, MovementParameters.UnPack(b));
    }

    [Fact]
    public void UnPackNet_BadInput_IsRefused()
    {
        Assert.Throws<ArgumentException>(() => MovementParameters.UnPackNet(new byte[28], MovementType.RawCommand, out _));
        Assert.Throws<RetailDataFormatException>(() => MovementParameters.UnPackNet(new byte[27], MovementType.MoveToPosition, out _));
        Assert.Throws<RetailDataFormatException>(() => MovementParameters.UnPackNet(new byte[11], MovementType.TurnToObject, out _));
        byte[] nan = new byte[12];
        BinaryPrimitives.WriteUInt32LittleEndian(nan.AsSpan(4), 0x7FC00000u);
        Assert.Throws<RetailDataFormatException>(() => MovementParameters.UnPackNet(nan, MovementType.TurnToHeading, out _));
        byte[] fast = new byte[12];
        BinaryPrimitives.WriteUInt32LittleEndian(fast.AsSpan(4), BitConverter.SingleToUInt32Bits(101f));   // beyond ±100
        Assert.Throws<RetailDataFormatException>(() => MovementParameters.UnPackNet(fast, MovementType.TurnToHeading, out _));
        BinaryPrimitives.WriteUInt32LittleEndian(fast.AsSpan(4), BitConverter.SingleToUInt32Bits(100f));   // the bound itself
        Assert.Equal(100f, MovementParameters.UnPackNet(fast, MovementType.TurnToHeading, out _).Speed);
        Assert.Equal(0x42C80000u, BitConverter.SingleToUInt32Bits(MovementParameters.MaxMoveToSpeed));
        Assert.Throws<ArgumentException>(() => new MovementParameters().PackNet(new byte[27], MovementType.MoveToObject));
        Assert.Throws<ArgumentException>(() => new MovementParameters().PackNet(new byte[28], MovementType.StopCompletely));
        Assert.Throws<ArgumentException>(() => new MovementParameters().Pack(new byte[39]));
        Assert.Throws<RetailDataFormatException>(() => MovementParameters.UnPack(new byte[39]));
    }
}
