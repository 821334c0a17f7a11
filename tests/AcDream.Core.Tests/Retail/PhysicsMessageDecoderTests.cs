using System;
using System.Numerics;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Fixtures.Wire;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Motion.Wire;
using AcDream.Core.Physics.Objects;
using Xunit;

namespace AcDream.Core.Tests.Retail;

// The layouts of retail's readers: PositionPack::UnPack (acclient.c:323686), CM_Physics::DispatchSB_* (709598-710002),
// PhysicsDesc::UnPack (331864), ObjDesc::UnPack (469826). Bodies written field by field, decoded, every field checked.
public class PhysicsMessageDecoderTests
{
    // +Aldis' login pose (first-login-walk-jump, msg 22): q = (0.275028974, 0, 0, -0.961435914), flags 0x34 = grounded, no
    // x, no y: the body holds w and z only (8 bytes of quaternion).
    [Fact]
    public void UpdatePosition_OmittedComponentsReadAsZero_TheRestInOrder()
    {
        var q = new Quaternion(0f, 0f, -0.961435914f, 0.275028974f);
        byte[] body = PhysicsMessageBytes.UpdatePosition(0x50000002u, 0x34, 0xA9B4002Au, new Vector3(126.643669f, 37.0984497f, 94.0050049f),
            q, instance: 90, position: 7, teleport: 2, forcePosition: 3);
        // 4 id + 4 flags + 4 cell + 12 origin + 8 (w, z) + 8 stamps.
        Assert.Equal(40, body.Length);
        var m = new UpdatePositionMessage();
        PhysicsMessageDecoder.Decode(body, m);
        Assert.Equal(0x50000002u, m.ObjectId);
        Assert.Equal(PositionPackFlags.IsGrounded | PositionPackFlags.OrientationHasNoX | PositionPackFlags.OrientationHasNoY, m.Flags);
        Assert.Equal(0xA9B4002Au, m.Position.ObjCellId);
        Assert.Equal(new Vector3(126.643669f, 37.0984497f, 94.0050049f), m.Position.Frame.Origin);
        Assert.Equal(0.275028974f, m.Position.Frame.Rotation.W, 6);
        Assert.Equal(0f, m.Position.Frame.Rotation.X);
        Assert.Equal(0f, m.Position.Frame.Rotation.Y);
        Assert.Equal(-0.961435914f, m.Position.Frame.Rotation.Z, 6);
        Assert.True(m.HasContact);
        Assert.Equal(Vector3.Zero, m.Velocity);
        Assert.Equal(0u, m.PlacementId);
        Assert.Equal((ushort)90, m.InstanceTimestamp);
        Assert.Equal((ushort)7, m.PositionTimestamp);
        Assert.Equal((ushort)2, m.TeleportTimestamp);
        Assert.Equal((ushort)3, m.ForcePositionTimestamp);
    }

    // A monster's pack, flags 0x36 | 0x01: velocity and placement id 0x65 after the quaternion; not grounded without 0x04.
    [Fact]
    public void UpdatePosition_VelocityAndPlacementFollowTheQuaternion()
    {
        var q = Quaternion.Identity;
        byte[] body = PhysicsMessageBytes.UpdatePosition(0x8000033Au, 0x33, 0xA9B30012u, new Vector3(36.9f, 77.6f, 94f), q,
            instance: 1, position: 46, velocity: new Vector3(1f, 2f, 3f), placementId: 0x65);
        var m = new UpdatePositionMessage();
        PhysicsMessageDecoder.Decode(body, m);
        Assert.Equal(new Vector3(1f, 2f, 3f), m.Velocity);
        Assert.Equal(0x65u, m.PlacementId);
        Assert.False(m.HasContact);
        Assert.Equal(1f, m.Position.Frame.Rotation.W);
    }

