using System;
using AcDream.Core.Physics.Objects;

namespace AcDream.Core.Physics.Scene;

/// <summary>
/// A set of objects kept in the visiting order (ascending id, then creation order: <see cref="KeyOf"/>): the world's object
/// table and the scene's visiting list. Not retail.
/// </summary>
/// <remarks>
/// <para>Retail keeps its objects in a hash table and walks it each tick; the library visits them in ascending id order, which
/// the golden hashes pin. A flat sorted array makes an insertion or removal O(n) (100,000 objects streamed in descending id
/// order cost seconds). Here the objects are held in blocks of at most <see cref="MaxBlock"/> entries, each block a sorted
/// array of references with their ids beside them, and the blocks in order in one array: an insertion or removal finds its
/// block by binary search (O(log n), reading ids, and objects only to order equal ids), shifts at most <see cref="MaxBlock"/> entries, and splits or merges a
/// block now and then (O(n / MaxBlock) block moves once per ~<see cref="MinBlock"/> changes), whatever the order of ids. A walk
/// in order reads contiguous references, as the flat array did.</para>
/// <para>Blocks keep their capacity and are reused from a free list, so once the list has been as large as it gets, no change
/// allocates (wakes during a tick insert into the visiting list).</para>
/// <para>Walks that may change the list while they run (a tick's callbacks may remove or create objects, a wake inserts an
/// object later in the order) use a <see cref="Cursor"/>: after a change it finds its place again from the key of the last
/// object it returned, so every object in the list when the walk reaches its place is returned once, in order.</para>
/// </remarks>
internal sealed class VisitOrderList
{
    /// <summary>Largest number of entries in a block (a full block splits in two).</summary>
    internal const int MaxBlock = 256;

    /// <summary>Smallest number of entries in a block when there are several (a smaller block merges with a neighbour).</summary>
    internal const int MinBlock = MaxBlock / 4;

    private Block[] _blocks = new Block[4];
    private int _blockCount;
    private Block[] _free = new Block[4];
    private int _freeCount;
    private int _count;
    private int _version;

    // Cached position of the last rank lookup (sequential GetObject(i) is O(1)).
    private int _rankVersion = -1;
    private int _rankBlock;
    private int _rankStart;

    /// <summary>Number of objects in the list.</summary>
    internal int Count => _count;

    /// <summary>The sort key of <paramref name="obj"/>: its id, then its creation number in its world.</summary>
    internal static UInt128 KeyOf(PhysicsObj obj) => new(obj.Id, obj.CreationNumber);

    /// <summary>True when <paramref name="a"/> comes before <paramref name="b"/> in the visiting order.</summary>
    internal static bool Precedes(PhysicsObj a, PhysicsObj b) => KeyOf(a) < KeyOf(b);

    /// <summary>Inserts <paramref name="obj"/> at its place in the order (it must not be in the list).</summary>
    internal void Insert(PhysicsObj obj)
    {
        UInt128 key = KeyOf(obj);
        if (_blockCount == 0)
        {
            InsertBlock(0, RentBlock());
        }

        int b = FindBlock(key);
        Block block = _blocks[b];
        int at = LowerBound(block, key);
        if (block.Count == MaxBlock)
        {
            if (at == MaxBlock && b == _blockCount - 1)
            {
                // Appending past the last block (ids streamed in ascending order): a new block, so blocks stay full.
                block = RentBlock();
                InsertBlock(b + 1, block);
                at = 0;
            }
            else if (at == 0 && b == 0)
            {
                // Prepending (ids streamed in descending order): likewise.
                block = RentBlock();
                InsertBlock(0, block);
            }
            else
            {
                Split(b);
                if (at > block.Count)
                {
                    at -= block.Count;
                    block = _blocks[b + 1];
                }
            }
        }

        int tail = block.Count - at;
        Array.Copy(block.Items, at, block.Items, at + 1, tail);
        Array.Copy(block.Ids, at, block.Ids, at + 1, tail);
        block.Items[at] = obj;
        block.Ids[at] = obj.Id;
        block.Count++;
        _count++;
        _version++;
    }

    /// <summary>Removes <paramref name="obj"/>; false when it is not in the list.</summary>
    internal bool Remove(PhysicsObj obj)
    {
        if (_blockCount == 0)
        {
            return false;
        }

        UInt128 key = KeyOf(obj);
        int b = FindBlock(key);
        Block block = _blocks[b];
        int at = LowerBound(block, key);
        if (at >= block.Count || !ReferenceEquals(block.Items[at], obj))
        {
            return false;
        }

        int tail = block.Count - at - 1;
        Array.Copy(block.Items, at + 1, block.Items, at, tail);
        Array.Copy(block.Ids, at + 1, block.Ids, at, tail);
        block.Count--;
        block.Items[block.Count] = null!;
        _count--;
        _version++;
        FixUnderflow(b);
        return true;
    }

