using System;

namespace AcDream.Core.Physics.Data;

/// <summary>
/// The client's data files, seen by id: the bytes of one entry (after the data-file container, which the client reads with its
/// own library). <see cref="LandBlockLoader"/> asks it for a landblock's entries: 0xXXYYFFFF, 0xXXYYFFFE, the indoor
/// cells 0xXXYY0100 onwards (client_cell.dat), and the environments (0x0Dxxxxxx) and building GfxObjs (0x01xxxxxx) they name
/// (client_portal.dat).
/// </summary>
public interface IRetailDataSource
{
    /// <summary>The bytes of entry <paramref name="id"/>; false when the files hold no such entry.</summary>
    /// <param name="id">The entry id.</param>
    /// <param name="bytes">The entry's bytes, from its first byte (the id) to its end.</param>
    bool TryGetEntry(uint id, out ReadOnlyMemory<byte> bytes);
}