    [Fact]
    public void UpdatePosition_NormFarFromOne_UnknownFlags_Truncated_TrailingBytes_AreRefused()
    {
        var m = new UpdatePositionMessage();
        // Flags 0x74 keep only w: w = 0.5 gives |q|² = 0.25.
        byte[] halfW = PhysicsMessageBytes.UpdatePosition(1, 0x74, 0xA9B40001u, new Vector3(1f, 1f, 1f), new Quaternion(0f, 0f, 0f, 0.5f), 1, 1);
        var e = Assert.Throws<RetailDataFormatException>(() => PhysicsMessageDecoder.Decode(halfW, m));
        Assert.Equal(24, e.Offset); // the quaternion's first byte
        // Omitting w of (w, x, y, z) = (0.6, 0, 0, 0.8) leaves |q|² = 0.64: refused; both sent is a unit quaternion.
        var q = new Quaternion(0f, 0f, 0.8f, 0.6f);
        Assert.Throws<RetailDataFormatException>(() =>
            PhysicsMessageDecoder.Decode(PhysicsMessageBytes.UpdatePosition(1, 0x38, 0xA9B40001u, Vector3.One, q, 1, 1), m));
        PhysicsMessageDecoder.Decode(PhysicsMessageBytes.UpdatePosition(1, 0x30, 0xA9B40001u, Vector3.One, q, 1, 1), m);
        // Flag 0x80 is not a position flag.
        byte[] unknown = PhysicsMessageBytes.UpdatePosition(1, 0x04, 0xA9B40001u, Vector3.One, Quaternion.Identity, 1, 1);
        unknown[4] = 0x84;
        Assert.Equal(4, Assert.Throws<RetailDataFormatException>(() => PhysicsMessageDecoder.Decode(unknown, m)).Offset);
        byte[] good = PhysicsMessageBytes.UpdatePosition(1, 0x04, 0xA9B40001u, Vector3.One, Quaternion.Identity, 1, 1);
        Assert.Throws<RetailDataFormatException>(() => PhysicsMessageDecoder.Decode(good.AsSpan(0, good.Length - 1), m));
        Assert.Throws<RetailDataFormatException>(() => PhysicsMessageDecoder.Decode([.. good, 0], m));
        byte[] nan = PhysicsMessageBytes.UpdatePosition(1, 0x04, 0xA9B40001u, new Vector3(float.NaN, 0f, 0f), Quaternion.Identity, 1, 1);
        Assert.Throws<RetailDataFormatException>(() => PhysicsMessageDecoder.Decode(nan, m));
    }

    [Fact]
    public void SmallMessages_ReadTheirFieldsInRetailOrder()
    {
        var v = new VectorUpdateMessage();
        PhysicsMessageDecoder.Decode(PhysicsMessageBytes.VectorUpdate(0x5000001Eu, new Vector3(0f, 0f, 3.56924868f), new Vector3(0f, 0f, 1f), 1, 2), v);
        Assert.Equal((0x5000001Eu, new Vector3(0f, 0f, 3.56924868f), new Vector3(0f, 0f, 1f), (ushort)1, (ushort)2),
            (v.ObjectId, v.Velocity, v.Omega, v.InstanceTimestamp, v.VectorTimestamp));

        var s = new SetStateMessage();
        PhysicsMessageDecoder.Decode(PhysicsMessageBytes.SetState(7, 0x4408, 3, 4), s);
        Assert.Equal((7u, PhysicsState.Hidden | PhysicsState.Gravity | PhysicsState.ReportCollisions, (ushort)3, (ushort)4),
            (s.ObjectId, s.State, s.InstanceTimestamp, s.StateTimestamp));

        var p = new ParentEventMessage();
        PhysicsMessageDecoder.Decode(PhysicsMessageBytes.ParentEvent(0x7A9B4026u, 0x80000010u, 1, 0x65, 5, 6), p);
        Assert.Equal((0x7A9B4026u, 0x80000010u, 1u, 0x65u, (ushort)5, (ushort)6),
            (p.ParentId, p.ChildId, p.Location, p.PlacementId, p.ParentInstanceTimestamp, p.ChildPositionTimestamp));

        var k = new PickupEventMessage();
        PhysicsMessageDecoder.Decode(PhysicsMessageBytes.PickupEvent(9, 1, 2), k);
        Assert.Equal((9u, (ushort)1, (ushort)2), (k.ObjectId, k.InstanceTimestamp, k.PositionTimestamp));

        var t = new PlayerTeleportMessage();
        byte[] tb = PhysicsMessageBytes.PlayerTeleport(0x1234);
        Assert.Equal(4, tb.Length);
        PhysicsMessageDecoder.Decode(tb, t);
        Assert.Equal((ushort)0x1234, t.TeleportTimestamp);
        // The pad is part of the body: two bytes alone are short.
        Assert.Throws<RetailDataFormatException>(() => PhysicsMessageDecoder.Decode(tb.AsSpan(0, 2), t));

        var d = new DeleteObjectMessage();
        byte[] db = PhysicsMessageBytes.DeleteObject(0x80000355u, 4);
        Assert.Equal(8, db.Length);
        PhysicsMessageDecoder.Decode(db, d);
        Assert.Equal((0x80000355u, (ushort)4), (d.ObjectId, d.InstanceTimestamp));
    }

