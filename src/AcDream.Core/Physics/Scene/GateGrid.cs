using System;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Scene;

/// <summary>
/// Where a <see cref="GateQueue"/>'s objects are: their entries (slot, generation, flags, side, position, and where the band
/// holds their copy) bucketed in square cells of <see cref="CellSize"/> metres, so that rebuilding the bands about the player
/// reads only the cells that can hold an object near the player's 96 m circle, not every queued object.
/// </summary>
/// <remarks>
/// Cells are found by a hash of their coordinates (open addressing; allocation only when it grows). A cell keeps its entries in
/// a range of one array shared by all cells (see <c>_arena</c>) and the z range they have had, so that a cell wholly inside or outside an annulus is skipped in 3D. A removed entry
/// is only marked dead (slot −1) and its cell listed; <see cref="Sweep"/> closes the gaps later, at a moment when no place
/// taken by <see cref="Select"/> is still in use (the queue sweeps at the end of each tick's test, <see cref="GateQueue.Finish"/>). Entry positions are float offsets
/// from the cell's corner (x, y, within 1e-6 m) and the float z the object's position holds.
/// </remarks>
internal sealed class GateGrid
{
    /// <summary>Side of a cell, metres: an eighth of a landblock.</summary>
    public const double CellSize = LandDefs.BlockLength / 8.0;

    /// <summary>What the queue keeps of an object in its cell.</summary>
    public struct Entry
    {
        public int Slot, Generation;
        public int BandIndex, BandEpoch; // where the band holds a copy (valid while the band's epoch is unchanged)
        public float X, Y, Z; // x, y from the cell's corner; z as the position holds it
        public float Side; // +1 beyond 96 m at the last check, -1 within
        public byte Flags;
    }

    private struct Cell
    {
        public int Cx, Cy;
        public int Start, Capacity; // the cell's range of the arena
        public int Count;
        public float ZMin, ZMax;
        public bool Dirty; // holds dead entries
    }

    // A new cell's first range; ranges double as the cell fills.
    private const int InitialCellCapacity = 8;

    // Every cell's entries, each cell in its own range. A cell that outgrows its range moves to a range twice as large at the
    // end of the used part (its old range becomes a hole); when the end has no room, the ranges are packed into the spare
    // buffer (the holes dropped) and the buffers swapped; only when the packed ranges still leave no room do the buffers grow,
    // to twice what the cells then need. So the grid allocates only when the capacity its cells need in total reaches a new
    // high (and then with room to spare), not whenever one cell outgrows its largest size so far.
    private Entry[] _arena = new Entry[256];
    private Entry[] _spare = new Entry[256];
    private int _arenaUsed;
    private Cell[] _cells = new Cell[16];
    private int _cellCount;
    private long[] _keys = new long[64];
    private int[] _cellAt = new int[64]; // -1 empty
    private int[] _dirty = new int[16];
    private int _dirtyCount;

    /// <summary>Entries held, dead ones not yet swept included.</summary>
    public int Held { get; private set; }

    public GateGrid() => Array.Fill(_cellAt, -1);

    /// <summary>The entry at a place.</summary>
    public ref Entry At(int cell, int index) => ref _arena[_cells[cell].Start + index];

    /// <summary>An entry's global position (the cell's corner plus its offsets).</summary>
    public void Global(int cell, int index, out double x, out double y, out double z)
    {
        ref Cell c = ref _cells[cell];
        ref Entry e = ref _arena[c.Start + index];
        x = c.Cx * CellSize + e.X;
        y = c.Cy * CellSize + e.Y;
        z = e.Z;
    }

    /// <summary>Adds an entry for an object at global (x, y) and float z; returns its place.</summary>
    public void Add(int slot, int generation, byte flags, double x, double y, float z, bool far, out int cell, out int index)
    {
        int cx = (int)Math.Floor(x / CellSize), cy = (int)Math.Floor(y / CellSize);
        cell = FindOrAddCell(cx, cy);
        if (_cells[cell].Count == _cells[cell].Capacity)
        {
            GrowCell(cell);
        }

        ref Cell c = ref _cells[cell];
        index = c.Count++;
        Held++;
        _arena[c.Start + index] = new Entry
        {
            Slot = slot,
            Generation = generation,
            BandEpoch = int.MinValue,
            X = (float)(x - cx * CellSize),
            Y = (float)(y - cy * CellSize),
            Z = z,
            Side = far ? 1f : -1f,
            Flags = flags,
        };
        c.ZMin = Math.Min(c.ZMin, z);
        c.ZMax = Math.Max(c.ZMax, z);
    }

