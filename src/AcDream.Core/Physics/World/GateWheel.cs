using System;

namespace AcDream.Core.Physics;

/// <summary>
/// A timing wheel of <see cref="GateEntry"/> values keyed by a monotone clock (metres of player travel): entries come out once
/// the clock reaches their key. Two levels — <see cref="NearBuckets"/> buckets of <see cref="NearWidth"/> m, then
/// <see cref="FarBuckets"/> buckets of <see cref="NearBuckets"/> × <see cref="NearWidth"/> m — and an overflow bucket. Buckets are
/// lists of fixed-size chunks from one pool, so draining reads memory in order; every push, pop and cascade is O(1). An entry
/// comes out once the clock reaches its key (never late). Stale entries (see <see cref="GateQueue"/>) are dropped when the
/// far level cascades and when the wheel is compacted; popped ones are checked by the caller.
/// </summary>
internal sealed class GateWheel
{
    /// <summary>Width of a near bucket, metres.</summary>
    public const double NearWidth = 1.0 / 32.0;

    /// <summary>Number of near buckets (the near level spans 16 m).</summary>
    public const int NearBuckets = 512;

    /// <summary>Number of far buckets (the far level spans 8 km).</summary>
    public const int FarBuckets = 512;

    private const double NearScale = 32.0; // 1 / NearWidth, exact
    private const int Overflow = NearBuckets + FarBuckets;
    private const int BucketCount = Overflow + 1;
    private const int ChunkSize = 16;

    private readonly GateQueue _owner;

    // Chunk pool: chunk c holds entries [c * ChunkSize, c * ChunkSize + _chunkCount[c]) and links to _chunkNext[c].
    private GateEntry[] _pool = new GateEntry[16 * ChunkSize];
    private int[] _chunkNext = new int[16];
    private int[] _chunkCount = new int[16];
    private int _freeChunk = -1;
    private int _chunksUsed;

    private readonly int[] _head = new int[BucketCount];
    private readonly int[] _tail = new int[BucketCount];
    private long _near; // index (clock / NearWidth) of the current near bucket; every lower index has been drained
    private long _farNext = 1; // index (clock / far width) of the next far bucket to cascade into the near level
    private int _nearEntries; // entries in near buckets, stale ones included
    private double _lastClock = double.NegativeInfinity;

    public GateWheel(GateQueue owner)
    {
        _owner = owner;
        Array.Fill(_head, -1);
        Array.Fill(_tail, -1);
    }

    /// <summary>Entries held, stale ones included.</summary>
    public int Count { get; private set; }

    /// <summary>Adds an entry due when the clock reaches <paramref name="key"/> (stored as its <see cref="GateEntry.Key"/>).</summary>
    /// <remarks>The key comes apart from the entry so that no caller writes one field of an entry just before it is copied whole
    /// (a store-forwarding stall).</remarks>
    public void Push(in GateEntry e, double key)
    {
        Append(BucketFor(key), e, key);
        Count++;
    }

    /// <summary>Moves the live entries due at <paramref name="clock"/> (never less than at the previous call) into
    /// <paramref name="due"/> from index <paramref name="n"/>, growing it as needed; returns the new count.</summary>
    public int PopDue(double clock, ref GateEntry[] due, int n)
    {
        if (clock == _lastClock)
        {
            return n; // nothing can have come due (a still player costs nothing)
        }

        _lastClock = clock;
        long target = Index(clock);
        while (_near < target)
        {
            // Drain the near buckets up to the target or the end of the near level's range, then move to the next range.
            long rangeEnd = _farNext * NearBuckets;
            long stop = Math.Min(target, rangeEnd);
            if (_nearEntries == 0)
            {
                _near = stop;
            }

            for (; _near < stop; _near++)
            {
                int bucket = NearSlot(_near);
                if (_head[bucket] >= 0)
                {
                    n = Drain(bucket, double.PositiveInfinity, ref due, n);
                }
            }

            if (_near == rangeEnd)
            {
                CascadeFar();
            }
        }

        // The current bucket: only the entries already due.
        return Drain(NearSlot(_near), clock, ref due, n);
    }

    /// <summary>Drops every stale entry.</summary>
    public void Compact()
    {
        for (int b = 0; b < BucketCount; b++)
        {
            if (_head[b] < 0)
            {
                continue;
            }

            int c = Detach(b);
            while (c >= 0)
            {
                int start = c * ChunkSize, end = start + _chunkCount[c];
                for (int k = start; k < end; k++)
                {
                    if (_owner.IsLive(_pool[k]))
                    {
                        Append(b, _pool[k], _pool[k].Key);
                    }
                    else
                    {
                        Count--;
                        _owner.StaleDropped();
                    }
                }

                int next = _chunkNext[c];
                FreeChunk(c);
                c = next;
            }
        }
    }