    [Fact]
    public void PhysicsDesc_EveryFieldInUnPackOrder_DefaultsForTheRest()
    {
        byte[] movement = [0, 0, 0x3D, 0, 0, 0, 0, 0]; // type 0, style index 0x3D, an empty state
        byte[] body = PhysicsMessageBytes.PhysicsDesc(PhysicsMessageBytes.CreateObjectStart(0x80000336u), 0x408,
            new PhysicsMessageBytes.Stamps(Position: 1, Movement: 2, State: 3, Vector: 4, Teleport: 5, ServerControl: 6,
                ForcePosition: 7, ObjDesc: 8, Instance: 9),
            movement: movement, autonomous: true,
            position: (0xA9B40025u, new Vector3(100f, 100f, 94f), new Quaternion(0f, 0f, 0.6f, 0.8f)),
            motionTable: 0x09000001u, setup: 0x02000001u, scale: 1.5f, friction: 0.5f, elasticity: 0.2f, translucency: 0.3f,
            velocity: new Vector3(1f, 0f, 0f), omega: new Vector3(0f, 0f, 0.5f), defaultScript: 0x33).ToArray();
        var m = new CreateObjectMessage();
        PhysicsMessageDecoder.Decode(body, m);
        PhysicsDesc d = m.Physics;
        Assert.Equal(0x80000336u, m.ObjectId);
        Assert.Equal(body.Length, m.WeenieDescOffset);
        Assert.Equal((PhysicsState)0x408, d.State);
        Assert.Equal(movement, d.MovementBuffer.ToArray());
        Assert.True(d.AutonomousMovement);
        Assert.Equal(0xA9B40025u, d.Position.ObjCellId);
        Assert.Equal(new Vector3(100f, 100f, 94f), d.Position.Frame.Origin);
        Assert.Equal(0.8f, d.Position.Frame.Rotation.W, 6);
        Assert.Equal((0x09000001u, 0x02000001u, 0u, 0u), (d.MotionTableId, d.SetupId, d.SoundTableId, d.ParentId));
        Assert.Equal((1.5f, 0.5f, 0.2f, 0.3f), (d.Scale, d.Friction, d.Elasticity, d.Translucency));
        Assert.Equal((new Vector3(1f, 0f, 0f), Vector3.Zero, new Vector3(0f, 0f, 0.5f)), (d.Velocity, d.Acceleration, d.Omega));
        Assert.Equal(0x33u, d.DefaultScript);
        for (int i = 0; i < 9; i++)
        {
            Assert.Equal((ushort)(i + 1), d.GetTimestamp((PhysicsTimeStamp)i));
        }

        // A bare description: retail's defaults (state 0x400C08, friction 0.95, elasticity 0.05, scale 1, no position).
        var bare = new PhysicsDesc();
        PhysicsMessageDecoder.DecodePhysicsDesc(PhysicsMessageBytes.PhysicsDesc(new RetailDataWriter(), 0x400C08,
            new PhysicsMessageBytes.Stamps(Instance: 1)).ToArray(), bare);
        Assert.Equal((PhysicsDesc.DefaultState, 0.95f, 0.05f, 1f, 0u), (bare.State, bare.Friction, bare.Elasticity, bare.Scale, bare.Position.ObjCellId));
        Assert.Equal(0, bare.MovementBufferLength);
    }

    [Fact]
    public void PhysicsDesc_ParentAndChildren_AndTheVisualDescriptionsChanges_AreRead()
    {
        // ObjDesc with one palette (base id 0x0400007E as a two-word id, one sub-palette), one texture change and one
        // part change, then padding to 4.
        var w = new RetailDataWriter().UInt32(0x80000578u).Byte(0x11).Byte(1).Byte(1).Byte(1)
            .UInt16(0x8400).UInt16(0x007E)           // palette id, top bit: a second word
            .UInt16(0x0BEF).Byte(0).Byte(24)         // sub-palette id (one word), offset, length
            .Byte(3).UInt16(0x0123).UInt16(0x0456)   // texture change: part 3, old, new
            .Byte(2).UInt16(0x0789)                  // part change: part 2, gfx id
            .Align4();
        w.UInt32(0x60u).UInt32(0x400C08).UInt32(0x80000577u).UInt32(1).UInt32(2).UInt32(0x80000579u).UInt32(2).UInt32(0x8000057Au).UInt32(3);
        for (int i = 0; i < 9; i++) w.UInt16(0);
        byte[] body = w.Align4().ToArray();
        var m = new CreateObjectMessage();
        PhysicsMessageDecoder.Decode(body, m);
        Assert.Equal((0x80000577u, 1u), (m.Physics.ParentId, m.Physics.ParentLocation));
        Assert.Equal(2, m.Physics.ChildCount);
        Assert.Equal((0x80000579u, 2u, 0x8000057Au, 3u),
            (m.Physics.GetChildId(0), m.Physics.GetChildLocation(0), m.Physics.GetChildId(1), m.Physics.GetChildLocation(1)));
        // Not 0x11: not a visual description.
        body[4] = 0x12;
        Assert.Equal(4, Assert.Throws<RetailDataFormatException>(() => PhysicsMessageDecoder.Decode(body, m)).Offset);
    }
}
