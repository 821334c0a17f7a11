using System;

namespace AcDream.Core.Physics.Format;

/// <summary>
/// The bytes handed to a retail-data unpacker are not the structure they claim to be: truncated, a count larger than the
/// bytes that remain, an unknown node or record type, an index past its array, a cycle. Thrown at the first bad byte, before
/// anything the unpacker builds is handed out (nothing is half-added to a world).
/// </summary>
/// <remarks>
/// Retail's <c>UnPack</c> functions return <c>FALSE</c> (or read past the buffer) on such bytes; the library names the
/// structure and the byte offset instead. It is the only exception an unpacker throws for bad bytes.
/// </remarks>
public sealed class RetailDataFormatException : FormatException
{
    /// <summary>Creates the exception for <paramref name="structure"/> at <paramref name="offset"/>.</summary>
    /// <param name="structure">The retail structure being read (for example <c>CSetup</c>, <c>BSPNODE</c>).</param>
    /// <param name="offset">The byte offset, from the start of the entry's bytes, where the bad value starts.</param>
    /// <param name="reason">What is wrong there.</param>
    public RetailDataFormatException(string structure, int offset, string reason)
        : base($"{structure}: {reason} (byte offset {offset})")
    {
        Structure = structure;
        Offset = offset;
        Reason = reason;
    }

    /// <summary>The retail structure whose bytes are bad.</summary>
    public string Structure { get; }

    /// <summary>The byte offset, from the start of the entry's bytes, where the bad value starts.</summary>
    public int Offset { get; }

    /// <summary>What is wrong at <see cref="Offset"/>.</summary>
    public string Reason { get; }
}
