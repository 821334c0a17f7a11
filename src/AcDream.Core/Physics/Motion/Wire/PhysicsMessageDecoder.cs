using System;
using System.Numerics;
using AcDream.Core.Physics.Format;
using AcDream.Core.Physics.Objects;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Motion.Wire;

/// <summary>
/// Decodes the server's physics messages (the body: the bytes after the opcode) into reusable message objects, as retail's
/// <c>CM_Physics::DispatchSB_*</c> and the packs they call read them: UpdatePosition (0xF748, <c>PositionPack::UnPack</c>),
/// VectorUpdate (0xF74E), SetState (0xF74B), ParentEvent (0xF749), PickupEvent (0xF74A), PlayerTeleport (0xF751),
/// DeleteObject (0xF747) and the physics part of CreateObject (0xF745, <c>PhysicsDesc::UnPack</c>); the MovementEvent
/// (0xF74C) is <see cref="MovementEventDecoder"/>'s. Nothing is applied; nothing is allocated once the message is warm.
/// </summary>
/// <remarks>Every decode consumes the body exactly (padding included) or throws <see cref="RetailDataFormatException"/>
/// naming the field and its offset: a truncated body, bytes left over, a NaN or infinite number, unknown flag bits, or a
/// quaternion whose norm is far from 1 (<see cref="QuaternionNormTolerance"/>). The message is then unspecified.</remarks>
public static class PhysicsMessageDecoder
{
    /// <summary>How far |q|² of a position's quaternion may be from 1 before the body is refused as corrupt (0.01): the
    /// wire drops components the sender knows are 0, so a norm far from 1 means a wrong flag or a damaged body. Within
    /// it the quaternion is stored normalised.</summary>
    public const double QuaternionNormTolerance = 0.01;

    private const uint KnownPositionFlags = 0x7F;
    private const uint KnownPhysicsDescFlags = 0x7FFFF;

    /// <summary>Decodes an UpdatePosition body (0xF748): <c>u32</c> object, then the position pack: <c>u32</c> flags,
    /// <c>u32</c> cell, origin x, y, z, the quaternion's w, x, y, z each unless its flag omits it (0), the velocity
    /// (flag 0x01), the placement id (0x02), then the instance, position, teleport and force-position stamps (<c>u16</c>
    /// each).</summary>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    /// <exception cref="RetailDataFormatException">The bytes are not an UpdatePosition (see the remarks).</exception>
    // retail: PositionPack::UnPack (acclient.c:323686)
    public static void Decode(ReadOnlySpan<byte> body, UpdatePositionMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        var r = new RetailDataReader(body, "UpdatePosition");
        message.ObjectId = r.ReadUInt32("object id");
        int flagsAt = r.Offset;
        uint flags = r.ReadUInt32("flags");
        if ((flags & ~KnownPositionFlags) != 0)
        {
            throw r.ErrorAt(flagsAt, $"unknown position flags 0x{flags & ~KnownPositionFlags:X}");
        }

        message.Flags = (PositionPackFlags)flags;
        // Position::UnPackOrigin (acclient.c:467193): the cell and the origin.
        uint cell = r.ReadUInt32("cell");
        Vector3 origin = r.ReadFiniteVector3("origin");
        int qAt = r.Offset;
        float qw = (flags & 0x08) != 0 ? 0f : r.ReadFiniteSingle("qw");
        float qx = (flags & 0x10) != 0 ? 0f : r.ReadFiniteSingle("qx");
        float qy = (flags & 0x20) != 0 ? 0f : r.ReadFiniteSingle("qy");
        float qz = (flags & 0x40) != 0 ? 0f : r.ReadFiniteSingle("qz");
        message.Position = new Position(cell, CheckedFrame(ref r, qAt, origin, qw, qx, qy, qz));
        message.Velocity = (flags & 0x01) != 0 ? r.ReadFiniteVector3("velocity") : Vector3.Zero;
        message.PlacementId = (flags & 0x02) != 0 ? r.ReadUInt32("placement id") : 0u;
        message.HasContact = (flags & 0x04) != 0;
        message.InstanceTimestamp = r.ReadUInt16("instance stamp");
        message.PositionTimestamp = r.ReadUInt16("position stamp");
        message.TeleportTimestamp = r.ReadUInt16("teleport stamp");
        message.ForcePositionTimestamp = r.ReadUInt16("force-position stamp");
        End(ref r);
    }

