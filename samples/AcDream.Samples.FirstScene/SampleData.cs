using System;
using System.Collections.Generic;
using AcDream.Core.Fixtures.Data;
using AcDream.Core.Physics.Data;
using AcDream.Core.Physics.Terrain;

namespace AcDream.Samples.FirstScene;

/// <summary>
/// The client's data files, as the library sees them (<see cref="IRetailDataSource"/>): entry bytes by id. A real client
/// answers from its own reader of client_cell.dat and client_portal.dat; the sample holds the few entries of its scene in a
/// dictionary, written in retail's layouts.
/// </summary>
internal sealed class SampleData : IRetailDataSource
{
    private readonly List<uint> _blocks = new();

    public SampleData(LandHeightTable heightTable) => HeightTable = heightTable;

    /// <summary>The Region's height table (retail reads it from the Region entry 0x13000000).</summary>
    public LandHeightTable HeightTable { get; }

    /// <summary>The entries, by id.</summary>
    public Dictionary<uint, byte[]> Entries { get; } = new();

    /// <summary>The landblocks held (0xXXYYFFFF).</summary>
    public uint[] BlockIds => _blocks.ToArray();

    /// <summary>Adds a landblock entry without an info entry.</summary>
    public void AddBlock(uint id, ReadOnlySpan<byte> height, ReadOnlySpan<ushort> terrain)
    {
        Entries[id] = WorldDataBytes.LandBlock(id, false, terrain, height);
        _blocks.Add(id);
    }

    public bool TryGetEntry(uint id, out ReadOnlyMemory<byte> bytes)
    {
        bool found = Entries.TryGetValue(id, out byte[]? b);
        bytes = b;
        return found;
    }
}
