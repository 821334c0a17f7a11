using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;
using AcDream.Core.Physics.Collision;

namespace AcDream.Core.Physics.Cells;

/// <summary>
/// A cell's <see cref="ObstacleSummary"/>s, one per listed shadow at the shadow's index, as four float arrays (origin x, y,
/// z and the reach the cell stores, <see cref="ObstacleSummary.ReachIn"/>): 16 bytes a shadow, laid out so that
/// <see cref="NextKept"/> decides four at a time (<see cref="Vector256{T}"/>: one AVX instruction each on x64; .NET's
/// element-wise fallback elsewhere, with the same results). The arrays' length is the shadow list's capacity rounded up to a
/// whole group of four.
/// </summary>
// non-retail: the packed copies that the exact early-out of ObjectReach reads (retail reads every shadowed object)
internal struct ObstacleTable
{
    private const int Lanes = 4;

    private float[] _x, _y, _z, _reach;

    /// <summary>A table with room for <paramref name="capacity"/> summaries.</summary>
    public ObstacleTable(int capacity)
    {
        int n = RoundUp(capacity);
        _x = new float[n];
        _y = new float[n];
        _z = new float[n];
        _reach = new float[n];
    }

    /// <summary>Makes room for <paramref name="capacity"/> summaries (never shrinks).</summary>
    public void EnsureCapacity(int capacity)
    {
        int n = RoundUp(capacity);
        if (n > _x.Length)
        {
            Array.Resize(ref _x, n);
            Array.Resize(ref _y, n);
            Array.Resize(ref _z, n);
            Array.Resize(ref _reach, n);
        }
    }

    /// <summary>Stores <paramref name="s"/> at <paramref name="i"/>, for a cell of landblock <paramref name="cellBlock"/>.</summary>
    public readonly void Set(int i, in ObstacleSummary s, uint cellBlock)
    {
        _x[i] = s.X;
        _y[i] = s.Y;
        _z[i] = s.Z;
        _reach[i] = s.ReachIn(cellBlock);
    }

    /// <summary>Copies the entry at <paramref name="from"/> to <paramref name="to"/>.</summary>
    public readonly void Move(int from, int to)
    {
        _x[to] = _x[from];
        _y[to] = _y[from];
        _z[to] = _z[from];
        _reach[to] = _reach[from];
    }

    /// <summary>True when the entry at <paramref name="i"/> is what <see cref="Set"/> stores for <paramref name="s"/> (bit
    /// for bit).</summary>
    public readonly bool Holds(int i, in ObstacleSummary s, uint cellBlock) =>
        Same(_x[i], s.X) && Same(_y[i], s.Y) && Same(_z[i], s.Z) && Same(_reach[i], s.ReachIn(cellBlock));

    /// <summary>The entry at <paramref name="i"/> as text (for messages).</summary>
    public readonly string Describe(int i) =>
        string.Create(System.Globalization.CultureInfo.InvariantCulture, $"(reach {_reach[i]:R} at {_x[i]:R}, {_y[i]:R}, {_z[i]:R})");

    /// <summary>
    /// The first group of four entries (its first index, a multiple of four), from the group of <paramref name="start"/> on,
    /// with an entry at or after <paramref name="start"/> that the vector test cannot pass over, and those entries as a
    /// 4-bit mask (<paramref name="kept"/>; lanes past <paramref name="count"/> may be set: the caller stops there); or an
    /// index at or past <paramref name="count"/> when there is none. Passed over: an entry whose ball <see cref="ObjectReach.Excludes"/> excludes from
    /// <paramref name="box"/>, tested lane by lane in its double arithmetic on the origin carried into the box's landblock by
    /// <paramref name="offset"/> (the cell's landblock offset, which <see cref="Objects.PhysicsObj.IsOutOfReach"/> adds to an
    /// origin of that landblock; 0 adds nothing but the sign of a zero, which no test here can see) and on the stored reach,
    /// which is never below the exact one: an obstacle passed over here is out of reach by the exact test too (each step of
    /// the margin's arithmetic is monotone in the reach). Parented (−∞) is always passed over; a NaN reach never.
    /// </summary>
    public readonly int NextKept(int start, int count, in ObjectReach box, Vector3 offset, out uint kept)
    {
        Vector256<double> minX = Vector256.Create(box.MinX), maxX = Vector256.Create(box.MaxX);
        Vector256<double> minY = Vector256.Create(box.MinY), maxY = Vector256.Create(box.MaxY);
        Vector256<double> minZ = Vector256.Create(box.MinZ), maxZ = Vector256.Create(box.MaxZ);
        Vector256<double> margin = Vector256.Create(ObjectReach.Margin), relative = Vector256.Create(ObjectReach.RelativeMargin);
        Vector256<double> ox = Vector256.Create((double)offset.X), oy = Vector256.Create((double)offset.Y);
        Vector256<double> oz = Vector256.Create((double)offset.Z);
        bool shifted = offset != Vector3.Zero;
        ref float x0 = ref MemoryMarshal.GetArrayDataReference(_x);
        ref float y0 = ref MemoryMarshal.GetArrayDataReference(_y);
        ref float z0 = ref MemoryMarshal.GetArrayDataReference(_z);
        ref float r0 = ref MemoryMarshal.GetArrayDataReference(_reach);
        int group = start & ~(Lanes - 1);
        // Lanes before start were decided already.
        uint decided = (1u << (start - group)) - 1u;
        for (; group < count; group += Lanes)
        {
            nuint at = (nuint)group;
            Vector256<double> x = Widen(Vector128.LoadUnsafe(ref x0, at));
            Vector256<double> y = Widen(Vector128.LoadUnsafe(ref y0, at));
            Vector256<double> z = Widen(Vector128.LoadUnsafe(ref z0, at));
            Vector256<double> r = Widen(Vector128.LoadUnsafe(ref r0, at));
            if (shifted)
            {
                x = ox + x;
                y = oy + y;
                z = oz + z;
            }

            // ObjectReach.Excludes, in its order: m = reach + Margin + RelativeMargin * (|x| + |y| + |z| + reach).
            Vector256<double> m = r + margin + relative * (Vector256.Abs(x) + Vector256.Abs(y) + Vector256.Abs(z) + r);
            Vector256<double> outside = Vector256.LessThan(x + m, minX) | Vector256.GreaterThan(x - m, maxX)
                | Vector256.LessThan(y + m, minY) | Vector256.GreaterThan(y - m, maxY)
                | Vector256.LessThan(z + m, minZ) | Vector256.GreaterThan(z - m, maxZ);
            kept = ~(Vector256.ExtractMostSignificantBits(outside) | decided) & 0xFu;
            if (kept != 0)
            {
                return group;
            }

            decided = 0;
        }

        kept = 0;
        return group;
    }

    // Four floats to four doubles (exact).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector256<double> Widen(Vector128<float> v) => Vector256.WidenLower(v.ToVector256Unsafe());

    private static bool Same(float a, float b) => BitConverter.SingleToInt32Bits(a) == BitConverter.SingleToInt32Bits(b);

    private static int RoundUp(int capacity) => (capacity + Lanes - 1) & ~(Lanes - 1);
}
