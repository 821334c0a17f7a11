using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;

namespace AcDream.Core.Physics.Scene;

/// <summary>
/// Copies of the gate entries that lie near the 96 m circle of a centre (a player position): each entry's position relative to
/// the centre (float), the side of 96 m its object was on at its last check (+1 beyond, −1 within), its slot and the slot's
/// generation. Laid out as arrays of floats so that one pass tests a whole band with SIMD.
/// </summary>
/// <remarks>
/// The scan is a conservative filter, never the decision: for a player at offset <c>p</c> from the centre it flags every entry
/// whose squared distance <c>d²</c> satisfies <c>side·(d² − 96²) &lt; tolerance</c> — every entry that may have crossed, plus those
/// within the tolerance of 96 m on their own side. The caller decides each flagged entry in double precision (and with retail's
/// own arithmetic near the boundary). Float rounding of the relative coordinates (|x| ≲ 110 m) moves <c>d²</c> by a few
/// thousandths of a square metre, far inside the tolerances the queue uses. Entries past <see cref="Count"/> up to the array
/// length are dead: an infinite x and side +1, which no test ever flags. The loop works on 8 entries at a time
/// (<see cref="Vector256{T}"/>: one AVX instruction each on x64 with AVX; .NET's element-wise fallback elsewhere, with the same
/// results) and makes no call, so its
/// constants stay in registers; it records which groups of 8 have flagged (or member) entries, and their lane masks, for a
/// second pass that only touches those.
/// </remarks>
internal sealed class GateBand
{
    private const int Lanes = 8;

    private float[] _x = Array.Empty<float>();
    private float[] _y = Array.Empty<float>();
    private float[] _z = Array.Empty<float>();
    private float[] _side = Array.Empty<float>();
    private int[] _slot = Array.Empty<int>();
    private int[] _generation = Array.Empty<int>();
    private byte[] _flags = Array.Empty<byte>();

    // Per group of 8 entries with flagged (or member) lanes: the group's first index and its lane mask.
    private int[] _groupAt = Array.Empty<int>();
    private uint[] _groupMask = Array.Empty<uint>();
    private int[] _memberAt = Array.Empty<int>();
    private uint[] _memberMask = Array.Empty<uint>();
    private int _memberGroups;

    public GateBand(double halfWidth)
    {
        HalfWidth = halfWidth;
        Grow(64);
    }

    /// <summary>Half-width of the band (metres): after a build it holds every live entry whose distance from the centre is within
    /// this (plus the queue's membership slack) of 96 m.</summary>
    public double HalfWidth { get; }

    /// <summary>False until the first build.</summary>
    public bool Valid { get; private set; }

    /// <summary>Global coordinates of the centre.</summary>
    public double CentreX { get; private set; }

    /// <inheritdoc cref="CentreX"/>
    public double CentreY { get; private set; }

    /// <inheritdoc cref="CentreX"/>
    public double CentreZ { get; private set; }

    /// <summary>Entries held, dead and stale ones included.</summary>
    public int Count { get; private set; }

    /// <summary>Entries held right after the last build or compaction.</summary>
    public int CountAtBuild { get; private set; }

    /// <summary>Changes whenever entries move (a reset or a compaction), so that indexes kept from before can be told stale.</summary>
    public int Epoch { get; private set; }

    /// <summary>Distance (metres) from the centre to a global point.</summary>
    public double DistanceTo(double x, double y, double z)
    {
        double dx = x - CentreX, dy = y - CentreY, dz = z - CentreZ;
        return Math.Sqrt(dx * dx + dy * dy + dz * dz);
    }

    /// <summary>Empties the band and moves its centre (entries are appended next).</summary>
    public void Reset(double cx, double cy, double cz)
    {
        Epoch++;
        Kill(0, Count);
        Count = 0;
        CountAtBuild = 0;
        CentreX = cx;
        CentreY = cy;
        CentreZ = cz;
        Valid = true;
    }

    /// <summary>Records the current count as the count of a fresh build (for the compaction rule).</summary>
    public void MarkBuilt() => CountAtBuild = Count;

    /// <summary>Appends an entry at a global position, on the given side; returns its index.</summary>
    public int Append(int slot, int generation, byte flags, double gx, double gy, double gz, bool far) =>
        Append(slot, generation, flags, (float)(gx - CentreX), (float)(gy - CentreY), (float)(gz - CentreZ), far ? 1f : -1f);