    // The near-bucket index of a clock reading: floor, which truncation is for the non-negative readings the gate uses. The
    // platform's native conversion: .NET's saturating (long) cast costs a helper call here, and readings stay far inside the
    // range where the two agree.
    private static long Index(double reading) => double.ConvertToIntegerNative<long>(Math.Max(0.0, reading * NearScale));

    private static int NearSlot(long index) => (int)(index & (NearBuckets - 1));

    private static int FarSlot(long index) => NearBuckets + (int)(index & (FarBuckets - 1));

    private int BucketFor(double key)
    {
        long i = Index(key);
        if (i < _near)
        {
            i = _near;
        }

        if (i < _farNext * NearBuckets)
        {
            return NearSlot(i);
        }

        long f = i / NearBuckets;
        return f < _farNext + FarBuckets ? FarSlot(f) : Overflow;
    }

    private void Append(int bucket, in GateEntry e, double key)
    {
        int t = _tail[bucket];
        if (t < 0 || _chunkCount[t] == ChunkSize)
        {
            int c = NewChunk();
            if (t < 0)
            {
                _head[bucket] = c;
            }
            else
            {
                _chunkNext[t] = c;
            }

            _tail[bucket] = c;
            t = c;
        }

        ref GateEntry slot = ref _pool[t * ChunkSize + _chunkCount[t]++];
        slot = e;
        slot.Key = key;
        if (bucket < NearBuckets)
        {
            _nearEntries++;
        }
    }

    private int NewChunk()
    {
        int c = _freeChunk;
        if (c >= 0)
        {
            _freeChunk = _chunkNext[c];
        }
        else
        {
            if (_chunksUsed == _chunkNext.Length)
            {
                int size = _chunkNext.Length * 2;
                Array.Resize(ref _chunkNext, size);
                Array.Resize(ref _chunkCount, size);
                Array.Resize(ref _pool, size * ChunkSize);
            }

            c = _chunksUsed++;
        }

        _chunkNext[c] = -1;
        _chunkCount[c] = 0;
        return c;
    }

    /// <summary>Detaches a bucket's chunk list (the caller walks it and frees the chunks).</summary>
    private int Detach(int bucket)
    {
        int c = _head[bucket];
        if (bucket < NearBuckets)
        {
            for (int k = c; k >= 0; k = _chunkNext[k])
            {
                _nearEntries -= _chunkCount[k];
            }
        }

        _head[bucket] = -1;
        _tail[bucket] = -1;
        return c;
    }

    private void FreeChunk(int c)
    {
        _chunkNext[c] = _freeChunk;
        _freeChunk = c;
    }

    /// <summary>Pops a bucket's entries due at <paramref name="clock"/>; the others stay. Liveness is not checked here (that
    /// would read a slot per entry): the caller checks it before acting on an entry's object.</summary>
    private int Drain(int bucket, double clock, ref GateEntry[] due, int n)
    {
        int c = Detach(bucket);
        while (c >= 0)
        {
            int start = c * ChunkSize, end = start + _chunkCount[c];
            for (int k = start; k < end; k++)
            {
                if (_pool[k].Key <= clock)
                {
                    Count--;
                    if (n == due.Length)
                    {
                        Array.Resize(ref due, n * 2);
                    }

                    due[n++] = _pool[k];
                }
                else
                {
                    Append(bucket, _pool[k], _pool[k].Key); // into a fresh chunk: this one is still being read
                }
            }

            int next = _chunkNext[c];
            FreeChunk(c);
            c = next;
        }

        return n;
    }

    /// <summary>The near level has reached far bucket <see cref="_farNext"/>'s range: its entries move to the near level, and
    /// once a whole far revolution has passed, the overflow entries now within reach move to the far level.</summary>
    private void CascadeFar()
    {
        long f = _farNext++;
        Reinsert(FarSlot(f));
        if ((_farNext & (FarBuckets - 1)) == 0)
        {
            Reinsert(Overflow);
        }
    }

    private void Reinsert(int bucket)
    {
        int c = Detach(bucket);
        while (c >= 0)
        {
            int start = c * ChunkSize, end = start + _chunkCount[c];
            for (int k = start; k < end; k++)
            {
                if (!_owner.IsLive(_pool[k]))
                {
                    Count--;
                    _owner.StaleDropped();
                }
                else
                {
                    Append(BucketFor(_pool[k].Key), _pool[k], _pool[k].Key); // possibly this bucket again (overflow): a fresh chunk
                }
            }

            int next = _chunkNext[c];
            FreeChunk(c);
            c = next;
        }
    }
}