    /// <summary>Decodes a VectorUpdate body (0xF74E): <c>u32</c> object, velocity, omega, <c>u16</c> instance and vector
    /// stamps (32 bytes).</summary>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    /// <exception cref="RetailDataFormatException">The bytes are not a VectorUpdate.</exception>
    // retail: CM_Physics::DispatchSB_VectorUpdate (acclient.c:710002)
    public static void Decode(ReadOnlySpan<byte> body, VectorUpdateMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        var r = new RetailDataReader(body, "VectorUpdate");
        message.ObjectId = r.ReadUInt32("object id");
        message.Velocity = r.ReadFiniteVector3("velocity");
        message.Omega = r.ReadFiniteVector3("omega");
        message.InstanceTimestamp = r.ReadUInt16("instance stamp");
        message.VectorTimestamp = r.ReadUInt16("vector stamp");
        End(ref r);
    }

    /// <summary>Decodes a SetState body (0xF74B): <c>u32</c> object, <c>u32</c> state, <c>u16</c> instance and state
    /// stamps (12 bytes).</summary>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    /// <exception cref="RetailDataFormatException">The bytes are not a SetState.</exception>
    // retail: CM_Physics::DispatchSB_SetState (acclient.c:709956)
    public static void Decode(ReadOnlySpan<byte> body, SetStateMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        var r = new RetailDataReader(body, "SetState");
        message.ObjectId = r.ReadUInt32("object id");
        message.State = (PhysicsState)r.ReadUInt32("state");
        message.InstanceTimestamp = r.ReadUInt16("instance stamp");
        message.StateTimestamp = r.ReadUInt16("state stamp");
        End(ref r);
    }

    /// <summary>Decodes a ParentEvent body (0xF749): <c>u32</c> parent, child, location, placement id, <c>u16</c> the
    /// parent's instance and the child's position stamps (20 bytes).</summary>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    /// <exception cref="RetailDataFormatException">The bytes are not a ParentEvent.</exception>
    // retail: CM_Physics::DispatchSB_ParentEvent (acclient.c:709841)
    public static void Decode(ReadOnlySpan<byte> body, ParentEventMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        var r = new RetailDataReader(body, "ParentEvent");
        message.ParentId = r.ReadUInt32("parent id");
        message.ChildId = r.ReadUInt32("child id");
        message.Location = r.ReadUInt32("location");
        message.PlacementId = r.ReadUInt32("placement id");
        message.ParentInstanceTimestamp = r.ReadUInt16("parent instance stamp");
        message.ChildPositionTimestamp = r.ReadUInt16("child position stamp");
        End(ref r);
    }

    /// <summary>Decodes a PickupEvent body (0xF74A): <c>u32</c> object, <c>u16</c> instance and position stamps (8 bytes).</summary>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    /// <exception cref="RetailDataFormatException">The bytes are not a PickupEvent.</exception>
    // retail: CM_Physics::DispatchSB_PickupEvent (acclient.c:709898)
    public static void Decode(ReadOnlySpan<byte> body, PickupEventMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        var r = new RetailDataReader(body, "PickupEvent");
        message.ObjectId = r.ReadUInt32("object id");
        message.InstanceTimestamp = r.ReadUInt16("instance stamp");
        message.PositionTimestamp = r.ReadUInt16("position stamp");
        End(ref r);
    }

    /// <summary>Decodes a PlayerTeleport body (0xF751): <c>u16</c> teleport stamp, padding to 4 bytes.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    /// <exception cref="RetailDataFormatException">The bytes are not a PlayerTeleport.</exception>
    // retail: CM_Physics::DispatchSB_PlayerTeleport (acclient.c:709628)
    public static void Decode(ReadOnlySpan<byte> body, PlayerTeleportMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        var r = new RetailDataReader(body, "PlayerTeleport");
        message.TeleportTimestamp = r.ReadUInt16("teleport stamp");
        r.Align4();
        End(ref r);
    }

