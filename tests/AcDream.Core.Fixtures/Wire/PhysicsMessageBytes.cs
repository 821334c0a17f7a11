using System.Numerics;
using AcDream.Core.Fixtures.Data;

namespace AcDream.Core.Fixtures.Wire;

/// <summary>
/// Builds the bodies (the bytes after the opcode) of the server's physics messages as the server writes them, field by
/// field: UpdatePosition 0xF748, VectorUpdate 0xF74E, SetState 0xF74B, ParentEvent 0xF749, PickupEvent 0xF74A,
/// PlayerTeleport 0xF751, DeleteObject 0xF747 and CreateObject 0xF745 (an empty visual description, the physics
/// description, no weenie description). The test-side mirror of <c>PhysicsMessageDecoder</c>.
/// </summary>
public static class PhysicsMessageBytes
{
    /// <summary>An UpdatePosition body. The quaternion's components whose omission flag (0x08 w, 0x10 x, 0x20 y, 0x40 z)
    /// is set in <paramref name="flags"/> are not written; the velocity is written with flag 0x01, the placement id with
    /// 0x02.</summary>
    public static byte[] UpdatePosition(uint objectId, uint flags, uint cell, Vector3 origin, Quaternion q,
                                        ushort instance, ushort position, ushort teleport = 0, ushort forcePosition = 0,
                                        Vector3 velocity = default, uint placementId = 0)
    {
        var w = new RetailDataWriter().UInt32(objectId).UInt32(flags).UInt32(cell).Vector3(origin);
        if ((flags & 0x08) == 0) w.Single(q.W);
        if ((flags & 0x10) == 0) w.Single(q.X);
        if ((flags & 0x20) == 0) w.Single(q.Y);
        if ((flags & 0x40) == 0) w.Single(q.Z);
        if ((flags & 0x01) != 0) w.Vector3(velocity);
        if ((flags & 0x02) != 0) w.UInt32(placementId);
        return w.UInt16(instance).UInt16(position).UInt16(teleport).UInt16(forcePosition).ToArray();
    }

    /// <summary>A VectorUpdate body.</summary>
    public static byte[] VectorUpdate(uint objectId, Vector3 velocity, Vector3 omega, ushort instance, ushort vector) =>
        new RetailDataWriter().UInt32(objectId).Vector3(velocity).Vector3(omega).UInt16(instance).UInt16(vector).ToArray();

    /// <summary>A SetState body.</summary>
    public static byte[] SetState(uint objectId, uint state, ushort instance, ushort stateStamp) =>
        new RetailDataWriter().UInt32(objectId).UInt32(state).UInt16(instance).UInt16(stateStamp).ToArray();

    /// <summary>A ParentEvent body.</summary>
    public static byte[] ParentEvent(uint parentId, uint childId, uint location, uint placement, ushort parentInstance,
                                     ushort childPosition) =>
        new RetailDataWriter().UInt32(parentId).UInt32(childId).UInt32(location).UInt32(placement)
            .UInt16(parentInstance).UInt16(childPosition).ToArray();

    /// <summary>A PickupEvent body.</summary>
    public static byte[] PickupEvent(uint objectId, ushort instance, ushort position) =>
        new RetailDataWriter().UInt32(objectId).UInt16(instance).UInt16(position).ToArray();

    /// <summary>A PlayerTeleport body.</summary>
    public static byte[] PlayerTeleport(ushort teleport) => new RetailDataWriter().UInt16(teleport).Align4().ToArray();

    /// <summary>A DeleteObject body.</summary>
    public static byte[] DeleteObject(uint objectId, ushort instance) =>
        new RetailDataWriter().UInt32(objectId).UInt16(instance).Align4().ToArray();

    /// <summary>The stamps of a physics description, by <c>PhysicsTimeStamp</c> order: position, movement, state, vector,
    /// teleport, server-controlled move, force position, object description, instance.</summary>
    public readonly record struct Stamps(ushort Position = 0, ushort Movement = 0, ushort State = 0, ushort Vector = 0,
                                         ushort Teleport = 0, ushort ServerControl = 0, ushort ForcePosition = 0,
                                         ushort ObjDesc = 0, ushort Instance = 0);

    /// <summary>A physics description in <c>PhysicsDesc::UnPack</c>'s order. Each optional field is written when its
    /// argument is given (and its flag set): movement (0x10000, with the autonomous dword), position (0x8000), motion
    /// table (0x2), setup (0x1), parent (0x20), scale (0x80), friction (0x100), elasticity (0x200), translucency
    /// (0x40000), velocity (0x4), omega (0x10), default script (0x2000); then the nine stamps and the padding.</summary>
    public static RetailDataWriter PhysicsDesc(RetailDataWriter w, uint state, Stamps stamps, byte[]? movement = null,
                                               bool autonomous = false, (uint Cell, Vector3 Origin, Quaternion Q)? position = null,
                                               uint motionTable = 0, uint setup = 0, (uint Parent, uint Location)? parent = null,
                                               float? scale = null, float? friction = null, float? elasticity = null,
                                               float? translucency = null, Vector3? velocity = null, Vector3? omega = null,
                                               uint defaultScript = 0)
    {
        uint flags = 0;
        if (movement is not null) flags |= 0x10000;
        if (position is not null) flags |= 0x8000;
        if (motionTable != 0) flags |= 0x2;
        if (setup != 0) flags |= 0x1;
        if (parent is not null) flags |= 0x20;
        if (scale is not null) flags |= 0x80;
        if (friction is not null) flags |= 0x100;
        if (elasticity is not null) flags |= 0x200;
        if (translucency is not null) flags |= 0x40000;
        if (velocity is not null) flags |= 0x4;
        if (omega is not null) flags |= 0x10;
        if (defaultScript != 0) flags |= 0x2000;
        w.UInt32(flags).UInt32(state);
        if (movement is not null)
        {
            w.UInt32((uint)movement.Length).Bytes(movement);
            if (movement.Length != 0) w.UInt32(autonomous ? 1u : 0u);
        }

        if (position is { } p) w.UInt32(p.Cell).Frame(p.Origin, p.Q);
        if (motionTable != 0) w.UInt32(motionTable);
        if (setup != 0) w.UInt32(setup);
        if (parent is { } pa) w.UInt32(pa.Parent).UInt32(pa.Location);
        if (scale is { } s) w.Single(s);
        if (friction is { } f) w.Single(f);
        if (elasticity is { } e) w.Single(e);
        if (translucency is { } t) w.Single(t);
        if (velocity is { } v) w.Vector3(v);
        if (omega is { } o) w.Vector3(o);
        if (defaultScript != 0) w.UInt32(defaultScript);
        w.UInt16(stamps.Position).UInt16(stamps.Movement).UInt16(stamps.State).UInt16(stamps.Vector).UInt16(stamps.Teleport)
            .UInt16(stamps.ServerControl).UInt16(stamps.ForcePosition).UInt16(stamps.ObjDesc).UInt16(stamps.Instance);
        return w.Align4();
    }

    /// <summary>The start of a CreateObject body: the object id and an empty visual description (0x11, three zero
    /// counts); append the physics description with <see cref="PhysicsDesc"/>.</summary>
    public static RetailDataWriter CreateObjectStart(uint objectId) =>
        new RetailDataWriter().UInt32(objectId).Byte(0x11).Byte(0).Byte(0).Byte(0);
}
