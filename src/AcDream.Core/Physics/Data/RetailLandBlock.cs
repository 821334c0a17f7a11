using System;
using AcDream.Core.Physics.Spatial;
using AcDream.Core.Physics.Terrain;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Data;

/// <summary>
/// A landblock's terrain (data-file entry 0xXXYYFFFF) as retail's <c>CLandBlock::UnPack</c> and
/// <c>CLandBlockStruct::UnPack</c> read it: whether a <see cref="RetailLandBlockInfo"/> (0xXXYYFFFE) exists, the 81 terrain
/// words and the 81 height indices (index <c>x * 9 + y</c>). Build the library's landblock with <see cref="ToLandBlock"/>.
/// </summary>
public sealed class RetailLandBlock
{
    private readonly ushort[] _terrain;
    private readonly byte[] _height;

    private RetailLandBlock(uint id, bool hasInfo, ushort[] terrain, byte[] height)
    {
        Id = id;
        HasInfo = hasInfo;
        _terrain = terrain;
        _height = height;
    }

    /// <summary>The landblock id (0xXXYYFFFF).</summary>
    public uint Id { get; }

    /// <summary>True when the block has an info entry (0xXXYYFFFE: buildings, objects, indoor cells).</summary>
    public bool HasInfo { get; }

    /// <summary>The 81 terrain words (road bits 0-1, type bits 2-6, scene bits 11-15). Retail: <c>terrain</c>.</summary>
    public ReadOnlySpan<ushort> Terrain => _terrain;

    /// <summary>The 81 height indices into the land height table. Retail: <c>height</c>.</summary>
    public ReadOnlySpan<byte> Height => _height;

    /// <summary>Unpacks one landblock entry's bytes: the id, the info flag, then the structure.</summary>
    /// <exception cref="RetailDataFormatException">The bytes are not a landblock (also: the id is not of the form 0xXXYYFFFF
    /// inside the world).</exception>
    // retail: CLandBlock::UnPack (acclient.c:351520)
    public static RetailLandBlock Unpack(ReadOnlySpan<byte> data)
    {
        var r = new RetailDataReader(data, "CLandBlock");
        uint id = r.ReadUInt32("id");
        if ((id & 0xFFFF) != 0xFFFF || !LandDefs.BlockIdToLCoord(id, out _, out _))
        {
            throw r.ErrorAt(0, $"0x{id:X8} is not a landblock id");
        }

        bool hasInfo = r.ReadUInt32("info flag") != 0;
        r.Structure = "CLandBlockStruct";
        var terrain = new ushort[LandBlock.VertexCount];
        var height = new byte[LandBlock.VertexCount];
        UnpackStruct(ref r, terrain, height);
        return new RetailLandBlock(id, hasInfo, terrain, height);
    }

    /// <summary>The 81 terrain words, the 81 height bytes, then 4-alignment.</summary>
    // retail: CLandBlockStruct::UnPack (acclient.c:354108)
    private static void UnpackStruct(ref RetailDataReader r, ushort[] terrain, byte[] height)
    {
        for (int i = 0; i < terrain.Length; i++)
        {
            terrain[i] = r.ReadUInt16("terrain");
        }

        for (int i = 0; i < height.Length; i++)
        {
            height[i] = r.ReadByte("height");
        }

        r.Align4();
    }

    /// <summary>The library's landblock from these heights and terrain words with <paramref name="heightTable"/>.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="heightTable"/> is null.</exception>
    public LandBlock ToLandBlock(LandHeightTable heightTable) => new(Id, _height, _terrain, heightTable);
}
