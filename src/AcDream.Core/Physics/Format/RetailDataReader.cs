using System;
using System.Buffers.Binary;
using System.Numerics;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Format;

/// <summary>
/// A bounds-checked little-endian cursor over one data-file entry's bytes (after the dat container), the shared reader of
/// every retail <c>UnPack</c> port. Each read checks the bytes that remain first and throws
/// <see cref="RetailDataFormatException"/> naming <see cref="Structure"/> and the offset; counts are checked against the
/// remaining bytes (<see cref="ReadCount"/>) before anything is allocated by them.
/// </summary>
/// <remarks>
/// Retail reads through <c>void **addr</c> with a <c>size</c> it mostly ignores; the port keeps retail's field order and
/// widths and adds the checks. <see cref="Structure"/> is settable so a nested structure's errors name it.
/// </remarks>
internal ref struct RetailDataReader
{
    private readonly ReadOnlySpan<byte> _data;
    private int _offset;

    /// <summary>Reads <paramref name="data"/> from its first byte; errors name <paramref name="structure"/>.</summary>
    public RetailDataReader(ReadOnlySpan<byte> data, string structure)
    {
        _data = data;
        _offset = 0;
        Structure = structure;
    }

    /// <summary>The retail structure being read, named by every error.</summary>
    public string Structure;

    /// <summary>Bytes read so far.</summary>
    public readonly int Offset => _offset;

    /// <summary>Bytes not yet read.</summary>
    public readonly int Remaining => _data.Length - _offset;

    /// <summary>The whole buffer's length.</summary>
    public readonly int Length => _data.Length;

    /// <summary>A format error at the current offset.</summary>
    public readonly RetailDataFormatException Error(string reason) => new(Structure, _offset, reason);

    /// <summary>A format error at <paramref name="offset"/>.</summary>
    public readonly RetailDataFormatException ErrorAt(int offset, string reason) => new(Structure, offset, reason);

    private ReadOnlySpan<byte> Take(int count, string what)
    {
        if (count < 0 || count > Remaining)
            throw Error($"{what} needs {count} bytes, {Remaining} remain");
        ReadOnlySpan<byte> s = _data.Slice(_offset, count);
        _offset += count;
        return s;
    }

    /// <summary>One byte.</summary>
    public byte ReadByte(string what = "byte") => Take(1, what)[0];

    /// <summary>A little-endian 16-bit unsigned value.</summary>
    public ushort ReadUInt16(string what = "uint16") => BinaryPrimitives.ReadUInt16LittleEndian(Take(2, what));

    /// <summary>A little-endian 16-bit signed value.</summary>
    public short ReadInt16(string what = "int16") => BinaryPrimitives.ReadInt16LittleEndian(Take(2, what));

    /// <summary>A little-endian 32-bit unsigned value.</summary>
    public uint ReadUInt32(string what = "uint32") => BinaryPrimitives.ReadUInt32LittleEndian(Take(4, what));

    /// <summary>A little-endian 32-bit signed value.</summary>
    public int ReadInt32(string what = "int32") => BinaryPrimitives.ReadInt32LittleEndian(Take(4, what));

    /// <summary>A little-endian IEEE single, bit for bit (NaN and infinities pass; callers that cannot take them check).</summary>
    public float ReadSingle(string what = "float") => BitConverter.Int32BitsToSingle(BinaryPrimitives.ReadInt32LittleEndian(Take(4, what)));

    /// <summary>A finite single; a NaN or infinity is a format error.</summary>
    public float ReadFiniteSingle(string what)
    {
        int at = _offset;
        float v = ReadSingle(what);
        if (!float.IsFinite(v))
            throw ErrorAt(at, $"{what} is not finite ({v})");
        return v;
    }

    /// <summary>Three singles x, y, z (retail <c>Vector3::UnPack</c> order).</summary>
    public Vector3 ReadVector3(string what = "vector")
    {
        float x = ReadSingle(what), y = ReadSingle(what), z = ReadSingle(what);
        return new Vector3(x, y, z);
    }

    /// <summary>Retail <c>Frame::UnPack</c> (acclient.c:357132): the origin x, y, z, then the quaternion w, x, y, z (28
    /// bytes), kept bit for bit (never normalised), tested as <c>Frame::IsValid</c> (357024) tests it (the same tests as
    /// <see cref="ReadAFrame"/>: a NaN or infinite component, or |q|² further than 5 × 0.0002 from 1, is a format error),
    /// then cached (<c>Frame::cache</c>).</summary>
    // retail: Frame::UnPack (acclient.c:357132)
    public Frame ReadFrame(string what = "frame")
    {
        AFrame stored = ReadAFrame(what);
        Frame f = Frame.Identity;
        f.Origin = stored.Origin;
        f.SetQuaternionRaw(stored.Qw, stored.Qx, stored.Qy, stored.Qz);
        f.Cache();
        return f;
    }

    /// <summary>Reads an <see cref="AFrame"/> (retail <c>AFrame::UnPack</c>, acclient.c:467618: origin x, y, z, then w, x, y,
    /// z, kept as read) and checks it as <c>AFrame::IsValid</c> (acclient.c:467555) does. <see cref="AFrame"/> is in
    /// <c>Spatial</c>, below this reader, so the reader reads it.</summary>
    /// <exception cref="RetailDataFormatException">Truncated, a component NaN or infinite, or not a unit quaternion.
    /// (Retail's <c>CAnimation::UnPack</c> ignores <c>AFrame::UnPack</c>'s FALSE; the library refuses the bytes.)</exception>
    // retail: AFrame::UnPack (acclient.c:467618)
    public AFrame ReadAFrame(string what)
    {
        int at = _offset;
        Vector3 origin = ReadVector3(what);
        float w = ReadSingle(what), x = ReadSingle(what), y = ReadSingle(what), z = ReadSingle(what);
        if (!VectorMath.IsFinite(origin) || !float.IsFinite(w) || !float.IsFinite(x) || !float.IsFinite(y) || !float.IsFinite(z))
        {
            throw ErrorAt(at, $"{what} is not finite");
        }

        if (!AFrame.IsUnit(w, x, y, z))
        {
            throw ErrorAt(at, $"{what} rotation is not a unit quaternion");
        }

        return AFrame.FromChecked(origin, w, x, y, z);
    }

    /// <summary>
    /// A 32-bit element count, checked before anything is sized by it: each element takes at least
    /// <paramref name="minBytesEach"/> bytes, so a count whose elements cannot fit in the bytes that remain is a format error
    /// at the count's own offset.
    /// </summary>
    public int ReadCount(string what, int minBytesEach)
    {
        int at = _offset;
        return CheckCount(ReadUInt32(what), what, minBytesEach, at);
    }

    /// <summary>A 16-bit element count, checked as <see cref="ReadCount"/> checks.</summary>
    public int ReadCount16(string what, int minBytesEach)
    {
        int at = _offset;
        return CheckCount(ReadUInt16(what), what, minBytesEach, at);
    }

    /// <summary>A compressed element count (<see cref="ReadCompressedUInt32"/>: 1, 2 or 4 bytes), checked as
    /// <see cref="ReadCount"/> checks.</summary>
    public int ReadCompressedCount(string what, int minBytesEach)
    {
        int at = _offset;
        return CheckCount(ReadCompressedUInt32(what), what, minBytesEach, at);
    }

    /// <summary>Checks a count read some other way (for example a byte, or a packed value) against the bytes that remain;
    /// the format error names <paramref name="countAt"/>, the offset of the field the count was read from.</summary>
    public readonly int CheckCount(uint count, string what, int minBytesEach, int countAt)
    {
        long need = (long)count * Math.Max(minBytesEach, 0);
        if (count > int.MaxValue || need > Remaining)
            throw ErrorAt(countAt, $"{what} count {count} needs at least {need} bytes, {Remaining} remain after it");
        return (int)count;
    }

    /// <summary>Skips <paramref name="count"/> bytes (data the physics does not use, consumed exactly).</summary>
    public void Skip(int count, string what = "skipped bytes") => Take(count, what);

    /// <summary>Skips to the next multiple of four from the start of the entry (retail <c>UNPACK_ALIGN</c> / <c>PACK_ALIGN</c>).</summary>
    public void Align4()
    {
        int pad = (4 - (_offset & 3)) & 3;
        Take(pad, "alignment padding");
    }

    /// <summary>Retail <c>SB_As32Bit_Compressed::Serialize</c> (acclient.c:489675), reading: one byte below 0x80 is the
    /// value; a first byte with 0x80 and not 0x40 takes a second byte (<c>(b0 &amp; 0x7F) &lt;&lt; 8 | b1</c>); with 0x40 as well,
    /// a second byte and a 16-bit word (<c>((b0 &amp; 0x3F) &lt;&lt; 8 | b1) &lt;&lt; 16 | w</c>).</summary>
    // retail: SB_As32Bit_Compressed::Serialize (acclient.c:489675)
    public uint ReadCompressedUInt32(string what = "compressed count")
    {
        byte b0 = ReadByte(what);
        if ((b0 & 0x80) == 0)
        {
            return b0;
        }

        byte b1 = ReadByte(what);
        if ((b0 & 0x40) != 0)
        {
            ushort w = ReadUInt16(what);
            return (uint)w | ((uint)(b1 | ((b0 & 0x3F) << 8)) << 16);
        }

        return (uint)(b1 | ((b0 & 0x7F) << 8));
    }

    /// <summary>Three finite singles x, y, z; a NaN or infinity is a format error.</summary>
    public Vector3 ReadFiniteVector3(string what)
    {
        int at = _offset;
        Vector3 v = ReadVector3(what);
        if (!float.IsFinite(v.X) || !float.IsFinite(v.Y) || !float.IsFinite(v.Z))
        {
            throw ErrorAt(at, $"{what} is not finite");
        }

        return v;
    }

    /// <summary>The bytes not yet read, without consuming them.</summary>
    public readonly ReadOnlySpan<byte> Rest => _data.Slice(_offset);

    /// <summary>The entry's bytes from <paramref name="offset"/> on (a field already read, read again where it stands).</summary>
    public readonly ReadOnlySpan<byte> From(int offset) => _data.Slice(offset);
}
