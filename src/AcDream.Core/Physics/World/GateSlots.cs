using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;

namespace AcDream.Core.Physics;

/// <summary>
/// The positions and sides of a <see cref="GateQueue"/>'s slots, laid out for one SIMD pass over all of them: landblock
/// (x &lt;&lt; 8 | y), local origin (as the object's position holds it) and side (+1 beyond 96 m, −1 within; +1 for a free slot,
/// whose local x is +inf, so that it is never selected).
/// </summary>
/// <remarks>
/// The pass measures in float from the player's own landblock: dx = (block x − player block x)·192 + (local x − player local
/// x). The first term is an exact whole number and the second is off by at most half an ulp of 192 m, so every object within a
/// few hundred metres of the player is measured to about 2e-5 m wherever it is in Dereth — far inside the scan tolerance and
/// membership slack of the queue. 20 bytes a slot, read in order.
/// </remarks>
internal sealed class GateSlots
{
    private const int Lanes = 8;

    private int[] _block = Array.Empty<int>();
    private float[] _x = Array.Empty<float>();
    private float[] _y = Array.Empty<float>();
    private float[] _z = Array.Empty<float>();
    private float[] _side = Array.Empty<float>();

    // Per group of 8 slots with a selected lane: its first slot and the lane masks of the three selections.
    private int[] _groupAt = Array.Empty<int>();
    private uint[] _hitMask = Array.Empty<uint>();
    private uint[] _ringMask = Array.Empty<uint>();
    private uint[] _bandMask = Array.Empty<uint>();

    /// <summary>Slots the arrays hold (a whole number of groups of 8).</summary>
    public int Capacity => _x.Length;

    /// <summary>Grows the arrays to hold at least <paramref name="size"/> slots (new ones free).</summary>
    public void Grow(int size)
    {
        size = (size + Lanes - 1) / Lanes * Lanes;
        int old = _x.Length;
        if (size <= old)
        {
            return;
        }

        Array.Resize(ref _block, size);
        Array.Resize(ref _x, size);
        Array.Resize(ref _y, size);
        Array.Resize(ref _z, size);
        Array.Resize(ref _side, size);
        _groupAt = new int[size / Lanes];
        _hitMask = new uint[size / Lanes];
        _ringMask = new uint[size / Lanes];
        _bandMask = new uint[size / Lanes];
        for (int s = old; s < size; s++)
        {
            Free(s);
        }
    }

    /// <summary>Puts an object at <paramref name="p"/> in slot <paramref name="slot"/>, on the given side.</summary>
    public void Set(int slot, in Position p, bool far)
    {
        uint cell = p.ObjCellId;
        _block[slot] = (int)((cell >> 16) & 0xFFFF);
        _x[slot] = p.Frame.Origin.X;
        _y[slot] = p.Frame.Origin.Y;
        _z[slot] = p.Frame.Origin.Z;
        _side[slot] = far ? 1f : -1f;
    }

    /// <summary>Marks a slot free: never selected.</summary>
    public void Free(int slot)
    {
        _block[slot] = 0;
        _x[slot] = float.PositiveInfinity;
        _y[slot] = 0f;
        _z[slot] = 0f;
        _side[slot] = 1f;
    }

    /// <summary>Sets a slot's side.</summary>
    public void SetSide(int slot, bool far) => _side[slot] = far ? 1f : -1f;

    /// <summary>A slot's global position (as <see cref="GateQueue.Global(in Position, out double, out double, out double)"/>).</summary>
    public void Global(int slot, out double x, out double y, out double z)
    {
        int b = _block[slot];
        x = (b >> 8) * (double)LandDefs.BlockLength + _x[slot];
        y = (b & 0xFF) * (double)LandDefs.BlockLength + _y[slot];
        z = _z[slot];
    }

    /// <summary>
    /// Measures the first <paramref name="count"/> slots from a player at <paramref name="p"/>: collects the slots with
    /// <c>side·(d² − r²) &lt; tolerance</c> into <paramref name="hits"/>, and those with <c>ringLo² &lt; d² &lt; ringHi²</c> and
    /// <c>bandLo² &lt; d² &lt; bandHi²</c> into <paramref name="ring"/> and <paramref name="band"/> (all from index 0, grown as
    /// needed); returns the number of hits.
    /// </summary>
    public int Scan(in Position p, int count, float r2, float tolerance, float ringLo2, float ringHi2, float bandLo2,
        float bandHi2, ref int[] hits, ref int[] ring, out int ringCount, ref int[] band, out int bandCount)
    {
        int groups = FindGroups(p, count, r2, tolerance, ringLo2, ringHi2, bandLo2, bandHi2);
        int n = 0, m = 0, b = 0;
        for (int g = 0; g < groups; g++)
        {
            int at = _groupAt[g];
            n = Expand(_hitMask[g], at, ref hits, n);
            m = Expand(_ringMask[g], at, ref ring, m);
            b = Expand(_bandMask[g], at, ref band, b);
        }

        ringCount = m;
        bandCount = b;
        return n;
    }