    /// <summary>Decodes a DeleteObject body (0xF747): <c>u32</c> object, <c>u16</c> instance stamp, padding to 4 bytes.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    /// <exception cref="RetailDataFormatException">The bytes are not a DeleteObject.</exception>
    // retail: CM_Physics::DispatchSB_DeleteObject (acclient.c:709598)
    public static void Decode(ReadOnlySpan<byte> body, DeleteObjectMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        var r = new RetailDataReader(body, "DeleteObject");
        message.ObjectId = r.ReadUInt32("object id");
        message.InstanceTimestamp = r.ReadUInt16("instance stamp");
        r.Align4();
        End(ref r);
    }

    /// <summary>Decodes a CreateObject body (0xF745) up to its weenie description: <c>u32</c> object, the visual
    /// description (retail <c>ObjDesc::UnPack</c>: the byte 0x11, palette, texture and part-change counts, the changes,
    /// padding to 4; read past), then the physics description (<see cref="DecodePhysicsDesc"/>). The weenie description
    /// is left to the client (<see cref="CreateObjectMessage.WeenieDescOffset"/>).</summary>
    /// <exception cref="ArgumentNullException"><paramref name="message"/> is null.</exception>
    /// <exception cref="RetailDataFormatException">The bytes are not a CreateObject's object, visual and physics parts.</exception>
    // retail: CM_Physics::DispatchSB_CreateObject (acclient.c:709716), through the physics description
    public static void Decode(ReadOnlySpan<byte> body, CreateObjectMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        var r = new RetailDataReader(body, "CreateObject");
        message.ObjectId = r.ReadUInt32("object id");
        SkipObjDesc(ref r);
        UnPackPhysicsDesc(ref r, message.Physics);
        message.WeenieDescOffset = r.Offset;
    }

    /// <summary>Decodes a physics description alone (its bytes start 4-byte aligned and must be consumed exactly).</summary>
    /// <exception cref="ArgumentNullException"><paramref name="desc"/> is null.</exception>
    /// <exception cref="RetailDataFormatException">Truncated, bytes left over, unknown flag bits, a NaN or infinite
    /// number, a rotation that is not a unit quaternion, or a child count that cannot fit.</exception>
    // retail: PhysicsDesc::UnPack (acclient.c:331864)
    public static void DecodePhysicsDesc(ReadOnlySpan<byte> data, PhysicsDesc desc)
    {
        ArgumentNullException.ThrowIfNull(desc);
        var r = new RetailDataReader(data, "PhysicsDesc");
        UnPackPhysicsDesc(ref r, desc);
        End(ref r);
    }

