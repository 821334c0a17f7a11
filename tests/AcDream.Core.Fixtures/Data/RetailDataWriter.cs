using System;
using System.Buffers.Binary;
using System.Collections.Generic;
using System.Numerics;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Fixtures.Data;

/// <summary>
/// Builds data-file entry bytes to the decompiled layouts, field by field (little-endian, as retail's <c>Pack</c> writes):
/// the test-side mirror of <c>RetailDataReader</c>. Each unpacker test writes its structure with this and reads it back.
/// </summary>
public sealed class RetailDataWriter
{
    private readonly List<byte> _bytes = new();

    public int Length => _bytes.Count;

    public byte[] ToArray() => _bytes.ToArray();

    public RetailDataWriter Byte(byte v) { _bytes.Add(v); return this; }

    public RetailDataWriter Bytes(ReadOnlySpan<byte> v) { foreach (byte b in v) _bytes.Add(b); return this; }

    public RetailDataWriter UInt16(ushort v) { Span<byte> s = stackalloc byte[2]; BinaryPrimitives.WriteUInt16LittleEndian(s, v); return Bytes(s); }

    public RetailDataWriter Int16(short v) { Span<byte> s = stackalloc byte[2]; BinaryPrimitives.WriteInt16LittleEndian(s, v); return Bytes(s); }

    public RetailDataWriter UInt32(uint v) { Span<byte> s = stackalloc byte[4]; BinaryPrimitives.WriteUInt32LittleEndian(s, v); return Bytes(s); }

    public RetailDataWriter Int32(int v) { Span<byte> s = stackalloc byte[4]; BinaryPrimitives.WriteInt32LittleEndian(s, v); return Bytes(s); }

    public RetailDataWriter Single(float v) => Int32(BitConverter.SingleToInt32Bits(v));

    public RetailDataWriter Vector3(Vector3 v) => Single(v.X).Single(v.Y).Single(v.Z);

    /// <summary>Retail <c>AFrame::Pack</c> order: origin x, y, z, then quaternion w, x, y, z.</summary>
    public RetailDataWriter Frame(Vector3 origin, Quaternion q) => Vector3(origin).Single(q.W).Single(q.X).Single(q.Y).Single(q.Z);

    public RetailDataWriter Frame(in Frame f) => Frame(f.Origin, f.Rotation);

    /// <summary>Pads with zeros to the next multiple of four from the start (retail <c>PACK_ALIGN</c>).</summary>
    public RetailDataWriter Align4() { while ((_bytes.Count & 3) != 0) _bytes.Add(0); return this; }
}