    /// <summary>Removes every object for which <paramref name="filter"/> says so, in one pass in order (the filter must not
    /// change this list).</summary>
    internal void RemoveWhere<TFilter>(ref TFilter filter)
        where TFilter : struct, IRemovalFilter
    {
        int removed = 0;
        for (int b = 0; b < _blockCount; b++)
        {
            Block block = _blocks[b];
            int w = 0;
            for (int i = 0; i < block.Count; i++)
            {
                PhysicsObj o = block.Items[i];
                if (filter.ShouldRemove(o))
                {
                    continue;
                }

                block.Items[w] = o;
                block.Ids[w] = block.Ids[i];
                w++;
            }

            Array.Clear(block.Items, w, block.Count - w);
            removed += block.Count - w;
            block.Count = w;
        }

        if (removed == 0)
        {
            return;
        }

        _count -= removed;
        _version++;
        for (int b = _blockCount - 1; b >= 0; b--)
        {
            if (b < _blockCount)
            {
                FixUnderflow(b);
            }
        }
    }

    /// <summary>The object of rank <paramref name="rank"/> (0 &lt;= rank &lt; <see cref="Count"/>, unchecked). Consecutive ranks
    /// cost O(1); a jump costs O(blocks).</summary>
    internal PhysicsObj At(int rank)
    {
        int b, start;
        if (_rankVersion == _version)
        {
            b = _rankBlock;
            start = _rankStart;
        }
        else
        {
            b = 0;
            start = 0;
        }

        while (rank < start)
        {
            b--;
            start -= _blocks[b].Count;
        }

        while (rank >= start + _blocks[b].Count)
        {
            start += _blocks[b].Count;
            b++;
        }

        _rankVersion = _version;
        _rankBlock = b;
        _rankStart = start;
        return _blocks[b].Items[rank - start];
    }

    /// <summary>A walk from the start of the list.</summary>
    internal Cursor Start() => new(_version);

    /// <summary>The next object of the walk <paramref name="c"/>: the first object after the last one it returned (first in the
    /// list at the start), found again by key if the list changed since. False at the end.</summary>
    internal bool MoveNext(ref Cursor c, out PhysicsObj obj)
    {
        if (c.Version != _version)
        {
            c.Version = _version;
            if (c.Started)
            {
                c.Block = FindBlockAfter(c.LastKey, out c.Index);
            }
        }

        while (c.Block < _blockCount && c.Index >= _blocks[c.Block].Count)
        {
            c.Block++;
            c.Index = 0;
        }

        if (c.Block >= _blockCount)
        {
            obj = null!;
            return false;
        }

        Block block = _blocks[c.Block];
        obj = block.Items[c.Index];
        c.LastKey = KeyOf(obj);
        c.Started = true;
        c.Index++;
        return true;
    }

    /// <summary>The object <paramref name="k"/> places after the one the walk <paramref name="c"/> last returned, when it is in
    /// the same block and the list has not changed since; otherwise null.</summary>
    internal PhysicsObj? Ahead(in Cursor c, int k)
    {
        if (c.Version != _version || c.Block >= _blockCount)
        {
            return null;
        }

        Block b = _blocks[c.Block];
        int i = c.Index - 1 + k;
        return (uint)i < (uint)b.Count ? b.Items[i] : null;
    }

    /// <summary>Where a walk stands in a <see cref="VisitOrderList"/>.</summary>
    internal struct Cursor
    {
        internal int Block, Index, Version;
        internal bool Started;
        internal UInt128 LastKey;

        internal Cursor(int version)
        {
            Version = version;
        }
    }

    /// <summary>Decides which objects <see cref="RemoveWhere"/> removes.</summary>
    internal interface IRemovalFilter
    {
        /// <summary>True to remove <paramref name="obj"/>.</summary>
        bool ShouldRemove(PhysicsObj obj);
    }

    private sealed class Block
    {
        internal readonly PhysicsObj[] Items = new PhysicsObj[MaxBlock];
        internal readonly uint[] Ids = new uint[MaxBlock];
        internal int Count;

        // The key of entry i (its id from the block, its creation number from the object only when needed).
        internal bool KeyLess(int i, UInt128 key)
        {
            uint id = (uint)(key >> 64);
            return Ids[i] != id ? Ids[i] < id : Items[i].CreationNumber < (ulong)key;
        }

        internal bool KeyEquals(int i, UInt128 key) => Ids[i] == (uint)(key >> 64) && Items[i].CreationNumber == (ulong)key;
    }