    /// <summary>Entry <paramref name="i"/>'s global position (the centre plus its float offset).</summary>
    public void Position(int i, out double x, out double y, out double z)
    {
        x = CentreX + _x[i];
        y = CentreY + _y[i];
        z = CentreZ + _z[i];
    }

    /// <summary>Sets the recorded side of entry <paramref name="i"/>.</summary>
    public void SetSide(int i, bool far) => _side[i] = far ? 1f : -1f;

    /// <summary>Makes entry <paramref name="i"/> dead (never flagged again; dropped by the next build or compaction).</summary>
    public void Kill(int i) => Kill(i, 1);

    /// <summary>Drops dead entries and those whose slot has moved on (<see cref="GateQueue.IsCurrent"/>); tells the queue where
    /// each kept entry now is (<see cref="GateQueue.Moved"/>).</summary>
    public void Compact(GateQueue queue)
    {
        Epoch++;
        int w = 0;
        for (int i = 0; i < Count; i++)
        {
            if (!float.IsPositiveInfinity(_x[i]) && queue.IsCurrent(_slot[i], _generation[i]))
            {
                _x[w] = _x[i];
                _y[w] = _y[i];
                _z[w] = _z[i];
                _side[w] = _side[i];
                _slot[w] = _slot[i];
                _generation[w] = _generation[i];
                _flags[w] = _flags[i];
                queue.Moved(this, _slot[w], w);
                w++;
            }
        }

        Kill(w, Count - w);
        Count = w;
        CountAtBuild = w;
    }

    /// <summary>
    /// Tests every entry against a player at global (px, py, pz): appends to <paramref name="hits"/> (from index
    /// <paramref name="n"/>, grown as needed) the entries with <c>side·(d² − r²) &lt; tolerance</c>, tagged with
    /// <paramref name="band"/>, and returns the new count. When <paramref name="selectMembers"/>, it also selects the entries with
    /// <c>lo² &lt; d² &lt; hi²</c>, for <see cref="CopyMembersTo"/>.
    /// </summary>
    public int Scan(double px, double py, double pz, float r2, float tolerance, byte band, ref GateHit[] hits, int n,
        bool selectMembers = false, float lo2 = 0f, float hi2 = 0f)
    {
        var p = new Vector3((float)(px - CentreX), (float)(py - CentreY), (float)(pz - CentreZ));
        int groups = FindGroups(p, r2, tolerance, selectMembers, lo2, hi2);
        for (int g = 0; g < groups; g++)
        {
            int at = _groupAt[g];
            for (uint mask = _groupMask[g]; mask != 0; mask &= mask - 1)
            {
                int i = at + BitOperations.TrailingZeroCount(mask);
                if (n == hits.Length)
                {
                    Array.Resize(ref hits, n * 2);
                }

                hits[n++] = new GateHit(_slot[i], _generation[i], _flags[i], band, i);
            }
        }

        return n;
    }

    /// <summary>Appends the entries the last <see cref="Scan"/> selected to <paramref name="into"/> (reset about its new centre),
    /// moving their float offsets from this centre to that one. The copies take this band's sides, which the queue keeps current
    /// (<see cref="SetSide"/> at every crossing).</summary>
    /// <remarks>The copy adds the difference of the centres in float: at most a few float ulps of ~100 m (≈1e-5 m) off the
    /// offsets made from the slots' doubles, far inside the scan tolerance and the membership slack. Stale copies come along
    /// (reading every slot's generation would cost a cache miss each); the queue's compaction rule bounds them.</remarks>
    public void CopyMembersTo(GateBand into)
    {
        float ox = (float)(CentreX - into.CentreX), oy = (float)(CentreY - into.CentreY), oz = (float)(CentreZ - into.CentreZ);
        for (int g = 0; g < _memberGroups; g++)
        {
            int at = _memberAt[g];
            for (uint mask = _memberMask[g]; mask != 0; mask &= mask - 1)
            {
                int i = at + BitOperations.TrailingZeroCount(mask);
                into.Append(_slot[i], _generation[i], _flags[i], _x[i] + ox, _y[i] + oy, _z[i] + oz, _side[i]);
            }
        }

        _memberGroups = 0;
    }

