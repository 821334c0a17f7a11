using System;
using AcDream.Core.Physics.Spatial;

namespace AcDream.Core.Physics.Objects;

/// <summary>
/// Objects attached to a parent, each at a frame relative to one of the parent's parts (retail <c>CHILDLIST</c>,
/// PORTAL/cphysobj/CChildList.c). Parallel arrays, grown by doubling.
/// </summary>
public sealed class ChildList
{
    private PhysicsObj[] _objects = new PhysicsObj[4];
    private uint[] _partNumbers = new uint[4];
    private Frame[] _frames = new Frame[4];

    /// <summary>Number of children.</summary>
    public int Count { get; private set; }

    /// <summary>Child <paramref name="index"/>.</summary>
    /// <exception cref="ArgumentOutOfRangeException">Index out of range.</exception>
    public PhysicsObj GetObject(int index)
    {
        CheckIndex(index);
        return _objects[index];
    }

    /// <summary>Part of the parent that child <paramref name="index"/> hangs from.</summary>
    /// <exception cref="ArgumentOutOfRangeException">Index out of range.</exception>
    public uint GetPartNumber(int index)
    {
        CheckIndex(index);
        return _partNumbers[index];
    }

    /// <summary>Frame of child <paramref name="index"/> relative to its part.</summary>
    /// <exception cref="ArgumentOutOfRangeException">Index out of range.</exception>
    public ref readonly Frame GetFrame(int index)
    {
        CheckIndex(index);
        return ref _frames[index];
    }

    /// <summary>Index of <paramref name="obj"/>, or -1.</summary>
    public int IndexOf(PhysicsObj obj)
    {
        for (int i = 0; i < Count; i++)
        {
            if (_objects[i] == obj)
            {
                return i;
            }
        }

        return -1;
    }

    internal void Add(PhysicsObj obj, uint partNumber, in Frame frame)
    {
        if (Count == _objects.Length)
        {
            int n = Count * 2;
            Array.Resize(ref _objects, n);
            Array.Resize(ref _partNumbers, n);
            Array.Resize(ref _frames, n);
        }

        _objects[Count] = obj;
        _partNumbers[Count] = partNumber;
        _frames[Count] = frame;
        Count++;
    }

    internal void Remove(PhysicsObj obj)
    {
        int i = IndexOf(obj);
        if (i < 0)
        {
            return;
        }

        Count--;
        for (int k = i; k < Count; k++)
        {
            _objects[k] = _objects[k + 1];
            _partNumbers[k] = _partNumbers[k + 1];
            _frames[k] = _frames[k + 1];
        }

        _objects[Count] = null!;
    }

    private void CheckIndex(int index)
    {
        if ((uint)index >= (uint)Count)
        {
            throw new ArgumentOutOfRangeException(nameof(index));
        }
    }
}