    private static int Expand(uint mask, int at, ref int[] list, int n)
    {
        for (; mask != 0; mask &= mask - 1)
        {
            if (n == list.Length)
            {
                Array.Resize(ref list, n * 2);
            }

            list[n++] = at + BitOperations.TrailingZeroCount(mask);
        }

        return n;
    }

    /// <summary>The vector loop (no calls, so its constants stay in registers): records each group of 8 slots with a selected
    /// lane and its three lane masks; returns the number of groups recorded.</summary>
    private int FindGroups(in Position p, int count, float r2, float tolerance, float ringLo2, float ringHi2, float bandLo2,
        float bandHi2)
    {
        uint cell = p.ObjCellId;
        Vector256<int> pbx = Vector256.Create((int)((cell >> 24) & 0xFF));
        Vector256<int> pby = Vector256.Create((int)((cell >> 16) & 0xFF));
        Vector256<int> low = Vector256.Create(0xFF);
        Vector256<float> side = Vector256.Create(LandDefs.BlockLength);
        Vector256<float> px = Vector256.Create(p.Frame.Origin.X), py = Vector256.Create(p.Frame.Origin.Y);
        Vector256<float> pz = Vector256.Create(p.Frame.Origin.Z);
        Vector256<float> vr2 = Vector256.Create(r2), vtol = Vector256.Create(tolerance);
        Vector256<float> rlo = Vector256.Create(ringLo2), rhi = Vector256.Create(ringHi2);
        Vector256<float> blo = Vector256.Create(bandLo2), bhi = Vector256.Create(bandHi2);
        ref int b0 = ref MemoryMarshal.GetArrayDataReference(_block);
        ref float x0 = ref MemoryMarshal.GetArrayDataReference(_x);
        ref float y0 = ref MemoryMarshal.GetArrayDataReference(_y);
        ref float z0 = ref MemoryMarshal.GetArrayDataReference(_z);
        ref float s0 = ref MemoryMarshal.GetArrayDataReference(_side);
        ref int ga = ref MemoryMarshal.GetArrayDataReference(_groupAt);
        ref uint hm = ref MemoryMarshal.GetArrayDataReference(_hitMask);
        ref uint rm = ref MemoryMarshal.GetArrayDataReference(_ringMask);
        ref uint bm = ref MemoryMarshal.GetArrayDataReference(_bandMask);
        int g = 0;
        for (int i = 0; i < count; i += Lanes) // the arrays hold free slots past count up to a whole group
        {
            nuint at = (nuint)i;
            Vector256<int> block = Vector256.LoadUnsafe(ref b0, at);
            Vector256<float> bx = Vector256.ConvertToSingle(Vector256.ShiftRightLogical(block, 8) - pbx) * side;
            Vector256<float> by = Vector256.ConvertToSingle((block & low) - pby) * side;
            Vector256<float> dx = bx + (Vector256.LoadUnsafe(ref x0, at) - px);
            Vector256<float> dy = by + (Vector256.LoadUnsafe(ref y0, at) - py);
            Vector256<float> dz = Vector256.LoadUnsafe(ref z0, at) - pz;
            Vector256<float> d2 = dx * dx + dy * dy + dz * dz;
            uint hit = Vector256.ExtractMostSignificantBits(Vector256.LessThan((d2 - vr2) * Vector256.LoadUnsafe(ref s0, at), vtol));
            uint ring = Vector256.ExtractMostSignificantBits(Vector256.GreaterThan(d2, rlo) & Vector256.LessThan(d2, rhi));
            uint band = Vector256.ExtractMostSignificantBits(Vector256.GreaterThan(d2, blo) & Vector256.LessThan(d2, bhi));
            Unsafe.Add(ref ga, g) = i;
            Unsafe.Add(ref hm, g) = hit;
            Unsafe.Add(ref rm, g) = ring;
            Unsafe.Add(ref bm, g) = band;
            g += (hit | band) != 0 ? 1 : 0; // the ring lies inside the band
        }

        return g;
    }
}