    // The block that holds key, or would: the first whose last key is >= key (the last block when none).
    private int FindBlock(UInt128 key)
    {
        int lo = 0, hi = _blockCount - 1;
        while (lo < hi)
        {
            int mid = (lo + hi) >> 1;
            Block m = _blocks[mid];
            if (m.KeyLess(m.Count - 1, key))
            {
                lo = mid + 1;
            }
            else
            {
                hi = mid;
            }
        }

        return lo;
    }

    // The position of the first entry whose key is > key (block, index; block == _blockCount at the end).
    private int FindBlockAfter(UInt128 key, out int index)
    {
        if (_blockCount == 0)
        {
            index = 0;
            return 0;
        }

        int b = FindBlock(key);
        Block block = _blocks[b];
        int at = LowerBound(block, key);
        if (at < block.Count && block.KeyEquals(at, key))
        {
            at++;
        }

        index = at;
        return b;
    }

    private static int LowerBound(Block block, UInt128 key)
    {
        int lo = 0, hi = block.Count;
        while (lo < hi)
        {
            int mid = (lo + hi) >> 1;
            if (block.KeyLess(mid, key))
            {
                lo = mid + 1;
            }
            else
            {
                hi = mid;
            }
        }

        return lo;
    }

    // Splits full block b into two halves (b and b + 1).
    private void Split(int b)
    {
        Block left = _blocks[b];
        Block right = RentBlock();
        int half = left.Count / 2;
        int moved = left.Count - half;
        Array.Copy(left.Items, half, right.Items, 0, moved);
        Array.Copy(left.Ids, half, right.Ids, 0, moved);
        Array.Clear(left.Items, half, moved);
        right.Count = moved;
        left.Count = half;
        InsertBlock(b + 1, right);
    }

    // After removals from block b: drops it when empty, or merges it with (or balances it against) a neighbour when it holds
    // fewer than MinBlock entries and is not the only block.
    private void FixUnderflow(int b)
    {
        Block block = _blocks[b];
        if (block.Count == 0)
        {
            RemoveBlock(b);
            return;
        }

        if (block.Count >= MinBlock || _blockCount == 1)
        {
            return;
        }

        int left = b > 0 ? b - 1 : b;
        Block l = _blocks[left], r = _blocks[left + 1];
        int total = l.Count + r.Count;
        if (total <= MaxBlock)
        {
            Array.Copy(r.Items, 0, l.Items, l.Count, r.Count);
            Array.Copy(r.Ids, 0, l.Ids, l.Count, r.Count);
            l.Count = total;
            Array.Clear(r.Items, 0, r.Count);
            r.Count = 0;
            RemoveBlock(left + 1);
            return;
        }

        int target = total / 2;
        if (l.Count < target)
        {
            // Move the front of r to the end of l.
            int n = target - l.Count;
            Array.Copy(r.Items, 0, l.Items, l.Count, n);
            Array.Copy(r.Ids, 0, l.Ids, l.Count, n);
            Array.Copy(r.Items, n, r.Items, 0, r.Count - n);
            Array.Copy(r.Ids, n, r.Ids, 0, r.Count - n);
            Array.Clear(r.Items, r.Count - n, n);
            l.Count += n;
            r.Count -= n;
        }
        else
        {
            // Move the end of l to the front of r.
            int n = l.Count - target;
            Array.Copy(r.Items, 0, r.Items, n, r.Count);
            Array.Copy(r.Ids, 0, r.Ids, n, r.Count);
            Array.Copy(l.Items, target, r.Items, 0, n);
            Array.Copy(l.Ids, target, r.Ids, 0, n);
            Array.Clear(l.Items, target, n);
            l.Count = target;
            r.Count += n;
        }
    }

    private void InsertBlock(int at, Block block)
    {
        if (_blockCount == _blocks.Length)
        {
            Array.Resize(ref _blocks, _blocks.Length * 2);
        }

        Array.Copy(_blocks, at, _blocks, at + 1, _blockCount - at);
        _blocks[at] = block;
        _blockCount++;
    }

    private void RemoveBlock(int at)
    {
        Block block = _blocks[at];
        Array.Copy(_blocks, at + 1, _blocks, at, _blockCount - at - 1);
        _blockCount--;
        _blocks[_blockCount] = null!;
        if (_freeCount == _free.Length)
        {
            Array.Resize(ref _free, _free.Length * 2);
        }

        _free[_freeCount++] = block;
    }

    private Block RentBlock()
    {
        if (_freeCount == 0)
        {
            return new Block();
        }

        Block b = _free[--_freeCount];
        _free[_freeCount] = null!;
        return b;
    }
}