    /// <summary>The vector loop: records each group of 8 entries with a flagged lane (and, when asked, each with a member lane) and
    /// its lane mask; returns the number of flagged groups.</summary>
    private int FindGroups(Vector3 p, float r2, float tolerance, bool selectMembers, float lo2, float hi2)
    {
        Vector256<float> vx = Vector256.Create(p.X), vy = Vector256.Create(p.Y), vz = Vector256.Create(p.Z);
        Vector256<float> vr2 = Vector256.Create(r2), vtol = Vector256.Create(tolerance);
        Vector256<float> vlo = Vector256.Create(lo2), vhi = Vector256.Create(hi2);
        ref float x0 = ref MemoryMarshal.GetArrayDataReference(_x);
        ref float y0 = ref MemoryMarshal.GetArrayDataReference(_y);
        ref float z0 = ref MemoryMarshal.GetArrayDataReference(_z);
        ref float s0 = ref MemoryMarshal.GetArrayDataReference(_side);
        ref int ga = ref MemoryMarshal.GetArrayDataReference(_groupAt);
        ref uint gm = ref MemoryMarshal.GetArrayDataReference(_groupMask);
        ref int ma = ref MemoryMarshal.GetArrayDataReference(_memberAt);
        ref uint mm = ref MemoryMarshal.GetArrayDataReference(_memberMask);
        int f = 0, m = 0;
        int count = Count; // the arrays hold dead entries past Count up to a whole group
        for (int i = 0; i < count; i += Lanes)
        {
            nuint at = (nuint)i;
            Vector256<float> dx = Vector256.LoadUnsafe(ref x0, at) - vx;
            Vector256<float> dy = Vector256.LoadUnsafe(ref y0, at) - vy;
            Vector256<float> dz = Vector256.LoadUnsafe(ref z0, at) - vz;
            Vector256<float> d2 = dx * dx + dy * dy + dz * dz;
            uint flagged = Vector256.ExtractMostSignificantBits(
                Vector256.LessThan((d2 - vr2) * Vector256.LoadUnsafe(ref s0, at), vtol));
            Unsafe.Add(ref ga, f) = i;
            Unsafe.Add(ref gm, f) = flagged;
            f += flagged != 0 ? 1 : 0;
            if (selectMembers)
            {
                uint inside = Vector256.ExtractMostSignificantBits(Vector256.GreaterThan(d2, vlo) & Vector256.LessThan(d2, vhi));
                Unsafe.Add(ref ma, m) = i;
                Unsafe.Add(ref mm, m) = inside;
                m += inside != 0 ? 1 : 0;
            }
        }

        _memberGroups = m;
        return f;
    }

    private int Append(int slot, int generation, byte flags, float x, float y, float z, float side)
    {
        if (Count + Lanes > _x.Length)
        {
            Grow(_x.Length * 2);
        }

        int i = Count++;
        _x[i] = x;
        _y[i] = y;
        _z[i] = z;
        _side[i] = side;
        _slot[i] = slot;
        _generation[i] = generation;
        _flags[i] = flags;
        return i;
    }

    private void Kill(int from, int count)
    {
        Array.Fill(_x, float.PositiveInfinity, from, count);
        Array.Fill(_y, 0f, from, count);
        Array.Fill(_z, 0f, from, count);
        Array.Fill(_side, 1f, from, count);
    }

    private void Grow(int size)
    {
        int old = _x.Length;
        Array.Resize(ref _x, size);
        Array.Resize(ref _y, size);
        Array.Resize(ref _z, size);
        Array.Resize(ref _side, size);
        Array.Resize(ref _slot, size);
        Array.Resize(ref _generation, size);
        Array.Resize(ref _flags, size);
        _groupAt = new int[size / Lanes + 1];
        _groupMask = new uint[size / Lanes + 1];
        _memberAt = new int[size / Lanes + 1];
        _memberMask = new uint[size / Lanes + 1];
        Kill(old, size - old);
    }
}

/// <summary>A gate entry a scan flagged: its slot, generation and <see cref="GateFlags"/>, and where it came from (a band and
/// index, or a grid cell and index).</summary>
internal readonly record struct GateHit(int Slot, int Generation, byte Flags, byte Band, int Index, int Cell = 0);
