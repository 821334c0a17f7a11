using System.Collections.Generic;
using System.Numerics;

namespace AcDream.Core.Fixtures.Data;

/// <summary>One <c>MotionData</c> to write: its animations (id, low frame, high frame, framerate), velocity, omega and
/// bitfield.</summary>
public sealed record MotionDataSpec(
    (uint Id, int Low, int High, float Framerate)[] Anims,
    Vector3 Velocity = default,
    Vector3 Omega = default,
    byte Bitfield = 0)
{
    /// <summary>No animations, no physics.</summary>
    public static MotionDataSpec Empty { get; } = new(System.Array.Empty<(uint, int, int, float)>());

    /// <summary>One animation.</summary>
    public static MotionDataSpec One(uint animId, int low, int high, float framerate, Vector3 velocity = default,
        Vector3 omega = default, byte bitfield = 0) =>
        new(new[] { (animId, low, high, framerate) }, velocity, omega, bitfield);
}

/// <summary>
/// Builds motion table entry bytes (data file type 0x09) following <c>CMotionTable::UnPack</c> (acclient.c:338603) and
/// <c>MotionData::UnPack</c> (acclient.c:341813) field by field: the entry id; default_style; style_defaults (count, then
/// key and value dwords); cycles and modifiers (count, then MotionData: id, num_anims byte, bitfield byte, physics flags
/// byte (1 velocity, 2 omega), padding to four, AnimData × num_anims (id, low, high, framerate), velocity, omega); links
/// (count, then outer key, inner count, MotionData × inner count).
/// </summary>
public sealed class MotionTableBytes
{
    private readonly List<(uint Key, uint Value)> _styleDefaults = new();
    private readonly List<(uint Key, MotionDataSpec Data)> _cycles = new();
    private readonly List<(uint Key, MotionDataSpec Data)> _modifiers = new();
    private readonly List<(uint Key, List<(uint Motion, MotionDataSpec Data)> Inner)> _links = new();

    /// <summary>The entry id (0x09xxxxxx).</summary>
    public uint Id { get; set; } = 0x09000001;

    /// <summary>The default style.</summary>
    public uint DefaultStyle { get; set; }

    /// <summary>A style's default substate.</summary>
    public MotionTableBytes StyleDefault(uint style, uint substate)
    {
        _styleDefaults.Add((style, substate));
        return this;
    }

    /// <summary>A cycle of <paramref name="substate"/> in <paramref name="style"/> (key (style &lt;&lt; 16) | (substate &amp; 0xFFFFFF)).</summary>
    public MotionTableBytes Cycle(uint style, uint substate, MotionDataSpec data)
    {
        _cycles.Add(((style << 16) | (substate & 0xFFFFFF), data));
        return this;
    }

    /// <summary>A modifier for <paramref name="style"/> (style 0: the style-less key modifier &amp; 0xFFFFFF).</summary>
    public MotionTableBytes Modifier(uint style, uint modifier, MotionDataSpec data)
    {
        _modifiers.Add(((style << 16) | (modifier & 0xFFFFFF), data));
        return this;
    }

    /// <summary>A link in <paramref name="style"/> from <paramref name="from"/> to <paramref name="to"/> (outer key
    /// (style &lt;&lt; 16) | (from &amp; 0xFFFFFF), inner key <paramref name="to"/>).</summary>
    public MotionTableBytes Link(uint style, uint from, uint to, MotionDataSpec data)
    {
        uint key = (style << 16) | (from & 0xFFFFFF);
        List<(uint, MotionDataSpec)>? inner = null;
        foreach ((uint k, List<(uint, MotionDataSpec)> l) in _links)
        {
            if (k == key)
            {
                inner = l;
            }
        }

        if (inner is null)
        {
            inner = new List<(uint, MotionDataSpec)>();
            _links.Add((key, inner));
        }

        inner.Add((to, data));
        return this;
    }

    /// <summary>The entry's bytes.</summary>
    public byte[] ToArray()
    {
        var w = new RetailDataWriter();
        w.UInt32(Id).UInt32(DefaultStyle).UInt32((uint)_styleDefaults.Count);
        foreach ((uint k, uint v) in _styleDefaults)
        {
            w.UInt32(k).UInt32(v);
        }

        w.UInt32((uint)_cycles.Count);
        foreach ((uint k, MotionDataSpec d) in _cycles)
        {
            WriteMotionData(w, k, d);
        }

        w.UInt32((uint)_modifiers.Count);
        foreach ((uint k, MotionDataSpec d) in _modifiers)
        {
            WriteMotionData(w, k, d);
        }

        w.UInt32((uint)_links.Count);
        foreach ((uint k, List<(uint Motion, MotionDataSpec Data)> inner) in _links)
        {
            w.UInt32(k).UInt32((uint)inner.Count);
            foreach ((uint m, MotionDataSpec d) in inner)
            {
                WriteMotionData(w, m, d);
            }
        }

        return w.ToArray();
    }

    /// <summary>Writes one MotionData as <c>MotionData::UnPack</c> reads it.</summary>
    public static void WriteMotionData(RetailDataWriter w, uint id, MotionDataSpec d)
    {
        byte physics = 0;
        if (d.Velocity != Vector3.Zero)
        {
            physics |= 1;
        }

        if (d.Omega != Vector3.Zero)
        {
            physics |= 2;
        }

        // MotionData::UnPack (acclient.c:341813) rounds its cursor up to 4 after the three bytes, always.
        w.UInt32(id).Byte((byte)d.Anims.Length).Byte(d.Bitfield).Byte(physics).Align4();
        foreach ((uint animId, int low, int high, float framerate) in d.Anims)
        {
            w.UInt32(animId).Int32(low).Int32(high).Single(framerate);
        }

        if ((physics & 1) != 0)
        {
            w.Vector3(d.Velocity);
        }

        if ((physics & 2) != 0)
        {
            w.Vector3(d.Omega);
        }
    }
}