    /// <summary>Removes the entry at a place: marks it dead (never selected) until the next <see cref="Sweep"/>.</summary>
    public void Remove(int cell, int index)
    {
        ref Cell c = ref _cells[cell];
        _arena[c.Start + index].Slot = -1;
        if (!c.Dirty)
        {
            c.Dirty = true;
            if (_dirtyCount == _dirty.Length)
            {
                Array.Resize(ref _dirty, _dirtyCount * 2);
            }

            _dirty[_dirtyCount++] = cell;
        }
    }

    /// <summary>Closes the gaps dead entries left, keeping the order of the live ones, and tells the queue where each moved entry
    /// now is (<see cref="GateQueue.EntryMoved"/>).</summary>
    public void Sweep(GateQueue queue)
    {
        for (int d = 0; d < _dirtyCount; d++)
        {
            int cell = _dirty[d];
            ref Cell c = ref _cells[cell];
            int w = 0;
            for (int i = 0; i < c.Count; i++)
            {
                if (_arena[c.Start + i].Slot < 0)
                {
                    continue;
                }

                if (w != i)
                {
                    _arena[c.Start + w] = _arena[c.Start + i];
                    queue.EntryMoved(_arena[c.Start + w].Slot, w);
                }

                w++;
            }

            Held -= c.Count - w;
            c.Count = w;
            c.Dirty = false;
        }

        _dirtyCount = 0;
    }

    /// <summary>
    /// Selects the entries of every cell that may hold an entry within <paramref name="crossWidth"/> of 96 m about
    /// (<paramref name="qx"/>, <paramref name="qy"/>, <paramref name="qz"/>) — infinite: every cell — or within
    /// <paramref name="bandWidth"/> of 96 m about the player (px, py, pz), and measures each from the player (double): those with
    /// <c>side·(d² − 96²) &lt; tolerance</c> go to <paramref name="hits"/>, those within <paramref name="bandWidth"/> and
    /// <paramref name="ringWidth"/> of 96 m to <paramref name="band"/> and <paramref name="ring"/> (places packed by
    /// <see cref="Pack"/>, lists from index 0, grown as needed). Returns the number of hits; <paramref name="tested"/> is the
    /// number of entries measured.
    /// </summary>
    public int Select(double px, double py, double pz, double qx, double qy, double qz, double crossWidth, double bandWidth,
        double ringWidth, double tolerance, ref long[] hits, ref long[] band, out int bandCount, ref long[] ring, out int ringCount,
        out long tested)
    {
        const double gate = PhysicsGlobals.PlayerActivityDistance;
        int n = 0, b = 0, r = 0;
        tested = 0;
        double bandLo = Sq(Math.Max(0.0, gate - bandWidth)), bandHi = Sq(gate + bandWidth);
        double ringLo = Sq(Math.Max(0.0, gate - ringWidth)), ringHi = Sq(gate + ringWidth);
        for (int ci = 0; ci < _cellCount; ci++)
        {
            ref Cell c = ref _cells[ci];
            if (c.Count == 0
                || (!MayHold(c, px, py, pz, bandWidth) && !(double.IsPositiveInfinity(crossWidth) || MayHold(c, qx, qy, qz, crossWidth))))
            {
                continue;
            }

            double ox = c.Cx * CellSize - px, oy = c.Cy * CellSize - py;
            tested += c.Count;
            for (int i = 0; i < c.Count; i++)
            {
                ref Entry e = ref _arena[c.Start + i];
                if (e.Slot < 0)
                {
                    continue; // dead
                }

                double dx = ox + e.X, dy = oy + e.Y, dz = e.Z - pz;
                double d2 = dx * dx + dy * dy + dz * dz;
                if (e.Side * (d2 - gate * gate) < tolerance)
                {
                    Push(ref hits, ref n, Pack(ci, i));
                }

                if (d2 > bandLo && d2 < bandHi)
                {
                    Push(ref band, ref b, Pack(ci, i));
                    if (d2 > ringLo && d2 < ringHi)
                    {
                        Push(ref ring, ref r, Pack(ci, i));
                    }
                }
            }
        }

        bandCount = b;
        ringCount = r;
        return n;
    }

    /// <summary>A place (cell and index) packed in one number.</summary>
    public static long Pack(int cell, int index) => ((long)cell << 32) | (uint)index;

    /// <summary>The cell of a packed place.</summary>
    public static int CellOf(long place) => (int)(place >> 32);

    /// <summary>The index of a packed place.</summary>
    public static int IndexOf(long place) => (int)place;

    private static double Sq(double v) => v * v;

    private static void Push(ref long[] list, ref int n, long value)
    {
        if (n == list.Length)
        {
            Array.Resize(ref list, n * 2);
        }

        list[n++] = value;
    }

