using System;

namespace AcDream.Core.Physics.Terrain;

/// <summary>
/// A landblock's raw terrain data as the dat stores it: 81 height indices and 81 terrain words, index <c>vx * 9 + vy</c>.
/// </summary>
public sealed class LandBlockData
{
    private readonly byte[] _height;
    private readonly ushort[] _terrain;

    /// <summary>Creates the data of landblock <paramref name="blockId"/> (<c>0xXXYYFFFF</c>).</summary>
    /// <exception cref="ArgumentException">An array is not 81 long.</exception>
    public LandBlockData(uint blockId, ReadOnlySpan<byte> height, ReadOnlySpan<ushort> terrain)
    {
        if (height.Length != LandBlock.VertexCount || terrain.Length != LandBlock.VertexCount)
        {
            throw new ArgumentException($"A landblock has {LandBlock.VertexCount} height indices and terrain words.", nameof(height));
        }

        BlockId = blockId;
        _height = height.ToArray();
        _terrain = terrain.ToArray();
    }

    /// <summary>The landblock id, <c>0xXXYYFFFF</c>.</summary>
    public uint BlockId { get; }

    /// <summary>The 81 height indices (into the land height table).</summary>
    public ReadOnlySpan<byte> Height => _height;

    /// <summary>The 81 terrain words (road bits 0-1, terrain type bits 2-6).</summary>
    public ReadOnlySpan<ushort> Terrain => _terrain;

    /// <summary>Builds the landblock's terrain with <paramref name="heightTable"/>.</summary>
    public LandBlock Build(LandHeightTable heightTable) => new(BlockId, _height, _terrain, heightTable);
}
