using System;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Data;

/// <summary>
/// An environment (data-file entry 0x0Dxxxxxx): the list of cell structures indoor cells take their shape from, as retail's
/// <c>CEnvironment::UnPack</c> reads it. An indoor cell names its environment and a structure index
/// (<see cref="RetailEnvCell.EnvironmentId"/>, <see cref="RetailEnvCell.CellStructIndex"/>).
/// </summary>
public sealed class RetailEnvironment
{
    private readonly RetailCellStruct[] _cells;

    private RetailEnvironment(uint id, RetailCellStruct[] cells)
    {
        Id = id;
        _cells = cells;
    }

    /// <summary>The entry's id (0x0Dxxxxxx).</summary>
    public uint Id { get; }

    /// <summary>The cell structures, in stored order. Retail: <c>cells</c>.</summary>
    public ReadOnlySpan<RetailCellStruct> CellStructs => _cells;

    /// <summary>The structure at <paramref name="index"/>, or null when out of range (retail indexes without a check).
    /// Retail <c>CEnvironment::get_cellstruct</c>.</summary>
    // retail: CEnvironment::get_cellstruct (acclient.c:352896)
    public RetailCellStruct? GetCellStruct(int index) => (uint)index < (uint)_cells.Length ? _cells[index] : null;

    /// <summary>Unpacks one environment entry's bytes: the id, the structure count, each structure
    /// (<c>CCellStruct::UnPack</c>). Retail <c>CEnvironment::UnPack</c>.</summary>
    /// <exception cref="RetailDataFormatException">The bytes are not an environment.</exception>
    // retail: CEnvironment::UnPack (acclient.c:352987)
    public static RetailEnvironment Unpack(ReadOnlySpan<byte> data)
    {
        var r = new RetailDataReader(data, "CEnvironment");
        uint id = r.ReadUInt32("id");
        // A structure is at least 16 (counts) + 8 (vertex array) + 4 + 4 (two one-leaf trees' tags) + ... > 32 bytes.
        int n = r.ReadCount("cell struct count", 32);
        var cells = new RetailCellStruct[n];
        for (int i = 0; i < n; i++)
        {
            cells[i] = RetailCellStruct.Unpack(ref r);
        }

        return new RetailEnvironment(id, cells);
    }
}