    // retail: PhysicsDesc::UnPack (acclient.c:331864)
    private static void UnPackPhysicsDesc(ref RetailDataReader r, PhysicsDesc d)
    {
        d.Reset();
        int flagsAt = r.Offset;
        uint flags = r.ReadUInt32("PhysicsDesc flags");
        if ((flags & ~KnownPhysicsDescFlags) != 0)
        {
            throw r.ErrorAt(flagsAt, $"unknown PhysicsDesc flags 0x{flags & ~KnownPhysicsDescFlags:X}");
        }

        d.Flags = (PhysicsDescFlags)flags;
        d.State = (PhysicsState)r.ReadUInt32("state");
        if ((flags & 0x10000) != 0)
        {
            int length = r.ReadCount("movement buffer length", 1);
            if (length != 0)
            {
                r.Rest[..length].CopyTo(d.MovementBufferFor(length));
                r.Skip(length, "movement buffer");
                d.AutonomousMovement = r.ReadUInt32("autonomous movement") != 0;
            }
        }
        else if ((flags & 0x20000) != 0)
        {
            d.AnimationFrameId = r.ReadUInt32("animation frame id");
        }

        if ((flags & 0x8000) != 0)
        {
            // Position::UnPack (acclient.c:467120): the cell, then Frame::UnPack (origin, w, x, y, z).
            uint cell = r.ReadUInt32("position cell");
            d.Position = new Position(cell, r.ReadFrame("position frame"));
        }

        d.MotionTableId = (flags & 0x2) != 0 ? r.ReadUInt32("motion table id") : 0u;
        d.SoundTableId = (flags & 0x800) != 0 ? r.ReadUInt32("sound table id") : 0u;
        d.PhysicsScriptTableId = (flags & 0x1000) != 0 ? r.ReadUInt32("physics script table id") : 0u;
        d.SetupId = (flags & 0x1) != 0 ? r.ReadUInt32("setup id") : 0u;
        if ((flags & 0x20) != 0)
        {
            d.ParentId = r.ReadUInt32("parent id");
            d.ParentLocation = r.ReadUInt32("parent location");
        }

        if ((flags & 0x40) != 0)
        {
            int n = r.ReadCount("children", 8);
            d.SetChildCount(n);
            for (int i = 0; i < n; i++)
            {
                uint id = r.ReadUInt32("child id");
                d.SetChild(i, id, r.ReadUInt32("child location"));
            }
        }

        if ((flags & 0x80) != 0)
        {
            d.Scale = r.ReadFiniteSingle("scale");
        }

        if ((flags & 0x100) != 0)
        {
            d.Friction = r.ReadFiniteSingle("friction");
        }

        if ((flags & 0x200) != 0)
        {
            d.Elasticity = r.ReadFiniteSingle("elasticity");
        }

        if ((flags & 0x40000) != 0)
        {
            d.Translucency = r.ReadFiniteSingle("translucency");
        }

        if ((flags & 0x4) != 0)
        {
            d.Velocity = r.ReadFiniteVector3("velocity");
        }

        if ((flags & 0x8) != 0)
        {
            d.Acceleration = r.ReadFiniteVector3("acceleration");
        }

        if ((flags & 0x10) != 0)
        {
            d.Omega = r.ReadFiniteVector3("omega");
        }

        d.DefaultScript = (flags & 0x2000) != 0 ? r.ReadUInt32("default script") : 0u;
        d.DefaultScriptIntensity = (flags & 0x4000) != 0 ? r.ReadFiniteSingle("default script intensity") : 0f;
        for (int i = 0; i < 9; i++)
        {
            d.SetTimestamp(i, r.ReadUInt16("timestamp"));
        }

        r.Align4();
    }

    // retail: ObjDesc::UnPack (acclient.c:469826), read past: 0x11, the counts, the palette id and sub-palettes, the
    // texture and part changes (ids as Unpack_AsDataIDOfKnownType: a u16, and a second u16 when its top bit is set), align 4.
    private static void SkipObjDesc(ref RetailDataReader r)
    {
        int at = r.Offset;
        if (r.ReadByte("ObjDesc marker") != 0x11)
        {
            throw r.ErrorAt(at, "the visual description does not start with 0x11");
        }

        int palettes = r.ReadByte("palette count");
        int textures = r.ReadByte("texture change count");
        int parts = r.ReadByte("part change count");
        if (palettes > 0)
        {
            SkipKnownTypeId(ref r);
            for (int i = 0; i < palettes; i++)
            {
                SkipKnownTypeId(ref r);
                r.Skip(2, "sub-palette offset and length");
            }
        }

        for (int i = 0; i < textures; i++)
        {
            r.Skip(1, "texture change part");
            SkipKnownTypeId(ref r);
            SkipKnownTypeId(ref r);
        }

        for (int i = 0; i < parts; i++)
        {
            r.Skip(1, "part change index");
            SkipKnownTypeId(ref r);
        }

        r.Align4();
    }

    private static void SkipKnownTypeId(ref RetailDataReader r)
    {
        if ((r.ReadUInt16("data id") & 0x8000) != 0)
        {
            r.Skip(2, "data id low word");
        }
    }

    // The quaternion as received (its omitted components 0): refused when |q|² is far from 1, stored normalised.
    private static Frame CheckedFrame(ref RetailDataReader r, int at, Vector3 origin, float qw, float qx, float qy, float qz)
    {
        double norm = (double)qw * qw + (double)qx * qx + (double)qy * qy + (double)qz * qz;
        if (!(Math.Abs(norm - 1.0) <= QuaternionNormTolerance))
        {
            throw r.ErrorAt(at, $"quaternion |q|² = {norm:G6} is far from 1 (a wrong omission flag or a damaged body)");
        }

        Frame f = Frame.Identity;
        f.Origin = origin;
        f.SetRotate(qw, qx, qy, qz);
        return f;
    }

    private static void End(ref RetailDataReader r)
    {
        if (r.Remaining != 0)
        {
            throw r.Error($"{r.Remaining} bytes after the message");
        }
    }
}
