using System;
using System.Collections.Generic;
using AcDream.Core.Physics.Format;

namespace AcDream.Core.Physics.Animation;

// CMotionTable::UnPack: a motion table from a data file entry's bytes.
public sealed partial class MotionTable
{
    // The smallest MotionData: id, three bytes and their padding.
    private const int MinMotionDataSize = 8;

    /// <summary>
    /// Reads a motion table from the bytes of its data file entry (type 0x09, after the dat container): the entry's id
    /// (retail reads it in <c>DBObj::Serialize</c> before <c>UnPack</c>), then <c>UnPack</c>'s fields: the default style;
    /// the style defaults (a count, then style and substate pairs); the cycles and the modifiers (a count, then
    /// <c>MotionData</c>s whose id is the key); the links (a count, then for each an outer key, a count and that many
    /// <c>MotionData</c>s keyed by their id).
    /// </summary>
    /// <param name="entry">The entry's bytes (its id first).</param>
    /// <returns>The table: read-only, shareable by every object that plays it.</returns>
    /// <exception cref="RetailDataFormatException">The bytes end early, a count is larger than the bytes left, a framerate
    /// is outside <see cref="AnimData"/>'s domain, or a motion's velocity or omega is not finite or longer than 50.</exception>
    // retail: CMotionTable::UnPack (acclient.c:338603)
    public static MotionTable UnPack(ReadOnlySpan<byte> entry)
    {
        var r = new RetailDataReader(entry, "CMotionTable");
        var t = new MotionTable();
        t.Id = r.ReadUInt32("id");
        // Retail: size < 12 fails at once (default style, the style-default count and the cycle count at least).
        if (r.Remaining < 12)
        {
            throw r.Error($"a motion table needs at least 12 bytes after its id, {r.Remaining} remain");
        }

        t._defaultStyle = r.ReadUInt32("default_style");
        int n = r.ReadCount("style_defaults", 8);
        for (int i = 0; i < n; i++)
        {
            uint key = r.ReadUInt32("style_defaults key");
            uint value = r.ReadUInt32("style_defaults value");
            t.StyleDefaults[key] = value;
        }

        ReadHash(ref r, t.Cycles, "cycles");
        ReadHash(ref r, t.Modifiers, "modifiers");
        int nLinks = r.ReadCount("links", 8);
        for (int i = 0; i < nLinks; i++)
        {
            uint key = r.ReadUInt32("links key");
            int tableSize = r.ReadCount("links table size", MinMotionDataSize);
            var inner = new Dictionary<uint, MotionData>(tableSize);
            for (int j = 0; j < tableSize; j++)
            {
                MotionData d = MotionData.UnPack(ref r);
                inner[d.Id] = d;
            }

            t.Links[key] = inner;
        }

        // Retail's last check: the cursor may stand short of a four-byte boundary only with the padding still in the buffer.
        // Retail's size bookkeeping (PackObj::GET_SIZE_LEFT, acclient.c:341465; PackObj::VERIFY_ADDR, acclient.c:341477)
        // is the reader's Remaining and its bounds checks.
        int pad = (4 - (r.Offset & 3)) & 3;
        if (pad != 0 && r.Remaining < pad)
        {
            throw r.Error("the table ends short of its four-byte padding");
        }

        return t;
    }

    private static void ReadHash(ref RetailDataReader r, Dictionary<uint, MotionData> hash, string what)
    {
        int n = r.ReadCount(what, MinMotionDataSize);
        for (int i = 0; i < n; i++)
        {
            MotionData d = MotionData.UnPack(ref r);
            hash[d.Id] = d;
        }
    }
}