    /// <summary>True when the cell (its square and its z range) may hold a point whose distance from (qx, qy, qz) is within
    /// <paramref name="width"/> of 96 m: its nearest point is nearer than 96 + width and its farthest farther than 96 − width.</summary>
    private static bool MayHold(in Cell c, double qx, double qy, double qz, double width)
    {
        const double gate = PhysicsGlobals.PlayerActivityDistance;
        double x0 = c.Cx * CellSize - qx, y0 = c.Cy * CellSize - qy, z0 = c.ZMin - qz;
        double x1 = x0 + CellSize, y1 = y0 + CellSize, z1 = c.ZMax - qz;
        double nx = Nearest(x0, x1), ny = Nearest(y0, y1), nz = Nearest(z0, z1);
        double fx = Math.Max(-x0, x1), fy = Math.Max(-y0, y1), fz = Math.Max(-z0, z1);
        double near2 = nx * nx + ny * ny + nz * nz, far2 = fx * fx + fy * fy + fz * fz;
        double hi = gate + width, lo = gate - width;
        return near2 < hi * hi && (lo <= 0.0 || far2 > lo * lo);
    }

    // The smallest |t| over [a, b].
    private static double Nearest(double a, double b) => a > 0.0 ? a : b < 0.0 ? -b : 0.0;

    private int FindOrAddCell(int cx, int cy)
    {
        long key = ((long)cx << 32) | (uint)cy;
        int mask = _keys.Length - 1;
        int h = Hash(key) & mask;
        while (_cellAt[h] >= 0)
        {
            if (_keys[h] == key)
            {
                return _cellAt[h];
            }

            h = (h + 1) & mask;
        }

        if (_cellCount == _cells.Length)
        {
            Array.Resize(ref _cells, _cells.Length * 2);
        }

        int cell = _cellCount++;
        _cells[cell] = new Cell { Cx = cx, Cy = cy, Start = 0, Capacity = 0, ZMin = float.PositiveInfinity, ZMax = float.NegativeInfinity };
        _keys[h] = key;
        _cellAt[h] = cell;
        if (_cellCount * 2 > _keys.Length)
        {
            Rehash();
        }

        return cell;
    }

    private void Rehash()
    {
        int size = _keys.Length * 2;
        _keys = new long[size];
        _cellAt = new int[size];
        Array.Fill(_cellAt, -1);
        for (int cell = 0; cell < _cellCount; cell++)
        {
            long key = ((long)_cells[cell].Cx << 32) | (uint)_cells[cell].Cy;
            int h = Hash(key) & (size - 1);
            while (_cellAt[h] >= 0)
            {
                h = (h + 1) & (size - 1);
            }

            _keys[h] = key;
            _cellAt[h] = cell;
        }
    }

    private static int Hash(long key)
    {
        ulong k = (ulong)key * 0x9E3779B97F4A7C15UL;
        return (int)(k >> 33);
    }

    // Gives cell a range twice its capacity (InitialCellCapacity for a new cell), its entries copied to the same indexes.
    private void GrowCell(int cell)
    {
        ref Cell c = ref _cells[cell];
        int capacity = c.Capacity == 0 ? InitialCellCapacity : c.Capacity * 2;
        if (c.Start + c.Capacity == _arenaUsed && c.Capacity != 0 && c.Start + capacity <= _arena.Length)
        {
            // The last range: it grows in place.
            _arenaUsed = c.Start + capacity;
            c.Capacity = capacity;
            return;
        }

        if (_arenaUsed + capacity > _arena.Length)
        {
            PackRanges(cell, capacity);
            return;
        }

        Array.Copy(_arena, c.Start, _arena, _arenaUsed, c.Count);
        c.Start = _arenaUsed;
        c.Capacity = capacity;
        _arenaUsed += capacity;
    }

    // Packs every range into the spare buffer (cell `growing` with range `capacity`), growing both buffers first when the
    // packed ranges would not fit, then swaps the buffers.
    private void PackRanges(int growing, int capacity)
    {
        int needed = capacity - _cells[growing].Capacity;
        for (int i = 0; i < _cellCount; i++)
        {
            needed += _cells[i].Capacity;
        }

        if (needed > _spare.Length)
        {
            int size = Math.Max(_arena.Length * 2, (int)System.Numerics.BitOperations.RoundUpToPowerOf2((uint)needed * 2));
            _spare = new Entry[size];
            Entry[] grown = new Entry[size];
            Array.Copy(_arena, grown, _arenaUsed);
            _arena = grown;
        }

        int at = 0;
        for (int i = 0; i < _cellCount; i++)
        {
            ref Cell c = ref _cells[i];
            int cap = i == growing ? capacity : c.Capacity;
            Array.Copy(_arena, c.Start, _spare, at, c.Count);
            c.Start = at;
            c.Capacity = cap;
            at += cap;
        }

        (_arena, _spare) = (_spare, _arena);
        _arenaUsed = at;
    }
}
