using System;
using System.Globalization;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Motion.Wire;

namespace AcDream.Core.Tests.Replay.Harness;

/// <summary>
/// The recordings' server messages rebuilt as the bodies the wire carried (the bytes after the opcode), from the CSV
/// columns, which keep every field (README of ../shared/data/replay): UpdatePosition 0xF748, VectorUpdate 0xF74E and
/// MovementEvent 0xF74C. A replay decodes them with the library's decoders and applies them through its entry points.
/// </summary>
public static class WireBodies
{
    /// <summary>An UpdatePosition body from a <c>*_s2c_updateposition.csv</c> row (<c>t_rel, guid, flags, objcell_id, x, y,
    /// z, qw, qx, qy, qz, vx, vy, vz, has_velocity, is_grounded, seq_instance, seq_position, seq_teleport, seq_force,
    /// placement_id, msg_idx</c>): the quaternion components the flags omit are not written, the velocity with flag 0x01,
    /// the placement id (decimal in the CSV) with 0x02.</summary>
    public static byte[] UpdatePosition(string[] c)
    {
        uint flags = Hex(c[2]);
        var w = new RetailDataWriter().UInt32(Hex(c[1])).UInt32(flags).UInt32(Hex(c[3]))
            .Single(F(c[4])).Single(F(c[5])).Single(F(c[6]));
        if ((flags & 0x08) == 0) w.Single(F(c[7]));
        if ((flags & 0x10) == 0) w.Single(F(c[8]));
        if ((flags & 0x20) == 0) w.Single(F(c[9]));
        if ((flags & 0x40) == 0) w.Single(F(c[10]));
        if ((flags & 0x01) != 0) w.Single(F(c[11])).Single(F(c[12])).Single(F(c[13]));
        if ((flags & 0x02) != 0) w.UInt32(uint.Parse(c[20], CultureInfo.InvariantCulture));
        return w.UInt16(U16(c[16])).UInt16(U16(c[17])).UInt16(U16(c[18])).UInt16(U16(c[19])).ToArray();
    }

    /// <summary>A VectorUpdate body from a <c>*_s2c_vectorupdate.csv</c> row (<c>t_rel, guid, vx, vy, vz, wx, wy, wz,
    /// seq_instance, seq_vector, msg_idx</c>).</summary>
    public static byte[] VectorUpdate(string[] c) =>
        new RetailDataWriter().UInt32(Hex(c[1])).Single(F(c[2])).Single(F(c[3])).Single(F(c[4]))
            .Single(F(c[5])).Single(F(c[6])).Single(F(c[7])).UInt16(U16(c[8])).UInt16(U16(c[9])).ToArray();

    /// <summary>A MovementEvent body from a <c>*_s2c_movementevent.csv</c> row (<c>t_rel, guid, seq_instance,
    /// seq_movement, seq_server_control, autonomous, movement_data_hex, ...</c>): guid, the three stamps, the autonomous
    /// byte, the zero pad, the movement data as received.</summary>
    public static byte[] MovementEvent(string[] c)
    {
        byte[] data = Convert.FromHexString(c[6]);
        return new RetailDataWriter().UInt32(Hex(c[1])).UInt16(U16(c[2])).UInt16(U16(c[3])).UInt16(U16(c[4]))
            .Byte(c[5] == "1" ? (byte)1 : (byte)0).Align4().Bytes(data).ToArray();
    }

    /// <summary>Decodes an UpdatePosition body (a fresh message: the loaders keep each decoded report).</summary>
    public static UpdatePositionMessage DecodePosition(byte[] body)
    {
        var m = new UpdatePositionMessage();
        PhysicsMessageDecoder.Decode(body, m);
        return m;
    }

    private static uint Hex(string s) => uint.Parse(s.AsSpan(2), NumberStyles.HexNumber, CultureInfo.InvariantCulture);

    private static float F(string s) => float.Parse(s, CultureInfo.InvariantCulture);

    private static ushort U16(string s) => (ushort)int.Parse(s, CultureInfo.InvariantCulture);
}
